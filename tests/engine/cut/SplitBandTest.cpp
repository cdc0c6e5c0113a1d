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
#include "mesh/MeshPrimitives.h"

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

// A plane through vertices: CGAL's split copies each vertex on the cut into
// a new vertex with the same position (split_along_edges), which is still
// that input vertex; the band's pieces say so as the whole split's do.
TEST(SplitBand, GivesTheWholeSplitsSourcesWhereThePlaneRunsThroughVertices) {
    const TriMesh sphere = makeIcosphere(3, 1.0);
    int cuts = 0, throughVertices = 0;
    for (int v : {5, 17, 40, 101}) {
        for (int axis = 0; axis < 3; ++axis) {
            const Vec3 normal = Vec3::Unit(axis);
            const CutSurface plane = CutSurface::plane(sphere.vertices[v], normal);
            const testsupport::SplitComparison comparison =
                testsupport::compareSplits(sphere, plane);
            EXPECT_TRUE(comparison.same) << "vertex " << v << ", normal " << normal.transpose()
                                         << ": " << comparison.difference;
            ++cuts;
            const std::vector<MeshPiece> pieces = splitBySurface(sphere, plane);
            int onCut = 0;
            for (const MeshPiece& piece : pieces)
                for (std::size_t p = 0; p < piece.sources.size(); ++p)
                    onCut += piece.sources[p].kind == VertexSource::Kind::Vertex &&
                             plane.side(piece.mesh.vertices[p]) == 0.0;
            throughVertices += onCut >= 2;  // the vertex in both pieces at least
        }
    }
    EXPECT_EQ(throughVertices, cuts);
}

}  // namespace
}  // namespace rigmesh
