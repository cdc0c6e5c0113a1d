// The band split (cut/CutBand.h) against CGAL's split of the whole surface:
// on every shared sketch, cut by planes at several places and tilts and by
// bent strokes, the pieces are the same bit for bit (positions, faces,
// sources, holes, sides), and the band holds (no fallback to the whole
// split) wherever it is smaller than the part: it falls back only when it
// would be most of a small sketch or the cut misses.
#include <gtest/gtest.h>

#include <Eigen/Geometry>
#include <cmath>

#include "SharedSketchPart.h"
#include "SplitComparison.h"
#include "cut/SurfaceSplit.h"

namespace rigmesh {
namespace {

TEST(SplitBand, GivesTheWholeSplitsPiecesOnEverySharedSketch) {
    int cuts = 0, banded = 0;
    for (const std::string& sketch : testsupport::sharedSketchNames(false)) {
        const testsupport::BandTally tally = testsupport::expectBandGivesTheWholeSplitAcross(
            testsupport::sharedSketchPart(sketch).mesh, sketch);
        cuts += tally.cuts;
        banded += tally.banded;
    }
    EXPECT_GT(cuts, 500);
    EXPECT_GT(banded, cuts * 2 / 3);
    std::printf("band used on %d of %d cuts\n", banded, cuts);
}

}  // namespace
}  // namespace rigmesh
