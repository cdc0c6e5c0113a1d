// Decomposition into cylindrical and connecting regions (paper 2.1, Fig. 2):
// region counts on the shared sketches and consistent bookkeeping between
// cylinders, caps and ports.
#include <gtest/gtest.h>

#include <string>

#include "AxisTestSupport.h"
#include "SketchToSurfaceTestSupport.h"
#include "axis/Decomposition.h"

namespace rigmesh {
namespace {

Decomposition decompositionOf(const std::string& sketch) {
    return decompose(axistest::axisOfStroke(testsupport::sharedSketchPoints(sketch)));
}

int countCapped(const Decomposition& d) {
    int count = 0;
    for (const CylinderRegion& c : d.cylinders)
        count += (c.startConnecting < 0 ? 1 : 0) + (c.endConnecting < 0 ? 1 : 0);
    return count;
}

TEST(Decomposition, YBranchIsThreeCylindersAroundOneConnectingRegion) {
    const Decomposition d = decompositionOf("y_branch");
    EXPECT_EQ(d.cylinders.size(), 3u);
    ASSERT_EQ(d.connecting.size(), 1u);
    EXPECT_EQ(d.connecting.front().ports.size(), 3u);
    EXPECT_EQ(countCapped(d), 3);
}

TEST(Decomposition, StarIsFiveCylindersAroundOneConnectingRegion) {
    const Decomposition d = decompositionOf("star");
    EXPECT_EQ(d.cylinders.size(), 5u);
    ASSERT_EQ(d.connecting.size(), 1u);
    EXPECT_EQ(d.connecting.front().ports.size(), 5u);
    EXPECT_EQ(countCapped(d), 5);
}

// biped.json (head, torso, two arms, two legs) decomposes, as of this
// writing, into 6 cylinders (head, two arms, two legs, and the torso between
// the two connecting regions) around 2 connecting regions (shoulders, hips);
// the test asks only for a sane count.
TEST(Decomposition, BipedHasLimbCylindersAroundConnectingRegions) {
    const Decomposition d = decompositionOf("biped");
    EXPECT_GE(d.cylinders.size(), 5u);
    EXPECT_GE(d.connecting.size(), 1u);
    EXPECT_LE(d.connecting.size(), 3u);
    // Head, two arms and two legs end in caps.
    EXPECT_EQ(countCapped(d), 5);
}

// A pruned bump off the middle of a body is a connecting region
// between the body's two halves, holding the bump's outline, so the surface
// follows it; the skeleton stays one chain (two caps, no other leaf).
TEST(Decomposition, APrunedBumpOffTheBodyBecomesAConnectingRegionWithItsOutline) {
    const Decomposition d = decompose(axistest::axisOfStroke(testsupport::blobWithBump()));
    ASSERT_EQ(d.connecting.size(), 1u);
    EXPECT_EQ(d.connecting.front().ports.size(), 2u);
    EXPECT_EQ(d.cylinders.size(), 2u);
    EXPECT_EQ(countCapped(d), 2);
    // Every outline vertex on the bump (above the ellipse's top, y = 1) is a
    // corner of one of the region's triangles.
    std::vector<bool> inRegion(d.axis.cdt.points.size(), false);
    for (int t : d.connecting.front().triangles)
        for (int v : d.axis.cdt.triangles[t])
            inRegion[v] = true;
    int bumpVertices = 0;
    for (std::size_t v = 0; v < d.axis.cdt.points.size(); ++v)
        if (d.axis.cdt.points[v].y() > 1.1) {
            ++bumpVertices;
            EXPECT_TRUE(inRegion[v]) << "bump outline vertex " << v << " is in no region";
        }
    EXPECT_GT(bumpVertices, 5);
}

// Pruned ears along a body lower than the outline's own spacing are no bumps:
// the shared tubes stay one cylinder (SingleTube), and so does a plain ellipse.
TEST(Decomposition, AnEllipseWithoutBumpIsOneCylinder) {
    const Decomposition d = decompose(axistest::axisOfStroke(testsupport::polarOutline(
        240, [](double t) { return 1.0 / std::hypot(std::cos(t) / 1.6, std::sin(t)); })));
    EXPECT_EQ(d.cylinders.size(), 1u);
    EXPECT_TRUE(d.connecting.empty());
}

class SingleTube : public ::testing::TestWithParam<std::string> {};

TEST_P(SingleTube, IsOneCylinderWithTwoCaps) {
    const Decomposition d = decompositionOf(GetParam());
    ASSERT_EQ(d.cylinders.size(), 1u);
    EXPECT_TRUE(d.connecting.empty());
    const CylinderRegion& c = d.cylinders.front();
    EXPECT_EQ(c.startConnecting, -1);
    EXPECT_EQ(c.endConnecting, -1);
    EXPECT_FALSE(c.startCap.empty());
    EXPECT_FALSE(c.endCap.empty());
}

INSTANTIATE_TEST_SUITE_P(TubeSketches, SingleTube, ::testing::Values("tube", "banana", "kinked"),
                         testsupport::sketchTestName);

class DecompositionBookkeeping : public ::testing::TestWithParam<std::string> {};

TEST_P(DecompositionBookkeeping, PortsAndCylinderEndsAgree) {
    const Decomposition d = decompositionOf(GetParam());
    const int cylinders = static_cast<int>(d.cylinders.size());
    const int regions = static_cast<int>(d.connecting.size());
    int ports = 0;
    for (int r = 0; r < regions; ++r) {
        EXPECT_FALSE(d.connecting[r].junctions.empty()) << "region " << r;
        for (const auto& port : d.connecting[r].ports) {
            ASSERT_GE(port.cylinder, 0);
            ASSERT_LT(port.cylinder, cylinders);
            const CylinderRegion& c = d.cylinders[port.cylinder];
            EXPECT_EQ(port.atStart ? c.startConnecting : c.endConnecting, r)
                << "region " << r << " port to cylinder " << port.cylinder;
            ++ports;
        }
    }
    int connectedEnds = 0;
    for (int c = 0; c < cylinders; ++c) {
        const CylinderRegion& cylinder = d.cylinders[c];
        for (int end : {cylinder.startConnecting, cylinder.endConnecting}) {
            EXPECT_GE(end, -1);
            EXPECT_LT(end, regions);
            connectedEnds += end >= 0 ? 1 : 0;
        }
    }
    EXPECT_EQ(ports, connectedEnds);
}

TEST_P(DecompositionBookkeeping, CapsRunBetweenTheEndChordPoints) {
    const Decomposition d = decompositionOf(GetParam());
    for (std::size_t c = 0; c < d.cylinders.size(); ++c) {
        const CylinderRegion& cylinder = d.cylinders[c];
        ASSERT_FALSE(cylinder.chords.empty());
        EXPECT_EQ(cylinder.startCap.empty(), cylinder.startConnecting >= 0) << "cylinder " << c;
        EXPECT_EQ(cylinder.endCap.empty(), cylinder.endConnecting >= 0) << "cylinder " << c;
        if (!cylinder.startCap.empty()) {
            EXPECT_EQ(cylinder.startCap.front(), cylinder.chords.front()[0]);
            EXPECT_EQ(cylinder.startCap.back(), cylinder.chords.front()[1]);
        }
        if (!cylinder.endCap.empty()) {
            EXPECT_EQ(cylinder.endCap.front(), cylinder.chords.back()[1]);
            EXPECT_EQ(cylinder.endCap.back(), cylinder.chords.back()[0]);
        }
    }
}

INSTANTIATE_TEST_SUITE_P(SharedSketches, DecompositionBookkeeping,
                         ::testing::ValuesIn(testsupport::sharedSketchNames(false)),
                         testsupport::sketchTestName);

}  // namespace
}  // namespace rigmesh
