#include "pose/QuaternionInterpolation.h"

#include <algorithm>
#include <cmath>

namespace rigmesh {

namespace {

// Below this angle between a and b slerp's sin(theta) loses precision and
// normalised linear interpolation is as accurate.
constexpr double kSmallAngle = 1e-6;

Eigen::Quaterniond fromCoeffs(const Eigen::Vector4d& c) {
    Eigen::Quaterniond q;
    q.coeffs() = c;
    return q;
}

// log of a unit quaternion: (0, theta * axis).
Eigen::Vector3d logUnit(const Eigen::Quaterniond& q) {
    const double vn = q.vec().norm();
    if (vn < 1e-15)
        return Eigen::Vector3d::Zero();
    return std::atan2(vn, q.w()) * q.vec() / vn;
}

Eigen::Quaterniond expPure(const Eigen::Vector3d& v) {
    const double angle = v.norm();
    if (angle < 1e-15)
        return Eigen::Quaterniond::Identity();
    const Eigen::Vector3d axis = v / angle;
    return Eigen::Quaterniond(std::cos(angle), std::sin(angle) * axis.x(),
                              std::sin(angle) * axis.y(), std::sin(angle) * axis.z());
}

}  // namespace

Eigen::Quaterniond slerpArc(const Eigen::Quaterniond& a, const Eigen::Quaterniond& b, double u) {
    if (u == 0.0)
        return a;
    if (u == 1.0)
        return b;
    const double d = std::clamp(a.coeffs().dot(b.coeffs()), -1.0, 1.0);
    const double theta = std::acos(d);
    if (theta < kSmallAngle)
        return fromCoeffs((1 - u) * a.coeffs() + u * b.coeffs()).normalized();
    if (M_PI - theta < kSmallAngle) {
        // Opposite quaternions (a full turn apart): any great arc works; go
        // through a perpendicular quaternion so the path stays defined.
        const Eigen::Vector4d p(-a.y(), a.x(), -a.w(), a.z());
        const double phi = u * M_PI;
        return fromCoeffs(std::cos(phi) * a.coeffs() + std::sin(phi) * p).normalized();
    }
    const double s = std::sin(theta);
    return fromCoeffs((std::sin((1 - u) * theta) / s) * a.coeffs() +
                      (std::sin(u * theta) / s) * b.coeffs())
        .normalized();
}

Eigen::Quaterniond slerpShortest(const Eigen::Quaterniond& a, const Eigen::Quaterniond& b,
                                 double u) {
    if (a.coeffs().dot(b.coeffs()) < 0)
        return slerpArc(a, fromCoeffs(-b.coeffs()), u);
    return slerpArc(a, b, u);
}

void alignHemispheres(std::vector<Eigen::Quaterniond>& keys) {
    for (std::size_t i = 1; i < keys.size(); ++i) {
        if (keys[i].coeffs().dot(keys[i - 1].coeffs()) < 0)
            keys[i].coeffs() = -keys[i].coeffs();
    }
}

Eigen::Quaterniond squadControl(const Eigen::Quaterniond& prev, const Eigen::Quaterniond& q,
                                const Eigen::Quaterniond& next) {
    const Eigen::Quaterniond inv = q.conjugate();
    const Eigen::Vector3d sum = logUnit(inv * next) + logUnit(inv * prev);
    return (q * expPure(-sum / 4.0)).normalized();
}

Eigen::Quaterniond squad(const Eigen::Quaterniond& q0, const Eigen::Quaterniond& q1,
                         const Eigen::Quaterniond& s0, const Eigen::Quaterniond& s1, double u) {
    if (u == 0.0)
        return q0;
    if (u == 1.0)
        return q1;
    return slerpArc(slerpArc(q0, q1, u), slerpArc(s0, s1, u), 2 * u * (1 - u));
}

}  // namespace rigmesh
