// The debug SVG shows what the surface was built on (debug/DebugSvg.h): its
// regions and sections, which differ from the rig's where the
// surface-only steps (ARCHITECTURE section 2) apply, in world coordinates like everything else.
#include <gtest/gtest.h>

#include <Eigen/Geometry>
#include <string>

#include "SurfaceTestSupport.h"
#include "debug/DebugSvg.h"

namespace rigmesh {
namespace {

int countOf(const std::string& text, const std::string& what) {
    int count = 0;
    for (std::size_t at = text.find(what); at != std::string::npos;
         at = text.find(what, at + what.size()))
        ++count;
    return count;
}

std::string group(const std::string& svg, const std::string& id) {
    const std::size_t start = svg.find("<g id='" + id + "'");
    const std::size_t end = svg.find("</g>", start);
    return start == std::string::npos ? std::string() : svg.substr(start, end - start);
}

TEST(DebugSvg, ABodyBumpsPatchIsDrawnThoughTheRigHasNoConnectingRegion) {
    const SketchToSurfaceResult result = sketchToSurface(testsupport::blobWithBump());
    ASSERT_TRUE(result.decomposition.connecting.empty());
    ASSERT_TRUE(result.surfaceRegions.has_value());
    ASSERT_FALSE(result.surfaceRegions->connecting.empty());
    const std::string svg = debugSvg(result);
    EXPECT_GT(countOf(group(svg, "triangles"), "fill='#8fd18f'"), 0);
}

TEST(DebugSvg, TheSurfacesSectionsAreDrawnInWorldCoordinates) {
    // A shared sketch moved far from the origin: the surface's sections come
    // back to the world with the rest.
    std::vector<Vec2> points = testsupport::sharedSketchPoints("biped");
    for (Vec2& p : points)
        p += Vec2(1000.0, -500.0);
    const SketchToSurfaceResult result = sketchToSurface(points);
    std::size_t sections = 0;
    Eigen::AlignedBox2d outline;
    for (const Vec2& p : result.polygon.points)
        outline.extend(p);
    const double slack = 2.0 * result.targetEdgeLength;
    for (const CylinderSections& cylinder : result.surfaceCylinders)
        for (const CrossSection& s : cylinder.sections) {
            ++sections;
            for (const Vec2& p : {s.left, s.right})
                EXPECT_LT(outline.exteriorDistance(p), slack);
        }
    ASSERT_GT(sections, 0u);
    EXPECT_EQ(countOf(group(debugSvg(result), "cross-sections"), "<line"),
              static_cast<int>(sections));
}

}  // namespace
}  // namespace rigmesh
