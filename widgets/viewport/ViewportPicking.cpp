// Viewport: what lies under a pixel (the sketch and view planes, joints,
// bones, parts, the surface and its weights), see Viewport.h.
#include <algorithm>
#include <limits>

#include "viewport/ViewMath.h"
#include "viewport/Viewport.h"

namespace rigmesh::widgets {

namespace {

// Möller-Trumbore: distance along the ray to the triangle, or infinity.
double rayTriangle(const Vec3& origin, const Vec3& direction, const Vec3& a, const Vec3& b,
                   const Vec3& c) {
    const Vec3 e1 = b - a, e2 = c - a, p = direction.cross(e2);
    const double det = e1.dot(p);
    if (std::abs(det) < 1e-300)
        return std::numeric_limits<double>::infinity();
    const Vec3 s = origin - a;
    const double u = s.dot(p) / det;
    if (u < 0 || u > 1)
        return std::numeric_limits<double>::infinity();
    const Vec3 q = s.cross(e1);
    const double v = direction.dot(q) / det;
    if (v < 0 || u + v > 1)
        return std::numeric_limits<double>::infinity();
    const double t = e2.dot(q) / det;
    return t > 0 ? t : std::numeric_limits<double>::infinity();
}

}  // namespace

QVector3D Viewport::sketchPlanePoint(const QPointF& pixel) const {
    return camera_.pointOnViewPlane(pixel, QSizeF(size()), sceneCentre());
}

QVector3D Viewport::viewPlanePoint(const QPointF& pixel, const QVector3D& through) const {
    return camera_.pointOnViewPlane(pixel, QSizeF(size()), through);
}

model::Placement Viewport::sketchPlacement() const {
    // The part's x and y axes are the camera's right and up, its z faces the
    // viewer, its origin is the scene centre: the sketch appears where drawn.
    Eigen::Matrix3d basis;
    basis.col(0) = toEigen(camera_.right());
    basis.col(1) = toEigen(camera_.up());
    basis.col(2) = -toEigen(camera_.forward());
    model::Placement placement;
    placement.rotation = Eigen::Quaterniond(basis).normalized();
    placement.translation = toEigen(sceneCentre());
    return placement;
}

QVector3D Viewport::jointWorldPosition(model::PartId part, JointId joint) const {
    const model::PartNode& node = document_->part(part);
    const PosedSkeleton& posed = posedSkeleton(node);
    return toQt(
        node.placement.toWorld(posed.jointPositions[node.part->skeleton.indexOfJoint(joint)]));
}

std::optional<model::Selection> Viewport::jointAt(const QPointF& pixel) const {
    constexpr double kPickRadiusPixels = 8.0;
    std::optional<model::Selection> best;
    double bestDistance = kPickRadiusPixels;
    for (const model::PartNode& node : document_->parts()) {
        if (!node.visible || !node.part)
            continue;
        const PosedSkeleton& posed = posedSkeleton(node);
        for (const Joint& joint : node.part->skeleton.joints()) {
            const Vec3& position = posed.jointPositions[node.part->skeleton.indexOfJoint(joint.id)];
            QVector3D screen =
                camera_.project(toQt(node.placement.toWorld(position)), QSizeF(size()));
            double d = std::hypot(screen.x() - pixel.x(), screen.y() - pixel.y());
            if (d < bestDistance) {
                bestDistance = d;
                best = model::Selection{node.id, joint.id};
            }
        }
    }
    return best;
}

std::optional<BoneHit> Viewport::boneAt(const QPointF& pixel) const {
    constexpr double kPickRadiusPixels = 6.0;
    std::optional<BoneHit> best;
    double bestDistance = kPickRadiusPixels;
    const QSizeF screenSize(size());
    for (const model::PartNode& node : document_->parts()) {
        if (!node.visible || !node.part)
            continue;
        const Skeleton& skeleton = node.part->skeleton;
        const PosedSkeleton& posed = posedSkeleton(node);
        auto screenOf = [&](JointId joint) {
            const Vec3& p = posed.jointPositions[skeleton.indexOfJoint(joint)];
            const QVector3D s = camera_.project(toQt(node.placement.toWorld(p)), screenSize);
            return QPointF(s.x(), s.y());
        };
        for (const Bone& bone : skeleton.bones()) {
            const QPointF a = screenOf(bone.head), b = screenOf(bone.tail);
            const QPointF ab = b - a;
            const double length2 = QPointF::dotProduct(ab, ab);
            const double t =
                length2 > 0 ? std::clamp(QPointF::dotProduct(pixel - a, ab) / length2, 0.0, 1.0)
                            : 0.0;
            const QPointF nearest = a + t * ab;
            const double d = std::hypot(pixel.x() - nearest.x(), pixel.y() - nearest.y());
            if (d < bestDistance) {
                bestDistance = d;
                best = BoneHit{node.id, bone.head, bone.tail};
            }
        }
    }
    return best;
}

std::optional<model::PartId> Viewport::partAt(const QPointF& pixel) const {
    const std::optional<SurfaceHit> hit = surfaceAt(pixel);
    return hit ? std::optional<model::PartId>(hit->part) : std::nullopt;
}

std::optional<Viewport::SurfaceHit> Viewport::surfaceAt(const QPointF& pixel) const {
    const Ray ray = camera_.rayThrough(pixel, QSizeF(size()));
    std::optional<SurfaceHit> best;
    double nearest = std::numeric_limits<double>::infinity();
    for (const model::PartNode& node : document_->parts()) {
        if (!node.visible || !node.part)
            continue;
        // Into the part's own frame.
        const Vec3 origin = node.placement.toLocal(toEigen(ray.origin));
        const Vec3 direction = node.placement.directionToLocal(toEigen(ray.direction));
        const auto& v = node.part->mesh.vertices;
        for (const auto& f : node.part->mesh.faces) {
            double t = rayTriangle(origin, direction, v[f[0]], v[f[1]], v[f[2]]);
            if (t < nearest) {
                nearest = t;
                const Vec3 at = origin + t * direction;
                int corner = 0;
                for (int c = 1; c < 3; ++c)
                    if ((v[f[c]] - at).squaredNorm() < (v[f[corner]] - at).squaredNorm())
                        corner = c;
                best = SurfaceHit{node.id, f[corner]};
            }
        }
    }
    return best;
}

QString Viewport::weightsAt(const QPointF& pixel) const {
    const std::optional<SurfaceHit> hit = surfaceAt(pixel);
    if (!hit)
        return {};
    const model::PartNode& node = document_->part(hit->part);
    const Part& part = *node.part;
    if (hit->vertex >= static_cast<int>(part.weights.perVertex.size()))
        return tr("Vertex %1 of %2: no weights").arg(hit->vertex).arg(node.name);
    auto weights = part.weights.perVertex[hit->vertex];
    std::sort(weights.begin(), weights.end(),
              [](const auto& a, const auto& b) { return a.second > b.second; });
    QStringList listed;
    for (const auto& [id, w] : weights) {
        auto name = part.boneNames.find(id);
        const QString label = name != part.boneNames.end()
                                  ? QString::fromStdString(name->second)
                                  : tr("bone %1 (to %2)")
                                        .arg(id)
                                        .arg(model::jointDisplayName(part.skeleton.bone(id).tail));
        listed << QStringLiteral("%1 %2").arg(label).arg(w, 0, 'f', 3);
    }
    return tr("Vertex %1 of %2: %3")
        .arg(hit->vertex)
        .arg(node.name, listed.join(QStringLiteral(", ")));
}

}  // namespace rigmesh::widgets
