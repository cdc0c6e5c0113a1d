// The SVG `transform` attribute as a 2D affine map.
#pragma once

#include <Eigen/Core>
#include <string_view>

#include "base/Types.h"

namespace rigmesh {

// A 2D affine map in homogeneous form: the last row is (0, 0, 1).
using Affine2 = Eigen::Matrix3d;

// Parses a transform list such as "translate(10,20) rotate(30 5 5)": matrix,
// translate, scale, rotate, skewX and skewY, applied right to left like SVG
// does. An empty attribute is the identity. Throws SvgSyntaxError
// (sketch/SvgNumberScanner.h) when malformed.
Affine2 parseSvgTransform(std::string_view attribute);

// Applies `transform` to the point `p`.
Vec2 applyAffine(const Affine2& transform, const Vec2& p);

}  // namespace rigmesh
