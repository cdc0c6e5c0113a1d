// A closed surface split by a cut surface (a plane, or the strip a curved
// stroke sweeps) into its connected pieces, each open where it was cut
// (paper 3.1, Fig. 7 left). CGAL's Polygon_mesh_processing::split; every
// vertex says where it came from.
#pragma once

#include <string>
#include <vector>

#include "cut/CutSurface.h"
#include "mesh/TriMesh.h"
#include "part/VertexSource.h"

namespace rigmesh {

struct MeshPiece {
    TriMesh mesh;           // open along the cut
    VertexSources sources;  // into the input mesh (mesh 0)
    // The holes the cut left, each a loop of vertex indices in the order of
    // the mesh's border (a patch filling it runs the same way).
    std::vector<std::vector<int>> holes;
    // +1: on the cut surface's positive side, -1: the other, as the
    // vertices beside its holes lie.
    int side = 0;
};

// Band: CGAL is given only the faces near the cut surface (cut/CutBand.h)
// and the rest is stitched back, the same pieces bit for bit; when the band
// does not hold, the whole surface is split. Whole: the whole surface is
// always split (what the band is compared with in the tests).
enum class SplitMethod { Band, Whole };

// How a split went: whether the band was used, its size, and why not.
struct SplitReport {
    bool band = false;
    int bandFaces = 0;
    int faces = 0;         // of the input
    std::string fallback;  // why the whole surface was split ("" if it was not)
};

// Throws Error when the input is not a closed manifold surface.
std::vector<MeshPiece> splitBySurface(const TriMesh& mesh, const CutSurface& surface,
                                      SplitMethod method = SplitMethod::Band,
                                      SplitReport* report = nullptr);

}  // namespace rigmesh
