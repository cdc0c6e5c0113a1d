// An exact position as a hash key: vertices that are bitwise at one place
// (a seam's copies) hash alike. For std::unordered_map<Vec3, T, PositionHash>.
#pragma once

#include <cstddef>
#include <functional>

#include "base/Types.h"

namespace rigmesh {

struct PositionHash {
    std::size_t operator()(const Vec3& p) const {
        std::size_t h = 0;
        for (int i = 0; i < 3; ++i)
            h ^= std::hash<double>{}(p[i]) + 0x9e3779b97f4a7c15ULL + (h << 6) + (h >> 2);
        return h;
    }
};

}  // namespace rigmesh
