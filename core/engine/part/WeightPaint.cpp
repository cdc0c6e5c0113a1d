#include "part/WeightPaint.h"

#include <algorithm>
#include <cmath>
#include <unordered_map>

#include "base/Error.h"
#include "mesh/MeshAdjacency.h"
#include "part/WeightLists.h"
#include "pose/VertexNormals.h"

namespace rigmesh {

double brushFalloff(BrushFalloff falloff, double d) {
    d = std::clamp(d, 0.0, 1.0);
    switch (falloff) {
        case BrushFalloff::Smooth:
            return (1.0 - d * d) * (1.0 - d * d);
        case BrushFalloff::Linear:
            return 1.0 - d;
        case BrushFalloff::Sharp:
            return (1.0 - d) * (1.0 - d);
        case BrushFalloff::Constant:
            return 1.0;
    }
    return 0.0;
}

WeightPainter::WeightPainter(const TriMesh& mesh) : mesh_(mesh) {}

const std::vector<std::vector<int>>& WeightPainter::neighbours() {
    if (neighbours_.empty() && mesh_.vertexCount() > 0)
        neighbours_ = vertexNeighbours(mesh_);
    return neighbours_;
}

const std::vector<Vec3>& WeightPainter::normals() {
    if (normals_.empty() && mesh_.vertexCount() > 0)
        normals_ = vertexNormals(mesh_);
    return normals_;
}

namespace {

void checkDab(const Part& part, const WeightDab& dab) {
    if (!part.skeleton.hasBone(dab.bone))
        throw Error(MessageId::PaintNoSuchBone, dab.bone);
    for (BoneId locked : dab.locked)
        if (!part.skeleton.hasBone(locked))
            throw Error(MessageId::PaintLockedNoSuchBone, locked);
    if (dab.locked.contains(dab.bone))
        throw Error(MessageId::PaintBoneLocked, dab.bone);
    if (!(dab.radius > 0.0) || !std::isfinite(dab.radius) || !(dab.strength >= 0.0) ||
        !(dab.strength <= 1.0) || !(dab.value >= 0.0) || !(dab.value <= 1.0) ||
        !dab.centre.allFinite())
        throw Error(MessageId::PaintBrushInvalid);
    if (dab.towardsViewer && (!dab.towardsViewer->allFinite() || dab.towardsViewer->norm() == 0.0))
        throw Error(MessageId::PaintViewDirectionInvalid);
    if (dab.mirror && part.mirror.size() != part.mesh.vertices.size())
        throw Error(MessageId::PaintMirrorAsymmetric);
}

}  // namespace

DabResult WeightPainter::paint(Part& part, const WeightDab& dab) {
    if (part.mesh.vertexCount() != mesh_.vertexCount())
        throw Error("The weight painter was made for another mesh.");
    checkDab(part, dab);
    const Skeleton& skeleton = part.skeleton;
    const BoneId bone = dab.bone;
    const LockedBones locked(skeleton, dab.locked);

    // The vertices under the brush (and under its reflection through the
    // sketch plane z = 0) with their strength.
    std::unordered_map<int, double> influence;
    auto gather = [&](const Vec3& centre, const std::optional<Vec3>& towardsViewer) {
        const double r2 = dab.radius * dab.radius;
        const std::vector<Vec3>* normal = towardsViewer ? &normals() : nullptr;
        for (int v = 0; v < mesh_.vertexCount(); ++v) {
            const double d2 = (mesh_.vertices[v] - centre).squaredNorm();
            if (d2 >= r2)
                continue;
            if (normal && (*normal)[v].dot(*towardsViewer) <= 0.0)
                continue;  // faces away: the far side of the limb
            const double f = dab.strength * brushFalloff(dab.falloff, std::sqrt(d2) / dab.radius);
            double& slot = influence[v];
            slot = std::max(slot, f);
        }
    };
    gather(dab.centre, dab.towardsViewer);
    if (dab.mirror) {
        std::optional<Vec3> mirroredView;
        if (dab.towardsViewer)
            mirroredView =
                Vec3(dab.towardsViewer->x(), dab.towardsViewer->y(), -dab.towardsViewer->z());
        gather(Vec3(dab.centre.x(), dab.centre.y(), -dab.centre.z()), mirroredView);
    }

    // Every target from the weights as the dab found them (Smooth reads the
    // neighbours), then every change: no vertex sees another's new value.
    auto& weights = part.weights.perVertex;
    std::vector<std::pair<int, double>> targets;
    targets.reserve(influence.size());
    for (const auto& [v, f] : influence) {
        const double w = weightOfBone(weights[v], bone);
        double target = w;
        switch (dab.mode) {
            case BrushMode::Add:
                target = w + f * (1.0 - w);
                break;
            case BrushMode::Subtract:
                target = w * (1.0 - f);
                break;
            case BrushMode::Replace:
                target = w + f * (dab.value - w);
                break;
            case BrushMode::Smooth: {
                const std::vector<int>& around = neighbours()[v];
                double mean = 0.0;
                for (int n : around)
                    mean += weightOfBone(weights[n], bone);
                mean /= static_cast<double>(std::max<std::size_t>(around.size(), 1));
                target = w + f * (mean - w);
                break;
            }
        }
        if (target != w)
            targets.emplace_back(v, target);
    }
    std::sort(targets.begin(), targets.end());

    DabResult result;
    for (const auto& [v, target] : targets) {
        WeightList updated = weights[v];
        if (!setWeightKeepingLocks(updated, bone, target, locked)) {
            ++result.skippedLocked;
            continue;
        }
        if (updated == weights[v])
            continue;
        result.changed.push_back(v);
        weights[v] = std::move(updated);
    }
    return result;
}

DabResult paintWeights(Part& part, const WeightDab& dab) {
    WeightPainter painter(part.mesh);
    return painter.paint(part, dab);
}

}  // namespace rigmesh
