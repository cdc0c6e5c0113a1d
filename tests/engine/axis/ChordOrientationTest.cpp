// Branch chords are oriented (left, right) for the direction of travel and
// the branches cover the live triangles: checked on every good shared sketch.
#include <gtest/gtest.h>

#include <string>
#include <vector>

#include "AxisTestSupport.h"
#include "SketchToSurfaceTestSupport.h"

namespace rigmesh {
namespace {

using testsupport::cross2;

class ChordOrientation : public ::testing::TestWithParam<std::string> {};

// The travel direction at chord i: from the previous axis point (the start
// node's centroid or the previous chord's midpoint) to the next one.
TEST_P(ChordOrientation, LeftEndLiesLeftOfTravelDirection) {
    const ChordalAxis axis = axistest::axisOfStroke(testsupport::sharedSketchPoints(GetParam()));
    int checked = 0;
    for (std::size_t b = 0; b < axis.branches.size(); ++b) {
        const AxisBranch& branch = axis.branches[b];
        std::vector<Vec2> path{axis.centroid(branch.startNode)};
        for (const PolygonEdge& chord : branch.chords)
            path.push_back(axis.midpoint(chord));
        path.push_back(axis.centroid(branch.endNode));
        for (std::size_t i = 0; i < branch.chords.size(); ++i) {
            const PolygonEdge& chord = branch.chords[i];
            const Vec2 span = axis.cdt.points[chord[0]] - axis.cdt.points[chord[1]];
            const Vec2 incoming = path[i + 1] - path[i];
            const Vec2 outgoing = path[i + 2] - path[i + 1];
            EXPECT_GT(cross2(incoming, span), 0.0) << "branch " << b << " chord " << i;
            EXPECT_GT(cross2(outgoing, span), 0.0) << "branch " << b << " chord " << i;
            ++checked;
        }
    }
    EXPECT_GT(checked, 0);
}

TEST_P(ChordOrientation, ConsecutiveChordsShareOneEndPointOnTheSameSide) {
    const ChordalAxis axis = axistest::axisOfStroke(testsupport::sharedSketchPoints(GetParam()));
    for (std::size_t b = 0; b < axis.branches.size(); ++b) {
        const auto& chords = axis.branches[b].chords;
        for (std::size_t i = 1; i < chords.size(); ++i) {
            const bool sameLeft = chords[i][0] == chords[i - 1][0];
            const bool sameRight = chords[i][1] == chords[i - 1][1];
            EXPECT_TRUE(sameLeft != sameRight)
                << "branch " << b << " chords " << i - 1 << ", " << i;
        }
    }
}

TEST_P(ChordOrientation, EveryLiveSleeveLiesOnExactlyOneBranch) {
    const ChordalAxis axis = axistest::axisOfStroke(testsupport::sharedSketchPoints(GetParam()));
    std::vector<int> visits(axis.cdt.triangles.size(), 0);
    for (const AxisBranch& branch : axis.branches)
        for (int sleeve : branch.sleeves)
            ++visits[sleeve];
    for (std::size_t t = 0; t < visits.size(); ++t) {
        if (axis.pruned[t])
            EXPECT_EQ(visits[t], 0) << "pruned triangle " << t;
        else if (axis.kind[t] == TriangleKind::Sleeve)
            EXPECT_EQ(visits[t], 1) << "sleeve " << t;
        else
            EXPECT_EQ(visits[t], 0) << "node " << t;
    }
}

INSTANTIATE_TEST_SUITE_P(SharedSketches, ChordOrientation,
                         ::testing::ValuesIn(testsupport::sharedSketchNames(false)),
                         testsupport::sketchTestName);

}  // namespace
}  // namespace rigmesh
