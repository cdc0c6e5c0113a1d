#include "cut/BoneEdits.h"

#include <algorithm>
#include <chrono>
#include <set>

#include "base/Error.h"
#include "base/Stopwatch.h"
#include "mesh/MeshAdjacency.h"
#include "part/BoneAnnotations.h"
#include "part/BoneWeights.h"
#include "rig/LocalBoneHeat.h"
#include "rig/ShortBones.h"

namespace rigmesh {

namespace {

using Clock = std::chrono::steady_clock;

// The closest split that still leaves both halves a bone of some length.
constexpr double kEndFraction = 0.05;

BoneEditResult finish(const Part& part, Skeleton skeleton, const WeightsById& weights,
                      const std::vector<int>& seeds, const std::vector<int>& unknown,
                      const std::vector<BoneId>& bones, Clock::time_point start) {
    skeleton.reorient();
    const LocalBoneHeatResult local =
        recomputeWeightsLocally(part.mesh, skeleton, weights, seeds, unknown, bones);
    BoneEditResult result;
    result.part = part;
    result.part.skeleton = std::move(skeleton);
    // A fresh value: failed bones and the warning were the old solve's.
    result.part.weights = SkinWeightsById{local.weights, {}, {}};
    // Closest bones known from the sketch no longer hold where bones changed.
    result.part.knownClosestBones.clear();
    result.part.boneNames.clear();
    result.part.lockedBones.clear();
    carryBoneAnnotations(part, result.part);
    // A kept frame holds while its bone points the same way (a split's first
    // half); a bone that turned (next to a deleted one) loses it.
    std::erase_if(result.part.boneFrames, [&](const auto& entry) {
        const Skeleton& before = part.skeleton;
        const Skeleton& after = result.part.skeleton;
        if (!after.hasBone(entry.first))
            return true;
        auto direction = [](const Skeleton& s, BoneId id) {
            return Vec3(s.joint(s.bone(id).tail).position - s.joint(s.bone(id).head).position)
                .normalized();
        };
        return direction(before, entry.first).dot(direction(after, entry.first)) < 1.0 - 1e-12;
    });
    result.reskinned = local.failedTest;
    result.reskinned.insert(result.reskinned.end(), local.transition.begin(),
                            local.transition.end());
    std::sort(result.reskinned.begin(), result.reskinned.end());
    result.bonesInvolved = static_cast<int>(local.bones.size());
    // A bone edit changes no face: an imported surface (Part::surfaceFromFile,
    // possibly open) stays as it came, and only what validate() asks holds.
    const std::vector<Message> problems =
        part.surfaceFromFile ? result.part.validate() : result.part.validateSolid();
    if (!problems.empty())
        throw Error(MessageId::BoneEditInvalidResult, problems.front());
    result.milliseconds = millisecondsSince(start);
    return result;
}

void requireRigged(const Part& part, BoneId bone) {
    if (part.skeleton.boneCount() == 0)
        throw Error(MessageId::PartHasNoSkeleton);
    if (!part.skeleton.hasBone(bone))
        throw Error(MessageId::PartHasNoBone, bone);
}

}  // namespace

BoneId nearestBone(const Part& part, const Vec3& point) {
    const std::vector<BoneSegment> segments = part.boneSegments();
    if (segments.empty())
        throw Error(MessageId::PartHasNoSkeleton);
    int best = 0;
    for (int b = 1; b < static_cast<int>(segments.size()); ++b)
        if (pointSegmentDistance(point, segments[b]) < pointSegmentDistance(point, segments[best]))
            best = b;
    return part.skeleton.bones()[best].id;
}

BoneEditResult splitBoneAt(const Part& part, BoneId bone, const Vec3& at) {
    const auto start = Clock::now();
    requireRigged(part, bone);
    const Bone& b = part.skeleton.bone(bone);
    const BoneSegment segment{part.skeleton.joint(b.head).position,
                              part.skeleton.joint(b.tail).position};
    const double t = closestSegmentParameter(at, segment);
    if (t < kEndFraction || t > 1.0 - kEndFraction)
        throw Error(MessageId::SplitTooCloseToJoint);
    // Both halves at least the shortest bone (rig/ShortBones.h), however
    // short the bone already is.
    const double length = (segment.tail - segment.head).norm();
    const double minimum = minimumBoneLength(part.mesh);
    const double shorterHalf = std::min(t, 1.0 - t) * length;
    if (shorterHalf < minimum)
        throw Error(MessageId::SplitBoneTooShort, shortNumber(shorterHalf), shortNumber(minimum));
    const Vec3 point = segment.head + t * (segment.tail - segment.head);
    Skeleton skeleton = part.skeleton;
    const JointId middle = skeleton.splitBone(bone, point);
    BoneId tailHalf = bone;
    for (BoneId id : skeleton.bonesAt(middle))
        if (id != bone)
            tailHalf = id;

    // Paper 3.3 cuts perpendicular to the bone through the new joint and
    // merges back; the merge's inclusion test (3.2.2) starts at the cut loop.
    // There both halves are equally close, so every vertex passes; the test
    // starts instead from every vertex the bone leads, and those beyond the
    // new joint (now closest to the far half, which has no weight) fail it.
    const WeightsById& weights = part.weights.perVertex;
    std::vector<int> seeds;
    for (int v = 0; v < part.mesh.vertexCount(); ++v)
        if (!weights[v].empty() && leadingBone(weights[v]) == bone)
            seeds.push_back(v);
    if (seeds.empty())
        throw Error(MessageId::SplitBoneLeadsNothing);
    BoneEditResult result =
        finish(part, std::move(skeleton), weights, seeds, {}, {bone, tailHalf}, start);
    result.newJoint = middle;
    return result;
}

BoneEditResult deleteBone(const Part& part, BoneId bone) {
    const auto start = Clock::now();
    requireRigged(part, bone);
    if (part.skeleton.boneCount() < 2)
        throw Error(MessageId::DeleteOnlyBone);

    const Bone b = part.skeleton.bone(bone);
    std::set<BoneId> neighbours;
    for (JointId end : {b.head, b.tail})
        for (BoneId id : part.skeleton.bonesAt(end))
            if (id != bone)
                neighbours.insert(id);
    Skeleton skeleton = part.skeleton;
    skeleton.collapseBone(
        bone, 0.5 * (part.skeleton.joint(b.head).position + part.skeleton.joint(b.tail).position));
    // The neighbours now reach the midpoint: none may end up shorter than
    // the shortest bone (rig/ShortBones.h).
    const double minimum = minimumBoneLength(part.mesh);
    for (BoneId id : neighbours)
        if (skeleton.hasBone(id) && skeleton.boneLength(id) < minimum)
            throw Error(MessageId::DeleteLeavesShortBone, id, shortNumber(skeleton.boneLength(id)),
                        shortNumber(minimum));

    // The collapsed piece (paper 3.3: between the cuts through the far joints
    // of the neighbouring bones): every vertex led by the bone or a
    // neighbour, all of them solved again.
    WeightsById weights = part.weights.perVertex;
    std::vector<int> piece;
    for (int v = 0; v < part.mesh.vertexCount(); ++v) {
        if (weights[v].empty())
            continue;
        const BoneId leading = leadingBone(weights[v]);
        if (leading == bone || neighbours.contains(leading))
            piece.push_back(v);
        std::erase_if(weights[v], [&](const auto& e) { return e.first == bone; });
        normaliseWeights(weights[v]);
    }
    return finish(part, std::move(skeleton), weights, piece, piece,
                  std::vector<BoneId>(neighbours.begin(), neighbours.end()), start);
}

}  // namespace rigmesh
