// Viewport: the weight inspection marks, see Viewport.h.
#include "viewport/ViewMath.h"
#include "viewport/Viewport.h"

namespace rigmesh::widgets {

namespace {

// Where the posed surface has vertex `v`: linear blend of the bone
// transforms, as the Linear Blend view would draw it (the marks only have
// to sit on the surface, within a point's size).
Vec3 posedVertex(const Part& part, const PosedSkeleton& posed, int v) {
    const Vec3& rest = part.mesh.vertices[v];
    if (v >= static_cast<int>(part.weights.perVertex.size()) || posed.boneTransforms.empty())
        return rest;
    Vec3 sum = Vec3::Zero();
    double total = 0.0;
    // Weights name bones by id; the transforms are by position.
    for (const auto& [bone, w] : part.weights.perVertex[v]) {
        const int index = part.skeleton.hasBone(bone) ? part.skeleton.indexOfBone(bone) : -1;
        if (index < 0 || index >= static_cast<int>(posed.boneTransforms.size()))
            continue;
        sum += w * posed.boneTransforms[index].apply(rest);
        total += w;
    }
    return total > 0.0 ? Vec3(sum / total) : rest;
}

}  // namespace

void Viewport::setInspectedVertex(std::optional<SurfaceHit> vertex) {
    const bool same =
        vertex.has_value() == inspected_.has_value() &&
        (!vertex || (vertex->part == inspected_->part && vertex->vertex == inspected_->vertex));
    inspected_ = vertex;
    update();
    if (!same)
        emit inspectedVertexChanged();
}

void Viewport::setMarkedVertices(model::PartId part, std::vector<int> vertices) {
    markedPart_ = part;
    marked_ = std::move(vertices);
    update();
}

void Viewport::addInspectionMarks(RenderScene& scene) const {
    auto mark = [&](model::PartId id, const std::vector<int>& vertices, const QVector3D& colour) {
        const model::PartNode* node = document_->findPart(id);
        if (!node || !node->part || !node->visible)
            return;
        const PosedSkeleton& posed = posedSkeleton(*node);
        for (int v : vertices)
            if (v >= 0 && v < node->part->mesh.vertexCount())
                scene.points.add(toQt(node->placement.toWorld(posedVertex(*node->part, posed, v))),
                                 colour);
    };
    mark(markedPart_, marked_, QVector3D(1.0f, 0.2f, 0.85f));  // Check Rig: magenta
    if (inspected_)
        mark(inspected_->part, {inspected_->vertex}, QVector3D(1.0f, 1.0f, 1.0f));
}

}  // namespace rigmesh::widgets
