// A rigid transform x -> rotation * x + translation, the value forward
// kinematics produces per joint and bone and skinning blends (paper section 3).
#pragma once

#include <Eigen/Geometry>

#include "base/Types.h"

namespace rigmesh {

struct RigidTransform {
    Eigen::Quaterniond rotation = Eigen::Quaterniond::Identity();  // unit
    Vec3 translation = Vec3::Zero();

    Vec3 apply(const Vec3& x) const { return rotation * x + translation; }
    // (*this) after `inner`: x -> this(inner(x)).
    RigidTransform operator*(const RigidTransform& inner) const {
        return {rotation * inner.rotation, rotation * inner.translation + translation};
    }
    RigidTransform inverse() const {
        const Eigen::Quaterniond inv = rotation.conjugate();
        return {inv, -(inv * translation)};
    }
    // Exactly the identity (no tolerance): what the rest pose produces.
    bool isIdentity() const {
        return rotation.w() == 1.0 && rotation.vec().isZero(0.0) && translation.isZero(0.0);
    }

    static RigidTransform identity() { return {}; }
    // Rotation by `q` about the point `centre`: x -> centre + q (x - centre),
    // written as q x + (centre - q centre) so that q = identity gives a zero
    // translation exactly.
    static RigidTransform rotationAbout(const Eigen::Quaterniond& q, const Vec3& centre) {
        return {q, centre - q * centre};
    }
};

}  // namespace rigmesh
