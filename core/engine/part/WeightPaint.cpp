#include "part/WeightPaint.h"

#include <algorithm>
#include <cmath>
#include <stdexcept>

#include "base/Error.h"
#include "mesh/MeshAdjacency.h"
#include "mesh/VertexNormals.h"
#include "part/WeightLists.h"
#include "rig/BoneSegments.h"
#include "rig/VertexMirror.h"

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

// Sets `bone` to `target` at vertex `v`, the weight it gives up going to
// `takes` where no other unlocked bone weighs v (else the other unlocked
// bones take up the difference). True if the weights changed; a visit that
// cannot be done is counted in `result`.
bool setAt(Part& part, int v, BoneId bone, double target, const std::optional<BoneId>& takes,
           const LockedBones& locked, DabResult& result) {
    WeightList& weights = part.weights.perVertex[v];
    WeightList updated = weights;
    const bool done = takes ? setWeightHandingOn(updated, bone, target, *takes, locked)
                            : setWeightKeepingLocks(updated, bone, target, locked);
    if (!done) {
        // A receiver always takes what a lowered weight gives up: what fails
        // is raising it where locked bones hold the rest, or a part of one
        // bone.
        ++(part.skeleton.boneCount() < 2 ? result.skippedOnlyBone : result.skippedLocked);
        return false;
    }
    if (updated == weights)
        return false;
    result.changed.push_back(v);
    weights = std::move(updated);
    return true;
}

// A vertex on the mirror plane painted with a bone whose image is another
// bone is its own partner: both bones get the mean of their two weights, so
// left and right agree there, their sum and every other weight kept
// (Blender's compromise for a centre vertex under X-mirror).
void balanceOnPlane(WeightList& list, BoneId bone, BoneId image) {
    const double mean = 0.5 * (weightOfBone(list, bone) + weightOfBone(list, image));
    std::erase_if(list,
                  [&](const auto& entry) { return entry.first == bone || entry.first == image; });
    if (mean > kDroppedWeight) {
        list.emplace_back(bone, mean);
        list.emplace_back(image, mean);
        std::sort(list.begin(), list.end());
    }
}

}  // namespace

const PartSymmetry& WeightPainter::symmetry(const Part& part) {
    if (!symmetrySearched_) {
        symmetry_ = findPartSymmetry(part);
        symmetrySearched_ = true;
        if (symmetry_)
            partners_ = mirrorVertices(mesh_, symmetry_->plane, vertexMirrorTolerance(mesh_));
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
    if (dab.mirror)
        paintMirrored(part, dab, gather(dab), locked, result);
    else
        paintBone(part, dab, gather(dab), locked, result);
    std::sort(result.changed.begin(), result.changed.end());
    result.changed.erase(std::unique(result.changed.begin(), result.changed.end()),
                         result.changed.end());
    return result;
}

WeightPainter::Influence WeightPainter::gather(const WeightDab& dab) {
    const double r2 = dab.radius * dab.radius;
    const std::vector<Vec3>* normal = dab.towardsViewer ? &normals() : nullptr;
    Influence influence;
    for (int v = 0; v < mesh_.vertexCount(); ++v) {
        const double d2 = (mesh_.vertices[v] - dab.centre).squaredNorm();
        if (d2 >= r2)
            continue;
        if (normal && (*normal)[v].dot(*dab.towardsViewer) <= 0.0)
            continue;  // faces away: the far side of the limb
        influence.emplace_back(
            v, dab.strength * brushFalloff(dab.falloff, std::sqrt(d2) / dab.radius));
    }
    return influence;
}

std::vector<std::pair<int, double>> WeightPainter::targets(const Part& part, const WeightDab& dab,
                                                           const Influence& influence) {
    // Every target from the weights as the dab found them (Smooth reads the
    // neighbours), before any change: no vertex sees another's new value.
    const auto& weights = part.weights.perVertex;
    std::vector<std::pair<int, double>> targets;
    targets.reserve(influence.size());
    for (const auto& [v, f] : influence) {
        const double w = weightOfBone(weights[v], dab.bone);
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
                    mean += weightOfBone(weights[n], dab.bone);
                mean /= static_cast<double>(std::max<std::size_t>(around.size(), 1));
                target = w + f * (mean - w);
                break;
            }
        }
        if (target != w)
            targets.emplace_back(v, target);
    }
    return targets;
}

void WeightPainter::paintBone(Part& part, const WeightDab& dab, const Influence& influence,
                              const LockedBones& locked, DabResult& result) {
    const WeightReceiver receiver(part.skeleton, dab.bone, locked);
    for (const auto& [v, target] : targets(part, dab, influence))
        setAt(part, v, dab.bone, target, receiver.at(mesh_.vertices[v]), locked, result);
}

void WeightPainter::paintMirrored(Part& part, const WeightDab& dab, const Influence& influence,
                                  const LockedBones& locked, DabResult& result) {
    const PartSymmetry& mirror = symmetry(part);
    const BoneId bone = dab.bone;
    const BoneId image = mirror.imageOf(bone);
    // A locked image is left alone: the dab paints its own side only.
    const bool paintImage = !locked.contains(image);
    // Each pair of partners once, led by the one the brush reaches more
    // strongly (the lower index on a tie): the leader's change is the
    // pair's, so the two sides cannot drift apart where the brush's edge or
    // the front-faces test falls between them.
    auto strengthAt = [&](int v) {
        auto found = std::lower_bound(influence.begin(), influence.end(), std::make_pair(v, -1.0));
        return found != influence.end() && found->first == v ? found->second : 0.0;
    };
    Influence leaders;
    leaders.reserve(influence.size());
    for (const auto& [v, f] : influence) {
        const int p = partners_[v];
        if (p != kNoMirrorVertex && p != v) {
            const double fp = strengthAt(p);
            if (fp > f || (fp == f && p < v))
                continue;  // the partner leads
        }
        leaders.emplace_back(v, f);
    }
    const WeightReceiver receiver(part.skeleton, bone, locked);
    const WeightReceiver imageReceiver(part.skeleton, image, locked);
    for (const auto& [v, target] : targets(part, dab, leaders)) {
        const std::optional<BoneId> takes = receiver.at(mesh_.vertices[v]);
        if (!setAt(part, v, bone, target, takes, locked, result))
            continue;
        const int p = partners_[v];
        if (p == kNoMirrorVertex) {
            ++result.unpaired;  // nothing to mirror it to: one side only
            continue;
        }
        if (!paintImage)
            continue;
        if (p == v) {
            if (image != bone)
                balanceOnPlane(part.weights.perVertex[v], bone, image);
            continue;
        }
        // The partner gets the same weight of the image bone, the weight it
        // gives up handed to the image of the leader's receiver (the parent
        // bone's image is the image's parent).
        std::optional<BoneId> imageTakes;
        if (takes && mirror.imageOf(*takes) != image && !locked.contains(mirror.imageOf(*takes)))
            imageTakes = mirror.imageOf(*takes);
        else
            imageTakes = imageReceiver.at(mesh_.vertices[p]);
        setAt(part, p, image, target, imageTakes, locked, result);
    }
}

DabResult paintWeights(Part& part, const WeightDab& dab) {
    WeightPainter painter(part.mesh);
    return painter.paint(part, dab);
}

}  // namespace rigmesh
