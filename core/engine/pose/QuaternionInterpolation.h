// Rotation interpolation for animation clips: slerp, and squad (Shoemake
// 1987) for a smooth (C1 at uniform key spacing) curve through key rotations.
#pragma once

#include <vector>

#include <Eigen/Geometry>

namespace rigmesh {

// Spherical linear interpolation along the great arc from a to b, without
// choosing the shorter of q / -q (callers align hemispheres themselves).
// u = 0 gives a and u = 1 gives b exactly.
Eigen::Quaterniond slerpArc(const Eigen::Quaterniond& a, const Eigen::Quaterniond& b, double u);

// Slerp along the shorter arc (b flipped to a's hemisphere).
Eigen::Quaterniond slerpShortest(const Eigen::Quaterniond& a, const Eigen::Quaterniond& b,
                                 double u);

// Flips each quaternion into its predecessor's hemisphere (q and -q are the
// same rotation), so that consecutive keys are interpolated the short way.
void alignHemispheres(std::vector<Eigen::Quaterniond>& keys);

// Squad's inner control point for key q with neighbours prev and next
// (all unit and hemisphere aligned):
//     s = q exp(-(log(q^-1 next) + log(q^-1 prev)) / 4).
Eigen::Quaterniond squadControl(const Eigen::Quaterniond& prev, const Eigen::Quaterniond& q,
                                const Eigen::Quaterniond& next);

// squad(q0, q1, s0, s1, u) = slerp(slerp(q0, q1, u), slerp(s0, s1, u), 2u(1-u)).
Eigen::Quaterniond squad(const Eigen::Quaterniond& q0, const Eigen::Quaterniond& q1,
                         const Eigen::Quaterniond& s0, const Eigen::Quaterniond& s1, double u);

}  // namespace rigmesh
