// The principal axes of a point set: its centroid and the eigen
// decomposition of its scatter matrix (sum of (p - c)(p - c)^T), the
// eigenvalues increasing, so the last eigenvector is the main direction.
// Shared by the auto-rig's main-axis chain and held props and by the
// mirror-plane search's candidate normals.
#pragma once

#include <Eigen/Eigenvalues>
#include <vector>

#include "base/Types.h"

namespace rigmesh {

struct PrincipalAxes {
    Vec3 centroid = Vec3::Zero();
    Eigen::SelfAdjointEigenSolver<Eigen::Matrix3d> scatter;
};

// `points` must not be empty.
inline PrincipalAxes principalAxesOf(const std::vector<Vec3>& points) {
    PrincipalAxes axes;
    for (const Vec3& p : points)
        axes.centroid += p;
    axes.centroid /= static_cast<double>(points.size());
    Eigen::Matrix3d scatter = Eigen::Matrix3d::Zero();
    for (const Vec3& p : points)
        scatter += (p - axes.centroid) * (p - axes.centroid).transpose();
    axes.scatter.compute(scatter);
    return axes;
}

}  // namespace rigmesh
