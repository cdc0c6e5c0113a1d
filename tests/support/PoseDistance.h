// How far apart two poses are: the largest joint rotation angle between them
// (radians) or root translation difference, over the joints of either.
#pragma once

#include <algorithm>

#include "pose/Pose.h"

namespace rigmesh::test {

inline double poseDistance(const Pose& a, const Pose& b) {
    double worst = (a.rootTranslation - b.rootTranslation).norm();
    for (const auto& [joint, q] : a.rotations)
        worst = std::max(worst, q.angularDistance(b.rotation(joint)));
    for (const auto& [joint, q] : b.rotations)
        worst = std::max(worst, q.angularDistance(a.rotation(joint)));
    return worst;
}

}  // namespace rigmesh::test
