// Figures of merit for a part's skin weights, measured the same
// way before and after a change to the bone heat:
//  - leak: turn one limb 60 degrees at its base (in the sketch plane and out
//    of it), skin with linear blend, and count the vertices of the other
//    limbs that move by more than 1% of the turned limb's length; summed over
//    every limb and both turns;
//  - smoothness: the 99th percentile over mesh edges of the largest change of
//    any single bone's weight across the edge;
//  - dominance: the fraction of vertices whose largest weight belongs to one
//    of their closest visible bones.
// A limb is a chain of bones from the root or a branching joint (degree >= 3)
// to a leaf through joints of degree 2. A vertex of a cylindrical region
// belongs to the limb of its closest visible bone (tested on every vertex, no
// construction shortcut); vertices of connecting regions (the body around a
// junction, paper 2.1) belong to no limb: they may follow any limb there.
#pragma once

#include <Eigen/Geometry>
#include <algorithm>
#include <cmath>
#include <numbers>
#include <vector>

#include "PartTestSupport.h"
#include "pose/Skinning.h"

namespace rigmesh::parttest {

struct Limb {
    JointId base = kNoJoint;
    std::vector<int> bones;  // bone indices, base to leaf
    double length = 0.0;
};

inline std::vector<Limb> limbsOf(const Skeleton& skeleton) {
    std::vector<Limb> limbs;
    for (const Joint& joint : skeleton.joints()) {
        if (joint.id != skeleton.root() && skeleton.degree(joint.id) < 3)
            continue;
        for (BoneId first : skeleton.childrenOf(joint.id)) {
            Limb limb;
            limb.base = joint.id;
            BoneId bone = first;
            while (true) {
                limb.bones.push_back(skeleton.indexOfBone(bone));
                limb.length += skeleton.boneLength(bone);
                const JointId tail = skeleton.bone(bone).tail;
                const std::vector<BoneId> next = skeleton.childrenOf(tail);
                if (next.size() != 1 || skeleton.degree(tail) != 2)
                    break;
                bone = next.front();
            }
            const JointId end = skeleton.bone(skeleton.bones()[limb.bones.back()].id).tail;
            if (skeleton.degree(end) == 1)
                limbs.push_back(std::move(limb));
        }
    }
    return limbs;
}

// The closest visible bone of each vertex (the nearest of its list).
inline std::vector<int> nearestVisibleBone(const ClosestBones& closest) {
    std::vector<int> nearest(closest.size(), -1);
    for (std::size_t v = 0; v < closest.size(); ++v) {
        double best = std::numeric_limits<double>::infinity();
        for (const auto& [bone, distance] : closest[v])
            if (distance < best)
                best = distance, nearest[v] = bone;
    }
    return nearest;
}

// The leak figure of `weights` on `part` (see above).
inline int limbLeak(const Part& part, const SkinWeights& weights, const ClosestBones& closest) {
    const Skeleton& skeleton = part.skeleton;
    const std::vector<Limb> limbs = limbsOf(skeleton);
    std::vector<int> limbOfBone(skeleton.boneCount(), -1);
    for (std::size_t l = 0; l < limbs.size(); ++l)
        for (int bone : limbs[l].bones)
            limbOfBone[bone] = static_cast<int>(l);
    const std::vector<int> nearest = nearestVisibleBone(closest);
    std::vector<int> limbOfVertex(nearest.size(), -1);
    for (std::size_t v = 0; v < nearest.size(); ++v)
        if (nearest[v] >= 0 && part.origins[v].kind == RegionKind::Cylindrical)
            limbOfVertex[v] = limbOfBone[nearest[v]];

    SkinningOptions lbs;
    lbs.method = SkinningMethod::LinearBlend;
    const WeightsById byId = weightsById(skeleton, weights).perVertex;  // as skinning reads them
    int moved = 0;
    for (std::size_t l = 0; l < limbs.size(); ++l) {
        const Limb& limb = limbs[l];
        const Vec3 base = skeleton.joint(limb.base).position;
        const Bone& last = skeleton.bones()[limb.bones.back()];
        Vec3 direction = skeleton.joint(last.tail).position - base;
        direction.z() = 0.0;
        direction.normalize();
        const Vec3 inPlane = Vec3::UnitZ();
        const Vec3 outOfPlane = inPlane.cross(direction).normalized();
        for (const Vec3& axis : {inPlane, outOfPlane}) {
            // A rotation about the base joint: x -> R (x - base) + base.
            const Eigen::Quaterniond turn(Eigen::AngleAxisd(std::numbers::pi / 3.0, axis));
            std::vector<RigidTransform> transforms(skeleton.boneCount());
            for (int bone : limb.bones)
                transforms[bone] = {turn, base - (turn * base)};
            const SkinnedVertices posed = skinVertices(
                part.mesh.vertices, {}, byId, SkinningTransforms(skeleton, transforms), lbs);
            for (std::size_t v = 0; v < posed.positions.size(); ++v) {
                if (limbOfVertex[v] < 0 || limbOfVertex[v] == static_cast<int>(l))
                    continue;
                if ((posed.positions[v] - part.mesh.vertices[v]).norm() > 0.01 * limb.length)
                    ++moved;
            }
        }
    }
    return moved;
}

// The 99th percentile over edges of max_b |w_b(a) - w_b(c)|.
inline double largestBoneJumpP99(const Part& part, const SkinWeights& weights) {
    const int boneCount = part.skeleton.boneCount();
    std::vector<double> jumps;
    for (const auto& [a, c] : meshEdges(part.mesh)) {
        const std::vector<double> wa = denseWeights(weights.perVertex[a], boneCount);
        const std::vector<double> wc = denseWeights(weights.perVertex[c], boneCount);
        double jump = 0.0;
        for (int b = 0; b < boneCount; ++b)
            jump = std::max(jump, std::abs(wa[b] - wc[b]));
        jumps.push_back(jump);
    }
    return percentile(jumps, 0.99);
}

// The fraction of vertices whose dominant bone is one of their closest visible bones.
inline double dominantIsClosestVisibleRate(const SkinWeights& weights,
                                           const ClosestBones& closest) {
    int hits = 0;
    for (std::size_t v = 0; v < closest.size(); ++v) {
        const int dominant = dominantBone(weights.perVertex[v]);
        for (const auto& entry : closest[v])
            if (entry.first == dominant) {
                ++hits;
                break;
            }
    }
    return closest.empty() ? 0.0 : static_cast<double>(hits) / static_cast<double>(closest.size());
}

}  // namespace rigmesh::parttest
