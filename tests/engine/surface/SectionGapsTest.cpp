// Gaps left by dropped cap slices (surface/SectionGaps.h): found where a cap
// slice and its neighbour stand more than three local edge lengths apart on
// one side, nowhere else; and the surface built over such a gap stands no
// wall well inside the outline where Least-Squares Meshes left it held
// (stubs 37 of the creature family; a cap whose slices would stand deeper
// is a patch instead, CapPatchesTest.cpp).
#include <gtest/gtest.h>

#include "CreatureOutlines.h"
#include "SurfaceTestSupport.h"
#include "SurfaceWall.h"
#include "surface/SectionGaps.h"

namespace rigmesh {
namespace {

CrossSection sectionAt(double x, double halfWidth, bool inCap) {
    CrossSection s;
    s.left = Vec2(x, -halfWidth);
    s.right = Vec2(x, halfWidth);
    s.inCap = inCap;
    s.spacing = 1.0;
    return s;
}

CylinderSections sectionsAt(const std::vector<std::pair<double, bool>>& xs) {
    CylinderSections c;
    for (const auto& [x, inCap] : xs) {
        c.sections.push_back(sectionAt(x, 5.0, inCap));
        c.axisPosition.push_back(x);
    }
    return c;
}

TEST(SectionGaps, ACapSliceFarFromItsNeighbourOnOneSideIsAGap) {
    CylinderSections c = sectionsAt({{0, false}, {1, false}, {2, true}, {3, true}});
    // The last slice's right end moves four spacings away: one side's gap.
    c.sections[3].right += Vec2(0, 4.0);
    const std::vector<SectionGap> gaps = sectionGaps(c, 1.0);
    ASSERT_EQ(gaps.size(), 1u);
    EXPECT_DOUBLE_EQ(gaps[0].axisPosition, 2.5);
    EXPECT_DOUBLE_EQ(gaps[0].halfWidth, 0.5);
    EXPECT_NEAR(gaps[0].length, (Vec2(2, 5) - Vec2(3, 9)).norm(), 1e-12);
}

TEST(SectionGaps, SlicesOneSpacingApartAndBodySectionsFarApartAreNoGaps) {
    EXPECT_TRUE(sectionGaps(sectionsAt({{0, true}, {1, true}, {2, true}}), 1.0).empty());
    // Body sections are resampled by their own rule; a wide step between
    // two of them is not a dropped cap slice.
    EXPECT_TRUE(sectionGaps(sectionsAt({{0, false}, {10, false}}), 1.0).empty());
}

TEST(SectionGaps, AStubWhoseCapDroppedSlicesStandsNoWallAcrossTheGap) {
    const auto outline = testsupport::creatureOutline(testsupport::CreatureClass::Stubs, 37);
    const SketchToSurfaceResult result = sketchToSurface(outline.stroke);
    bool anyGap = false;
    for (const CylinderSections& c : result.surfaceCylinders)
        anyGap = anyGap || !sectionGaps(c, result.targetEdgeLength).empty();
    EXPECT_TRUE(anyGap);
    // Its slices stand up to 3.5 spacings inside the outline beside the
    // gap; with the strip across it free, within SurfaceWall.h's limit.
    const double wall = surfacetest::deepestWall(result.surface.mesh, result.polygon.points).depth /
                        result.polygon.spacing;
    EXPECT_LT(wall, 2.0);
}

}  // namespace
}  // namespace rigmesh
