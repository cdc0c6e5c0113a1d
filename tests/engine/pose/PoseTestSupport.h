// Helpers for the posing tests: rigged parts from the shared sketches (built
// once per test binary), synthetic skeletons, random poses and small mesh
// measures.
#pragma once

#include <gtest/gtest.h>

#include <Eigen/Geometry>
#include <algorithm>
#include <cmath>
#include <map>
#include <random>
#include <string>
#include <vector>

#include "SharedSketchPart.h"
#include "SketchToSurfaceTestSupport.h"
#include "pipeline/SketchToPart.h"
#include "pose/ForwardKinematics.h"
#include "pose/Pose.h"

namespace rigmesh::posetest {

inline const Part& sharedPart(const std::string& sketch) {
    return testsupport::sharedSketchPart(sketch);
}

inline double boundingBoxDiagonal(const std::vector<Vec3>& points) {
    Eigen::AlignedBox3d box;
    for (const Vec3& p : points)
        box.extend(p);
    return box.diagonal().norm();
}

// A straight chain of `bones` bones of length `length` along +x from the
// origin; the root is the first joint.
inline Skeleton straightChain(int bones, double length) {
    Skeleton s;
    JointId previous = s.addJoint(Vec3::Zero());
    for (int i = 1; i <= bones; ++i) {
        const JointId next = s.addJoint(Vec3(i * length, 0, 0));
        s.addBone(previous, next);
        previous = next;
    }
    return s;
}

// A uniformly random unit quaternion turned by at most `maxAngle` radians.
inline Eigen::Quaterniond randomRotation(std::mt19937& rng, double maxAngle) {
    std::normal_distribution<double> normal;
    std::uniform_real_distribution<double> uniform(0.0, maxAngle);
    const Vec3 axis = Vec3(normal(rng), normal(rng), normal(rng)).normalized();
    return Eigen::Quaterniond(Eigen::AngleAxisd(uniform(rng), axis));
}

// Every joint at a random rotation of at most `maxAngle`, plus a random root
// translation of at most `maxTranslation` per axis.
inline Pose randomPose(const Skeleton& skeleton, std::mt19937& rng, double maxAngle,
                       double maxTranslation = 0.0) {
    Pose pose;
    for (const Joint& joint : skeleton.joints())
        pose.setRotation(joint.id, randomRotation(rng, maxAngle));
    std::uniform_real_distribution<double> offset(-maxTranslation, maxTranslation);
    pose.rootTranslation = Vec3(offset(rng), offset(rng), offset(rng));
    return pose;
}

// Joints by number of bones from the root (breadth first).
inline std::vector<int> jointDepths(const PoseHierarchy& h) {
    std::vector<int> depth(h.jointCount(), 0);
    for (int j : h.parentFirstOrder())
        depth[j] = h.parent(j) < 0 ? 0 : depth[h.parent(j)] + 1;
    return depth;
}

// The joint furthest from the root in bones (the first one on a tie).
inline JointId deepestJoint(const Skeleton& skeleton) {
    const PoseHierarchy h(skeleton);
    const std::vector<int> depth = jointDepths(h);
    return h.jointId(
        static_cast<int>(std::max_element(depth.begin(), depth.end()) - depth.begin()));
}

// Posed bone lengths from FK.
inline std::vector<double> posedBoneLengths(const Skeleton& skeleton, const Pose& pose) {
    const PoseHierarchy h(skeleton);
    const PosedSkeleton posed = forwardKinematics(h, pose);
    std::vector<double> lengths;
    for (int b = 0; b < h.boneCount(); ++b)
        lengths.push_back(
            (posed.jointPositions[h.boneTailJoint(b)] - posed.jointPositions[h.boneHeadJoint(b)])
                .norm());
    return lengths;
}

// Signed volume enclosed by a closed, outward-oriented mesh.
inline double signedVolume(const std::vector<Vec3>& vertices,
                           const std::vector<std::array<int, 3>>& faces) {
    double sixTimes = 0.0;
    for (const auto& [a, b, c] : faces)
        sixTimes += vertices[a].dot(vertices[b].cross(vertices[c]));
    return sixTimes / 6.0;
}

// Angle of the rotation taking a to b (q and -q alike).
inline double rotationAngle(const Eigen::Quaterniond& a, const Eigen::Quaterniond& b) {
    return 2.0 * std::acos(std::min(1.0, std::abs(a.normalized().dot(b.normalized()))));
}

}  // namespace rigmesh::posetest
