// A skeleton's bones as the segments the weight solvers and distance
// queries take (rig/BoneSegment.h), from head joint to tail joint.
#pragma once

#include <vector>

#include "rig/BoneSegment.h"
#include "rig/Skeleton.h"

namespace rigmesh {

inline BoneSegment segmentOf(const Skeleton& skeleton, const Bone& bone) {
    return {skeleton.joint(bone.head).position, skeleton.joint(bone.tail).position};
}

// Throws Error on an unknown bone.
inline BoneSegment segmentOf(const Skeleton& skeleton, BoneId id) {
    return segmentOf(skeleton, skeleton.bone(id));
}

// Every bone's segment, in the order of skeleton.bones().
inline std::vector<BoneSegment> segmentsOf(const Skeleton& skeleton) {
    std::vector<BoneSegment> segments;
    segments.reserve(skeleton.bones().size());
    for (const Bone& bone : skeleton.bones())
        segments.push_back(segmentOf(skeleton, bone));
    return segments;
}

// The segments of `ids`, in that order.
inline std::vector<BoneSegment> segmentsOf(const Skeleton& skeleton,
                                           const std::vector<BoneId>& ids) {
    std::vector<BoneSegment> segments;
    segments.reserve(ids.size());
    for (BoneId id : ids)
        segments.push_back(segmentOf(skeleton, id));
    return segments;
}

}  // namespace rigmesh
