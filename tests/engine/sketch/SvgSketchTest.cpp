// Reading sketches from SVG: path commands, curves, transforms, y flip.
#include <gtest/gtest.h>

#include <cmath>
#include <numbers>
#include <string>

#include "SketchTestSupport.h"
#include "base/Error.h"
#include "sketch/Sketch.h"
#include "sketch/StrokeCleaner.h"

namespace rigmesh {
namespace {

Sketch svgBody(const std::string& body) {
    return parseSketchSvg(R"svg(<svg xmlns="http://www.w3.org/2000/svg">)svg" + body + "</svg>",
                          "inline.svg");
}

std::vector<Vec2> pathPoints(const std::string& d) {
    return svgBody("<path d=\"" + d + "\"/>").points;
}

std::string svgError(const std::string& body) {
    try {
        svgBody(body);
    } catch (const Error& error) {
        return error.what();
    }
    return "";
}

void expectPoints(const std::vector<Vec2>& actual, const std::vector<Vec2>& expected) {
    ASSERT_EQ(actual.size(), expected.size());
    for (std::size_t i = 0; i < actual.size(); ++i) {
        EXPECT_NEAR((actual[i] - expected[i]).norm(), 0.0, 1e-9) << "point " << i;
    }
}

TEST(SvgPath, AbsoluteLinesAreFlippedToYUp) {
    expectPoints(pathPoints("M 10 20 L 30 20 L 30 50 Z"), {{10, -20}, {30, -20}, {30, -50}});
}

TEST(SvgPath, RelativeAndAxisCommands) {
    expectPoints(pathPoints("m 10,20 l 5,0 h 10 v 10 H 0 V 0 l -1 -1 z"),
                 {{10, -20}, {15, -20}, {25, -20}, {25, -30}, {0, -30}, {0, 0}, {-1, 1}});
}

TEST(SvgPath, ImplicitRepeatedCommandsAfterMovetoAreLinetos) {
    expectPoints(pathPoints("M0 0 10 0 10 10"), {{0, 0}, {10, 0}, {10, -10}});
    expectPoints(pathPoints("m0 0 10 0 0 10"), {{0, 0}, {10, 0}, {10, -10}});
    expectPoints(pathPoints("M0 0L1 0 2 0 3 0"), {{0, 0}, {1, 0}, {2, 0}, {3, 0}});
}

TEST(SvgPath, CompactNumberSyntax) {
    expectPoints(pathPoints("M1e-3-.5.5.5L2E1,1e+1"), {{1e-3, 0.5}, {0.5, -0.5}, {20, -10}});
    expectPoints(pathPoints("M-1-2l+3-4"), {{-1, 2}, {2, 6}});
}

TEST(SvgPath, CubicCurvesAreFlattenedWithExactEndpoints) {
    const auto points = pathPoints("M0 0 C 0 10 10 10 10 0");
    ASSERT_EQ(points.size(), 17u);
    EXPECT_EQ(points.back(), Vec2(10, 0));
    // The midpoint of this symmetric cubic is at (5, 7.5), flipped.
    EXPECT_NEAR((points[8] - Vec2(5, -7.5)).norm(), 0.0, 1e-12);
}

TEST(SvgPath, SmoothCubicReflectsThePreviousControlPoint) {
    const auto smooth = pathPoints("M0 0 C 0 10 10 10 10 0 S 20 -10 20 0");
    const auto explicitCurve = pathPoints("M0 0 C 0 10 10 10 10 0 C 10 -10 20 -10 20 0");
    expectPoints(smooth, explicitCurve);
    const auto relative = pathPoints("m0 0 c 0 10 10 10 10 0 s 10 -10 10 0");
    expectPoints(relative, explicitCurve);
}

TEST(SvgPath, QuadraticAndSmoothQuadraticCurves) {
    const auto points = pathPoints("M0 0 Q 5 10 10 0 T 20 0");
    const auto explicitCurve = pathPoints("M0 0 Q 5 10 10 0 Q 15 -10 20 0");
    expectPoints(points, explicitCurve);
    ASSERT_EQ(points.size(), 33u);
    EXPECT_NEAR((points[8] - Vec2(5, -5)).norm(), 0.0, 1e-12);
    expectPoints(pathPoints("m0 0 q 5 10 10 0 t 10 0"), explicitCurve);
}

TEST(SvgPath, ArcsLieOnTheirCircle) {
    // Two half circles of radius 10 around (10, 0): a full circle.
    const auto points = pathPoints("M0 0 A 10 10 0 0 1 20 0 a 10 10 0 1 1 -20 0 z");
    ASSERT_GT(points.size(), 30u);
    for (const Vec2& p : points) {
        EXPECT_NEAR((p - Vec2(10, 0)).norm(), 10.0, 1e-9);
    }
    // Sweep flag 1 in y-down SVG goes clockwise on screen: through y = -10,
    // which is +10 once flipped.
    EXPECT_NEAR(points[points.size() / 4].y(), 10.0, 0.5);
}

TEST(SvgPath, ArcFlagsNeedNoSeparators) {
    expectPoints(pathPoints("M0 0a10 10 0 0120 0"), pathPoints("M0 0 a 10 10 0 0 1 20 0"));
}

TEST(SvgPath, ArcWithTooSmallRadiiIsScaledToReachItsEnd) {
    const auto points = pathPoints("M0 0 A 1 1 0 0 0 20 0");
    EXPECT_EQ(points.back(), Vec2(20, 0));
    for (const Vec2& p : points) {
        EXPECT_NEAR((p - Vec2(10, 0)).norm(), 10.0, 1e-9);
    }
}

TEST(SvgPath, RotatedEllipticalArcKeepsItsEndpoint) {
    const auto points = pathPoints("M0 0 A 30 10 45 1 0 20 10");
    EXPECT_NEAR((points.back() - Vec2(20, -10)).norm(), 0.0, 1e-12);
    EXPECT_GT(points.size(), 20u);
}

TEST(SvgPath, OnlyTheFirstSubpathCounts) {
    expectPoints(pathPoints("M0 0 L 1 0 L 1 1 Z M 5 5 L 6 6"), {{0, 0}, {1, 0}, {1, -1}});
    expectPoints(pathPoints("M0 0 L 1 0 L 1 1 m 5 5 l 6 6"), {{0, 0}, {1, 0}, {1, -1}});
}

TEST(SvgPath, MalformedPathDataIsAnError) {
    EXPECT_NE(svgError(R"svg(<path d="L 1 1"/>)svg").find("moveto"), std::string::npos);
    EXPECT_NE(svgError(R"svg(<path d="M 1"/>)svg").find("expected a number"), std::string::npos);
    EXPECT_NE(svgError(R"svg(<path d="M 0 0 X 3 3"/>)svg").find("unknown command"),
              std::string::npos);
    EXPECT_NE(svgError(R"svg(<path d="M0 0 A 1 1 0 2 0 3 3"/>)svg").find("arc flag"),
              std::string::npos);
}

TEST(SvgTransforms, TranslateScaleRotateAndMatrix) {
    expectPoints(svgBody(R"svg(<path transform="translate(10, 20)" d="M 1 2 L 3 4"/>)svg").points,
                 {{11, -22}, {13, -24}});
    expectPoints(svgBody(R"svg(<path transform="scale(2)" d="M 1 2"/>)svg").points, {{2, -4}});
    expectPoints(svgBody(R"svg(<path transform="scale(2 3)" d="M 1 2"/>)svg").points, {{2, -6}});
    expectPoints(svgBody(R"svg(<path transform="rotate(90)" d="M 1 0"/>)svg").points, {{0, -1}});
    expectPoints(svgBody(R"svg(<path transform="rotate(90 1 1)" d="M 2 1"/>)svg").points,
                 {{1, -2}});
    expectPoints(svgBody(R"svg(<path transform="matrix(1 2 3 4 5 6)" d="M 1 1"/>)svg").points,
                 {{9, -12}});
    expectPoints(svgBody(R"svg(<path transform="skewX(45)" d="M 0 1"/>)svg").points, {{1, -1}});
}

TEST(SvgTransforms, ListsApplyRightToLeftAndAncestorsOutermost) {
    // translate then scale in the list: the point is scaled first.
    expectPoints(svgBody(R"svg(<path transform="translate(10,0) scale(2)" d="M 1 1"/>)svg").points,
                 {{12, -2}});
    expectPoints(svgBody(R"svg(<g transform="translate(10,0)"><g transform="scale(2)">)svg"
                         R"svg(<path transform="translate(1,1)" d="M 1 1"/></g></g>)svg")
                     .points,
                 {{14, -4}});
}

TEST(SvgTransforms, MalformedTransformIsAnError) {
    EXPECT_NE(svgError(R"svg(<path transform="spin(3)" d="M 0 0"/>)svg").find("unknown transform"),
              std::string::npos);
    EXPECT_NE(svgError(R"svg(<path transform="translate(1,2" d="M 0 0"/>)svg").find("missing ')'"),
              std::string::npos);
}

TEST(SvgElements, FirstOutlineInDocumentOrderInsideGroups) {
    const Sketch sketch = svgBody(
        R"svg(<rect width="5" height="5"/><g><g><polyline points="1,2 3,4 5,6"/></g></g>)svg"
        R"svg(<path d="M 9 9 L 8 8"/>)svg");
    expectPoints(sketch.points, {{1, -2}, {3, -4}, {5, -6}});
    expectPoints(svgBody(R"svg(<polygon points="0 0 1 0 1 1"/>)svg").points,
                 {{0, 0}, {1, 0}, {1, -1}});
}

TEST(SvgElements, DefinitionsAndEmptyPathsAreSkipped) {
    const Sketch sketch = svgBody(
        R"svg(<defs><path id="marker" d="M 100 100 L 200 200"/></defs><path d=""/><path/>)svg"
        R"svg(<clipPath><path d="M 7 7 L 8 8"/></clipPath><svg:path d="M 1 1 L 2 1"/>)svg");
    expectPoints(sketch.points, {{1, -1}, {2, -1}});
}

TEST(SvgElements, DocumentWithoutOutlineIsAnError) {
    EXPECT_NE(svgError(R"svg(<rect width="5" height="5"/><circle r="3"/>)svg")
                  .find("no path, polyline or polygon"),
              std::string::npos);
    EXPECT_THROW(parseSketchSvg("<html/>", "a.svg"), Error);
    EXPECT_THROW(parseSketchSvg("<svg><path d='M 0 0'", "a.svg"), Error);
    EXPECT_NE(svgError(R"svg(<polyline points="1 2 3"/>)svg").find("odd number"),
              std::string::npos);
}

TEST(SvgFiles, InkscapeDrawingReadsAndCleans) {
    const Sketch sketch = readSketchFile(std::string(RIGMESH_TEST_DATA) + "/svg/inkscape_blob.svg");
    EXPECT_EQ(sketch.name, "inkscape_blob");
    ASSERT_GT(sketch.points.size(), 50u);
    // The layer's translate(-10,-20) and the document's y flip.
    Vec2 low = sketch.points.front();
    Vec2 high = low;
    for (const Vec2& p : sketch.points) {
        low = low.cwiseMin(p);
        high = high.cwiseMax(p);
    }
    EXPECT_NEAR(low.x(), 30.0, 1.0);
    EXPECT_NEAR(high.x(), 130.0, 1.0);
    EXPECT_NEAR(high.y(), -30.0, 1.0);
    EXPECT_NEAR(low.y(), -110.0, 1.0);
    const CleanPolygon clean = cleanStroke(sketch.points);
    expectSimpleCounterClockwise(clean.points);
    expectUniformSpacing(clean, 1.6);
}

}  // namespace
}  // namespace rigmesh
