// Body sections next to a fixed end chord follow the drawn outline
// (surface/EndSectionSnap.h): the section one in lies within an
// eighth of its smoothed distance from the outline, those further in move
// less, and nothing else changes.
#include <gtest/gtest.h>

#include <limits>

#include "SurfaceTestSupport.h"
#include "sketch/PolygonGeometry.h"
#include "surface/EndSectionSnap.h"

namespace rigmesh {
namespace {

double distanceToOutline(const std::vector<Vec2>& outline, const Vec2& p) {
    double nearest = std::numeric_limits<double>::infinity();
    for (std::size_t i = 0; i < outline.size(); ++i)
        nearest =
            std::min(nearest, distanceToSegment(p, outline[i], outline[(i + 1) % outline.size()]));
    return nearest;
}

// The larger distance of a section's two end points from the outline.
double offOutline(const std::vector<Vec2>& outline, const CrossSection& s) {
    return std::max(distanceToOutline(outline, s.left), distanceToOutline(outline, s.right));
}

TEST(EndSectionSnap, SectionsNextToAFixedEndMeetTheOutlineAndNothingElseMoves) {
    int snapped = 0;
    for (const std::string& name : testsupport::sharedSketchNames(false)) {
        SCOPED_TRACE(name);
        const SketchToSurfaceResult result = sketchToSurface(testsupport::sharedSketchPoints(name));
        const std::vector<Vec2>& outline = result.decomposition.axis.cdt.points;
        std::vector<CylinderSections> cylinders = result.cylinders;
        snapSectionsNearEndsToOutline(cylinders, result.decomposition);
        for (std::size_t c = 0; c < cylinders.size(); ++c) {
            const auto& before = result.cylinders[c].sections;
            const auto& after = cylinders[c].sections;
            ASSERT_EQ(after.size(), before.size());
            int first = 0, last = static_cast<int>(before.size()) - 1;
            while (first <= last && before[first].inCap)
                ++first;
            while (last >= first && before[last].inCap)
                --last;
            for (int s = 0; s < static_cast<int>(before.size()); ++s) {
                EXPECT_EQ(after[s].leftPolygonIndex, before[s].leftPolygonIndex);
                EXPECT_EQ(after[s].rightPolygonIndex, before[s].rightPolygonIndex);
                EXPECT_EQ(after[s].inCap, before[s].inCap);
                const int in = std::min(s - first, last - s);  // sections in from the nearer end
                if (before[s].inCap || in <= 0 || in >= 8) {
                    EXPECT_EQ(after[s].left, before[s].left) << c << " " << s;
                    EXPECT_EQ(after[s].right, before[s].right) << c << " " << s;
                    continue;
                }
                // No strip folds: a moved section crosses neither neighbour.
                for (int n : {s - 1, s + 1})
                    EXPECT_FALSE(segmentsIntersect(after[s].left, after[s].right, after[n].left,
                                                   after[n].right))
                        << c << " " << s << " " << n;
                // Never further from the outline than smoothing left it.
                EXPECT_LE(offOutline(outline, after[s]), offOutline(outline, before[s]) + 1e-12);
                if (in == 1 && last - first > 2) {
                    EXPECT_LE(offOutline(outline, after[s]),
                              offOutline(outline, before[s]) / 8.0 + 1e-9)
                        << c << " " << s;
                    snapped += offOutline(outline, before[s]) > 1e-9;
                }
            }
        }
    }
    // Smoothing left some end-adjacent sections off the outline (else this
    // test could not fail).
    EXPECT_GT(snapped, 10);
}

}  // namespace
}  // namespace rigmesh
