// Small helpers every tool and the viewport share: Qt and
// Eigen vectors, the angle the cursor sweeps around a point on screen (the
// turns of Select and Pose), and a joint's parent as the pose sees it.
#pragma once

#include <QPointF>
#include <QVector3D>
#include <cmath>

#include "base/Types.h"
#include "pose/PoseHierarchy.h"
#include "rig/Skeleton.h"

namespace rigmesh::widgets {

inline QVector3D toQt(const Vec3& v) {
    return QVector3D(float(v.x()), float(v.y()), float(v.z()));
}

inline Vec3 toEigen(const QVector3D& v) {
    return Vec3(v.x(), v.y(), v.z());
}

// The signed angle (radians) the cursor swept around `centre` on screen from
// `from` to `to`. Screen y points down, so a clockwise sweep is positive: a
// positive turn about the camera's forward axis, as the user sees it.
inline double screenSweep(const QPointF& centre, const QPointF& from, const QPointF& to) {
    const double start = std::atan2(from.y() - centre.y(), from.x() - centre.x());
    const double now = std::atan2(to.y() - centre.y(), to.x() - centre.x());
    return std::remainder(now - start, 2.0 * M_PI);
}

// The joint whose rotation turns `joint`'s bone: its parent in the pose's
// hierarchy (breadth first from the root, so skeletons whose bones were never
// reoriented, such as imported ones, agree with forward kinematics);
// kNoJoint for the root or an unknown joint.
inline JointId poseParent(const Skeleton& skeleton, JointId joint) {
    if (skeleton.jointCount() == 0 || !skeleton.hasJoint(joint))
        return kNoJoint;
    const PoseHierarchy hierarchy(skeleton);
    const int parent = hierarchy.parent(hierarchy.indexOf(joint));
    return parent < 0 ? kNoJoint : hierarchy.jointId(parent);
}

}  // namespace rigmesh::widgets
