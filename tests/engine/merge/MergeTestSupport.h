// Parts of the shared sketches placed for merges, and the checks every merge
// test asks of its result.
#pragma once

#include <gtest/gtest.h>

#include <Eigen/Geometry>
#include <map>
#include <string>

#include "SharedSketchPart.h"
#include "merge/MergeParts.h"
#include "mesh/MeshChecks.h"

namespace rigmesh::mergetest {

using testsupport::sharedSketchPart;

// The part moved by `offset` (what a placement does in the document).
inline Part translated(Part part, const Vec3& offset) {
    for (Vec3& p : part.mesh.vertices)
        p += offset;
    Skeleton& s = part.skeleton;
    for (const Joint& joint : std::vector<Joint>(s.joints()))
        s.setJointPosition(joint.id, joint.position + offset);
    return part;
}

// The part turned by `angle` radians about `axis` through the origin.
inline Part rotated(Part part, const Vec3& axis, double angle) {
    const Eigen::Matrix3d r = Eigen::AngleAxisd(angle, axis.normalized()).toRotationMatrix();
    for (Vec3& p : part.mesh.vertices)
        p = r * p;
    Skeleton& s = part.skeleton;
    for (const Joint& joint : std::vector<Joint>(s.joints()))
        s.setJointPosition(joint.id, r * joint.position);
    return part;
}

// The joint of `part` nearest to `point`.
inline JointId nearestJoint(const Part& part, const Vec3& point) {
    JointId best = kNoJoint;
    double bestDistance = 0.0;
    for (const Joint& joint : part.skeleton.joints()) {
        const double d = (joint.position - point).norm();
        if (best == kNoJoint || d < bestDistance) {
            best = joint.id;
            bestDistance = d;
        }
    }
    return best;
}

// The joint of `part` with the largest (or smallest) coordinate `axis`.
inline JointId extremeJoint(const Part& part, int axis, bool largest) {
    const auto& joints = part.skeleton.joints();
    return std::max_element(joints.begin(), joints.end(),
                            [&](const Joint& a, const Joint& b) {
                                return largest ? a.position[axis] < b.position[axis]
                                               : a.position[axis] > b.position[axis];
                            })
        ->id;
}

// Closed, manifold, consistently oriented, free of self-intersections; the
// part's own invariants; every bone leads at least one vertex, but those the
// merge request made (a connecting bone may lead none: it is there to pose).
inline void expectValidMergedPart(const Part& part, const std::vector<BoneId>& requested = {}) {
    const MeshReport report = analyseMesh(part.mesh, true);
    EXPECT_TRUE(report.isWatertightGenus0() || (report.isClosed() && report.isManifold()))
        << "closed " << report.isClosed() << " manifold " << report.isManifold();
    EXPECT_EQ(report.selfIntersectingFacePairs, 0);
    EXPECT_EQ(report.inconsistentlyOrientedEdges, 0);
    const auto problems = part.validateSolid();
    EXPECT_TRUE(problems.empty()) << englishText(problems);
    std::map<BoneId, int> leads = leadingVertexCounts(part.weights.perVertex);
    for (const Bone& bone : part.skeleton.bones())
        if (std::find(requested.begin(), requested.end(), bone.id) == requested.end()) {
            EXPECT_GT(leads[bone.id], 0) << "bone " << bone.id << " leads no vertex";
        }
}

}  // namespace rigmesh::mergetest
