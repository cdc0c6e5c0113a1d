// The chordal axis and its pruning (paper 2.1): junction and branch counts on
// tubes, Y shapes and stars, pruning of bumps, and chord orientation.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <string>
#include <utility>

#include "AxisTestSupport.h"
#include "SketchToSurfaceTestSupport.h"

namespace rigmesh {
namespace {

using axistest::axisOfStroke;
using axistest::countLimbBranches;
using axistest::countLive;

constexpr double kFineSpacing = 0.05;  // outline spacing of the synthetic shapes
constexpr double kLimbEndReach = 2.0;  // in half-widths: how near a limb's terminal is to its end

TEST(ChordalAxis, LongThinTubeHasOneBranchBetweenTwoTerminals) {
    const ChordalAxis axis = axisOfStroke(testsupport::stadium(10.0, 0.5, 0.02), kFineSpacing);
    EXPECT_EQ(countLive(axis, TriangleKind::Junction), 0);
    ASSERT_EQ(axis.branches.size(), 1u);
    const AxisBranch& branch = axis.branches.front();
    EXPECT_EQ(axis.kind[branch.startNode], TriangleKind::Terminal);
    EXPECT_EQ(axis.kind[branch.endNode], TriangleKind::Terminal);
    EXPECT_EQ(branch.chords.size(), branch.sleeves.size() + 1);
}

TEST(ChordalAxis, TubeSketchHasOneBranchBetweenTwoTerminals) {
    const ChordalAxis axis = axisOfStroke(testsupport::sharedSketchPoints("tube"));
    EXPECT_EQ(countLive(axis, TriangleKind::Junction), 0);
    ASSERT_EQ(axis.branches.size(), 1u);
    EXPECT_EQ(axis.kind[axis.branches.front().startNode], TriangleKind::Terminal);
    EXPECT_EQ(axis.kind[axis.branches.front().endNode], TriangleKind::Terminal);
}

TEST(ChordalAxis, SyntheticYHasOneJunctionAndThreeLimbs) {
    const ChordalAxis axis = axisOfStroke(testsupport::armedStar(3, 0.5, 2.0), kFineSpacing);
    EXPECT_EQ(countLive(axis, TriangleKind::Junction), 1);
    EXPECT_EQ(axis.branches.size(), 3u);
    EXPECT_EQ(countLimbBranches(axis), 3);
}

TEST(ChordalAxis, YBranchSketchHasOneJunctionAndThreeLimbs) {
    const ChordalAxis axis = axisOfStroke(testsupport::sharedSketchPoints("y_branch"));
    EXPECT_EQ(countLive(axis, TriangleKind::Junction), 1);
    EXPECT_EQ(axis.branches.size(), 3u);
    EXPECT_EQ(countLimbBranches(axis), 3);
}

TEST(ChordalAxis, SmallBumpIsPrunedWhileLimbsSurvive) {
    const auto shape = axistest::tubeWithBumpAndLimb(0.01);
    const ChordalAxis axis = axisOfStroke(shape.outline, kFineSpacing);

    const int apex = axistest::nearestPolygonVertex(axis, shape.bumpApex);
    ASSERT_LT((axis.cdt.points[apex] - shape.bumpApex).norm(), 2 * kFineSpacing);
    for (int t : axistest::trianglesAround(axis, apex))
        EXPECT_TRUE(axis.pruned[t]) << "bump triangle " << t << " survived pruning";

    // Each real limb keeps a terminal branch reaching its rounded end: the
    // semicircular end itself lies within its base chord's circle and is
    // pruned, so the terminal sits about one half-width inside the end point,
    // while a lost limb would end at the junction, 3 to 4 units away.
    for (const auto& [end, halfWidth] :
         {std::pair{shape.limbTip, shape.limbHalfWidth}, std::pair{shape.leftEnd, shape.tubeRadius},
          std::pair{shape.rightEnd, shape.tubeRadius}}) {
        double nearest = INFINITY;
        for (const AxisBranch& branch : axis.branches)
            for (int node : {branch.startNode, branch.endNode})
                if (axis.kind[node] == TriangleKind::Terminal)
                    nearest = std::min(nearest, (axis.centroid(node) - end).norm());
        EXPECT_LT(nearest, kLimbEndReach * halfWidth)
            << "no terminal near (" << end.x() << ", " << end.y() << ")";
    }
    // The tube's two halves and the limb meet in one junction.
    EXPECT_EQ(countLive(axis, TriangleKind::Junction), 1);
    EXPECT_EQ(countLimbBranches(axis), 3);
    EXPECT_GT(std::count(axis.kindBeforePruning.begin(), axis.kindBeforePruning.end(),
                         TriangleKind::Junction),
              1)
        << "the bump should have made a junction before pruning";
}

TEST(ChordalAxis, SyntheticStarKeepsFiveLimbs) {
    const ChordalAxis axis = axisOfStroke(testsupport::armedStar(5, 0.8, 2.0), kFineSpacing);
    EXPECT_EQ(countLimbBranches(axis), 5);
}

TEST(ChordalAxis, StarSketchKeepsFiveLimbsAroundTheBody) {
    const ChordalAxis axis = axisOfStroke(testsupport::sharedSketchPoints("star"));
    EXPECT_EQ(countLimbBranches(axis), 5);
    // Five limbs on a tree of junction triangles need at least three junctions.
    EXPECT_GE(countLive(axis, TriangleKind::Junction), 3);
}

TEST(ChordalAxis, BranchesRunThroughLiveSleevesBetweenLiveNodes) {
    const ChordalAxis axis = axisOfStroke(testsupport::sharedSketchPoints("biped"));
    for (const AxisBranch& branch : axis.branches) {
        EXPECT_FALSE(axis.pruned[branch.startNode]);
        EXPECT_FALSE(axis.pruned[branch.endNode]);
        for (int sleeve : branch.sleeves) {
            EXPECT_FALSE(axis.pruned[sleeve]);
            EXPECT_EQ(axis.kind[sleeve], TriangleKind::Sleeve);
        }
    }
}

}  // namespace
}  // namespace rigmesh
