// The band split (cut/CutBand.h) on the camel at the shipped recipe's last
// step (what bench_merge cuts): the benchmark's three cuts and planes and
// bent strokes at many places give the whole split's pieces bit for bit, and
// the band holds (no fallback) on the benchmark's cuts.
#include <gtest/gtest.h>

#include "CamelLastMerge.h"
#include "SplitComparison.h"
#include "cut/SurfaceSplit.h"

namespace rigmesh {
namespace {

TEST(CutBandOnTheCamel, TheBenchmarksCutsUseTheBandAndGiveTheWholeSplitsPieces) {
    const Part& camel = testsupport::finishedCamel();
    std::vector<testsupport::NamedCut> cuts;
    // bench_merge's Edit/camel/cut_smooth and cut_sharp (the same split) and
    // cut_curved_smooth.
    cuts.push_back({"bench plane", CutSurface::plane(Vec3(0.2, 0.0, 0.0), Vec3(1.0, 0.1, 0.0))});
    std::vector<Vec3> stroke;
    for (int i = 0; i <= 8; ++i) {
        const double y = -2.0 + 0.5 * i;
        stroke.push_back(Vec3(0.2 + 0.4 * (1.0 - std::abs(y) / 2.0), y, 0.0));
    }
    cuts.push_back({"bench stroke", CutSurface::swept(stroke, Vec3::UnitZ())});
    for (const testsupport::NamedCut& cut : cuts) {
        SCOPED_TRACE(cut.name);
        const testsupport::SplitComparison result =
            testsupport::compareSplits(camel.mesh, cut.surface);
        EXPECT_TRUE(result.same) << result.difference;
        EXPECT_TRUE(result.report.band) << result.report.fallback;
        EXPECT_LT(result.report.bandFaces, result.report.faces / 4);
    }
}

TEST(CutBandOnTheCamel, CutsAcrossTheCamelGiveTheWholeSplitsPieces) {
    const testsupport::BandTally tally =
        testsupport::expectBandGivesTheWholeSplitAcross(testsupport::finishedCamel().mesh, "camel");
    const int cuts = tally.cuts, banded = tally.banded;
    EXPECT_GT(banded, cuts * 3 / 4);
    std::printf("band used on %d of %d cuts of the camel\n", banded, cuts);
}

}  // namespace
}  // namespace rigmesh
