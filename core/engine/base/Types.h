// Small value types shared by every engine module.
#pragma once

#include <Eigen/Core>
#include <vector>

namespace rigmesh {

using Vec2 = Eigen::Vector2d;
using Vec3 = Eigen::Vector3d;

// An ordered list of 2D points; whether it is closed is said by its user.
using Polyline2 = std::vector<Vec2>;

}  // namespace rigmesh
