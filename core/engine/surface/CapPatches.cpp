#include "surface/CapPatches.h"

#include <algorithm>
#include <cmath>
#include <limits>
#include <numbers>
#include <set>

#include "sketch/PolygonGeometry.h"
#include "surface/SectionGaps.h"

namespace rigmesh {
namespace {

// A face steeper than this (degrees) is a wall's (tests/engine/surface/SurfaceWall.h).
constexpr double kSteepDegrees = 75.0;
// A cap is built as a patch where its slices would stand as a wall deeper
// than this (local edge lengths): Least-Squares Meshes, leaving the strip
// across the gap free (SectionGaps.h), takes such a wall down by about half,
// and SurfaceWall.h allows 2. On the creature family the slices of caps
// with gaps stand 2.7-3.5 deep (walls of 0.8-1.5 left after the solve) or
// 4.1-4.7 (1.8-2.5 left).
constexpr double kWallDepth = 4.0;

// The triangles on the cap's side of its base chord: from the triangle on
// the chord whose third corner lies on the cap's outline path, across every
// edge but the chord.
std::vector<int> capTriangles(const PolygonTriangulation& cdt, const PolygonEdge& base,
                              const std::vector<int>& capPath) {
    const std::set<int> onPath(capPath.begin(), capPath.end());
    auto isBase = [&](int a, int b) {
        return (a == base[0] && b == base[1]) || (a == base[1] && b == base[0]);
    };
    const int count = static_cast<int>(cdt.triangles.size());
    int start = -1;
    for (int t = 0; t < count && start < 0; ++t)
        for (int k = 0; k < 3; ++k)
            if (isBase(cdt.triangles[t][(k + 1) % 3], cdt.triangles[t][(k + 2) % 3]) &&
                onPath.count(cdt.triangles[t][k]))
                start = t;
    std::vector<int> triangles;
    if (start < 0)
        return triangles;
    std::vector<bool> seen(count, false);
    std::vector<int> stack{start};
    seen[start] = true;
    while (!stack.empty()) {
        const int t = stack.back();
        stack.pop_back();
        triangles.push_back(t);
        for (int k = 0; k < 3; ++k) {
            const int n = cdt.neighbors[t][k];
            if (n < 0 || seen[n] ||
                isBase(cdt.triangles[t][(k + 1) % 3], cdt.triangles[t][(k + 2) % 3]))
                continue;
            seen[n] = true;
            stack.push_back(n);
        }
    }
    return triangles;
}

// Whether the cylinder's start (first) and end (second) caps have a gap
// between their slices.
std::pair<bool, bool> capsWithGaps(const CylinderSections& cylinder, double targetEdgeLength) {
    const auto& sections = cylinder.sections;
    const auto body = std::find_if(sections.begin(), sections.end(),
                                   [](const CrossSection& s) { return !s.inCap; });
    if (body == sections.end())
        return {false, false};
    const auto lastBody = std::find_if(sections.rbegin(), sections.rend(),
                                       [](const CrossSection& s) { return !s.inCap; });
    const double first = cylinder.axisPosition[body - sections.begin()];
    const double last = cylinder.axisPosition[sections.rend() - lastBody - 1];
    bool start = false, end = false;
    for (const SectionGap& gap : sectionGaps(cylinder, targetEdgeLength)) {
        start = start || gap.axisPosition < first;
        end = end || gap.axisPosition > last;
    }
    return {start, end};
}

// How deep inside the outline a cap's slices stand as a wall (local edge
// lengths): the largest distance D to the outline of a point on a slice
// whose semicircle there is higher than tan(kSteepDegrees) D, where the
// outline nearest the point is not the slice's own end (a slice passing a
// concave corner on the inside).
double sliceWallDepth(const CylinderSections& cylinder, bool atStart,
                      const std::vector<Vec2>& outline) {
    const double steep = std::tan(kSteepDegrees * std::numbers::pi / 180.0);
    const auto& sections = cylinder.sections;
    const auto body = std::find_if(sections.begin(), sections.end(),
                                   [](const CrossSection& s) { return !s.inCap; });
    const auto lastBody =
        std::find_if(sections.rbegin(), sections.rend(), [](const CrossSection& s) {
            return !s.inCap;
        }).base();
    const auto from = atStart ? sections.begin() : lastBody;
    const auto to = atStart ? body : sections.end();
    const int n = static_cast<int>(outline.size());
    double deepest = 0.0;
    for (auto s = from; s != to; ++s) {
        const double r = s->radius();
        const double spacing = s->spacing > 0 ? s->spacing : r;
        if (!(r > 0 && spacing > 0))
            continue;
        const int samples = std::max(2, static_cast<int>(std::ceil(2 * r / spacing)));
        for (int k = 1; k < samples; ++k) {
            const double f = static_cast<double>(k) / samples;
            const Vec2 x = s->left + f * (s->right - s->left);
            const double fromEnd = std::min(f, 1 - f) * 2 * r;
            const double height = std::sqrt(fromEnd * (2 * r - fromEnd));
            double d = std::numeric_limits<double>::infinity();
            for (int j = 0; j < n; ++j)
                d = std::min(d, distanceToSegment(x, outline[j], outline[(j + 1) % n]));
            if (d < 0.99 * fromEnd && height > steep * d)
                deepest = std::max(deepest, d / spacing);
        }
    }
    return deepest;
}

}  // namespace

bool patchCapsWithGaps(Decomposition& regions, std::vector<CylinderSections>& cylinders,
                       double targetEdgeLength, const CrossSectionOptions& options) {
    bool turned = false;
    for (std::size_t c = 0; c < regions.cylinders.size(); ++c) {
        const auto [startGap, endGap] = capsWithGaps(cylinders[c], targetEdgeLength);
        if (!startGap && !endGap)
            continue;
        CylinderRegion& cylinder = regions.cylinders[c];
        bool rebuilt = false;
        auto turn = [&](bool atStart) {
            if (sliceWallDepth(cylinders[c], atStart, regions.axis.cdt.points) <= kWallDepth)
                return;
            const std::vector<int>& path = atStart ? cylinder.startCap : cylinder.endCap;
            const PolygonEdge& base = atStart ? cylinder.chords.front() : cylinder.chords.back();
            ConnectingRegion patch;
            patch.triangles = capTriangles(regions.axis.cdt, base, path);
            if (patch.triangles.empty())
                return;
            const int index = static_cast<int>(regions.connecting.size());
            patch.ports.push_back({static_cast<int>(c), atStart});
            regions.connecting.push_back(std::move(patch));
            if (atStart) {
                cylinder.startCap.clear();
                cylinder.startConnecting = index;
                cylinder.startJunction = -1;
            } else {
                cylinder.endCap.clear();
                cylinder.endConnecting = index;
                cylinder.endJunction = -1;
            }
            rebuilt = true;
        };
        if (startGap)
            turn(true);
        if (endGap)
            turn(false);
        if (rebuilt)
            cylinders[c] =
                buildCrossSections(regions, static_cast<int>(c), targetEdgeLength, options);
        turned = turned || rebuilt;
    }
    return turned;
}

}  // namespace rigmesh
