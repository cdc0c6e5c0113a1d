// Order statistics of measured figures (surface angles, weight differences).
#pragma once

#include <algorithm>
#include <cstddef>
#include <vector>

namespace rigmesh {

// The value below which `fraction` (0..1) of `values` lie, by the nearest
// rank below: the element at floor(fraction * (n - 1)) of the sorted values.
// 0 for no values.
inline double percentile(std::vector<double> values, double fraction) {
    if (values.empty())
        return 0.0;
    const auto rank =
        std::min(values.size() - 1,
                 static_cast<std::size_t>(fraction * static_cast<double>(values.size() - 1)));
    const auto at = values.begin() + static_cast<std::ptrdiff_t>(rank);
    std::nth_element(values.begin(), at, values.end());
    return *at;
}

}  // namespace rigmesh
