// A closed outline made exactly symmetric, for tests of mirrored rigs and
// mirrored paint on a shape whose two halves are alike to the last bit.
#pragma once

#include <Eigen/Geometry>
#include <vector>

#include "base/Types.h"

namespace rigmesh::testsupport {

// A closed outline made exactly symmetric about the vertical line through
// its box's middle: its right half and that half reflected. A drawn outline
// is only roughly symmetric, and its limbs' weights differ as much as its
// limbs do, so a mirrored stroke is compared on such an outline.
inline std::vector<Vec2> symmetricOutline(const std::vector<Vec2>& points) {
    Eigen::AlignedBox2d box;
    for (const Vec2& p : points)
        box.extend(p);
    const double middle = box.center().x();
    // The run of points right of the middle, from crossing to crossing.
    const int n = static_cast<int>(points.size());
    int start = 0;
    for (int i = 0; i < n; ++i)
        if (points[i].x() < middle && points[(i + 1) % n].x() >= middle)
            start = (i + 1) % n;
    std::vector<Vec2> right;
    for (int k = 0; k < n && points[(start + k) % n].x() >= middle; ++k)
        right.push_back(points[(start + k) % n]);
    std::vector<Vec2> outline = right;
    for (auto it = right.rbegin(); it != right.rend(); ++it)
        outline.emplace_back(2.0 * middle - it->x(), it->y());
    return outline;
}

}  // namespace rigmesh::testsupport
