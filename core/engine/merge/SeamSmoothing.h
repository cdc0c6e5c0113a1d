// Local smoothing around the intersection loop after a merge (paper 3.2.1):
// only vertices whose graph distance to the loop is below k = 0.6 times the
// distance from their nearest loop point to that loop's centroid move; every
// other vertex keeps its position bit for bit.
#pragma once

#include <array>
#include <vector>

#include "mesh/TriMesh.h"

namespace rigmesh {

struct SeamSmoothingOptions {
    double k = 0.6;  // the paper's band factor
};

// The band (paper 3.2.1): vertices within the graph distance above.
std::vector<int> seamBand(const TriMesh& mesh, const std::vector<std::array<int, 2>>& loop,
                          const SeamSmoothingOptions& options = {});

// Moves the band's vertices to minimise the squared uniform Laplacian over
// the band and its one ring (a thin-plate fill, as Least-Squares Meshes in
// 2.2 without anchors), the rest held. Returns the moved vertices.
std::vector<int> smoothSeam(TriMesh& mesh, const std::vector<std::array<int, 2>>& loop,
                            const SeamSmoothingOptions& options = {});

}  // namespace rigmesh
