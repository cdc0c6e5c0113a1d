#include "part/WeightPaint.h"

#include <algorithm>
#include <cmath>
#include <stdexcept>
#include <unordered_map>

#include "base/Error.h"
#include "mesh/MeshAdjacency.h"
#include "part/WeightLists.h"
#include "pose/VertexNormals.h"
#include "rig/BoneSegments.h"

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
}

// The bone that takes the weight `bone` gives up at a vertex no other
// unlocked bone weighs, as Blender's auto-normalise hands it on: the parent
// bone first, else the unlocked bone nearest the vertex. None when every
// other bone is locked (or there is none).
class WeightReceiver {
  public:
    WeightReceiver(const Skeleton& skeleton, BoneId bone, const LockedBones& locked) {
        const std::optional<BoneId> parent = skeleton.parentBone(bone);
        if (parent && !locked.contains(*parent)) {
            parent_ = parent;
            return;
        }
        for (const Bone& other : skeleton.bones())
            if (other.id != bone && !locked.contains(other.id))
                others_.emplace_back(other.id, segmentOf(skeleton, other.id));
    }
    std::optional<BoneId> at(const Vec3& vertex) const {
        if (parent_)
            return parent_;
        std::optional<BoneId> nearest;
        double best = 0.0;
        for (const auto& [id, segment] : others_) {
            const double d = pointSegmentDistance(vertex, segment);
            if (!nearest || d < best) {
                nearest = id;
                best = d;
            }
        }
        return nearest;
    }

  private:
    std::optional<BoneId> parent_;
    std::vector<std::pair<BoneId, BoneSegment>> others_;
};

}  // namespace

const PartSymmetry& WeightPainter::symmetry(const Part& part) {
    if (!symmetrySearched_) {
        symmetry_ = findPartSymmetry(part);
        symmetrySearched_ = true;
    }
    if (!symmetry_)
        throw Error(MessageId::PaintMirrorAsymmetric);
    return *symmetry_;
}

DabResult WeightPainter::paint(Part& part, const WeightDab& dab) {
    if (part.mesh.vertexCount() != mesh_.vertexCount())
        throw std::logic_error("The weight painter was made for another mesh.");
    checkDab(part, dab);
    const LockedBones locked(part.skeleton, dab.locked);
    DabResult result;
    if (!dab.mirror) {
        paintBone(part, dab, dab.bone, gather(dab, dab.centre, dab.towardsViewer, {}), locked,
                  result);
        return result;
    }
    // X-mirror: the reflection through the part's left-right plane paints
    // the bone's mirror image (the bone itself across the middle).
    const PartSymmetry& mirror = symmetry(part);
    const Vec3 centre = mirror.plane.reflect(dab.centre);
    std::optional<Vec3> view;
    if (dab.towardsViewer)
        view = mirror.plane.reflectDirection(*dab.towardsViewer);
    const BoneId image = mirror.imageOf(dab.bone);
    if (image == dab.bone) {
        paintBone(part, dab, dab.bone,
                  gather(dab, centre, view, gather(dab, dab.centre, dab.towardsViewer, {})), locked,
                  result);
    } else {
        paintBone(part, dab, dab.bone, gather(dab, dab.centre, dab.towardsViewer, {}), locked,
                  result);
        if (!locked.contains(image))
            paintBone(part, dab, image, gather(dab, centre, view, {}), locked, result);
    }
    std::sort(result.changed.begin(), result.changed.end());
    result.changed.erase(std::unique(result.changed.begin(), result.changed.end()),
                         result.changed.end());
    return result;
}

std::unordered_map<int, double> WeightPainter::gather(const WeightDab& dab, const Vec3& centre,
                                                      const std::optional<Vec3>& towardsViewer,
                                                      std::unordered_map<int, double> influence) {
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
    return influence;
}

void WeightPainter::paintBone(Part& part, const WeightDab& dab, BoneId bone,
                              const std::unordered_map<int, double>& influence,
                              const LockedBones& locked, DabResult& result) {
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

    const WeightReceiver receiver(part.skeleton, bone, locked);
    for (const auto& [v, target] : targets) {
        WeightList updated = weights[v];
        const std::optional<BoneId> takes = receiver.at(mesh_.vertices[v]);
        const bool done = takes ? setWeightHandingOn(updated, bone, target, *takes, locked)
                                : setWeightKeepingLocks(updated, bone, target, locked);
        if (!done) {
            // A receiver always takes what a lowered weight gives up: what
            // fails is raising it where locked bones hold the rest, or a
            // part of one bone.
            ++(part.skeleton.boneCount() < 2 ? result.skippedOnlyBone : result.skippedLocked);
            continue;
        }
        if (updated == weights[v])
            continue;
        result.changed.push_back(v);
        weights[v] = std::move(updated);
    }
}

DabResult paintWeights(Part& part, const WeightDab& dab) {
    WeightPainter painter(part.mesh);
    return painter.paint(part, dab);
}

}  // namespace rigmesh
