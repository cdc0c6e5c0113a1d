#include "IoTestSupport.h"

#include <cmath>
#include <limits>
#include <unordered_map>

namespace rigmesh::iotest {

std::vector<int> matchVertices(const std::vector<Vec3>& a, const std::vector<Vec3>& b) {
    if (b.empty())
        return std::vector<int>(a.size(), -1);
    Vec3 lo = b[0], hi = b[0];
    for (const Vec3& v : b) {
        lo = lo.cwiseMin(v);
        hi = hi.cwiseMax(v);
    }
    const double cell = std::max((hi - lo).norm() / 64.0, 1e-12);
    auto key = [&](const Vec3& p, int dx, int dy, int dz) {
        const long x = static_cast<long>(std::floor((p.x() - lo.x()) / cell)) + dx;
        const long y = static_cast<long>(std::floor((p.y() - lo.y()) / cell)) + dy;
        const long z = static_cast<long>(std::floor((p.z() - lo.z()) / cell)) + dz;
        return (x * 73856093L) ^ (y * 19349663L) ^ (z * 83492791L);
    };
    std::unordered_multimap<long, int> grid;
    for (int i = 0; i < static_cast<int>(b.size()); ++i)
        grid.emplace(key(b[static_cast<std::size_t>(i)], 0, 0, 0), i);
    std::vector<int> match;
    for (const Vec3& p : a) {
        int best = -1;
        double bestDistance = std::numeric_limits<double>::max();
        for (int dx = -1; dx <= 1; ++dx)
            for (int dy = -1; dy <= 1; ++dy)
                for (int dz = -1; dz <= 1; ++dz) {
                    const auto [first, last] = grid.equal_range(key(p, dx, dy, dz));
                    for (auto it = first; it != last; ++it) {
                        const double d = (b[static_cast<std::size_t>(it->second)] - p).norm();
                        if (d < bestDistance) {
                            bestDistance = d;
                            best = it->second;
                        }
                    }
                }
        match.push_back(best);
    }
    return match;
}

}  // namespace rigmesh::iotest
