// A bone as the skin weight solver sees it: a 3D segment from head to tail,
// with the point/segment distance queries Pinocchio's bone heat skinning needs
// (Baran & Popovic 2007, section 4: heat flows from the closest point of the
// closest visible bone).
#pragma once

#include <algorithm>

#include "base/Types.h"

namespace rigmesh {

struct BoneSegment {
    Vec3 head;
    Vec3 tail;
};

// Parameter t in [0, 1] of the point of `bone` closest to `p`; a degenerate
// bone (head == tail) answers 0.
inline double closestSegmentParameter(const Vec3& p, const BoneSegment& bone) {
    const Vec3 axis = bone.tail - bone.head;
    const double lengthSquared = axis.squaredNorm();
    if (!(lengthSquared > 0.0)) {
        return 0.0;
    }
    return std::clamp((p - bone.head).dot(axis) / lengthSquared, 0.0, 1.0);
}

inline Vec3 closestPointOnSegment(const Vec3& p, const BoneSegment& bone) {
    return bone.head + closestSegmentParameter(p, bone) * (bone.tail - bone.head);
}

// Euclidean distance from `p` to the segment; NaN if the bone is not finite.
inline double pointSegmentDistance(const Vec3& p, const BoneSegment& bone) {
    return (p - closestPointOnSegment(p, bone)).norm();
}

inline bool isFinite(const BoneSegment& bone) {
    return bone.head.allFinite() && bone.tail.allFinite();
}

}  // namespace rigmesh
