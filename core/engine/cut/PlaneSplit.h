// A closed surface split by a plane into its connected pieces, each open
// where the plane cut it (paper 3.1, Fig. 7 left). CGAL's
// Polygon_mesh_processing::split; every vertex says where it came from.
#pragma once

#include <vector>

#include "mesh/TriMesh.h"
#include "part/VertexSource.h"

namespace rigmesh {

struct MeshPiece {
    TriMesh mesh;           // open along the cut
    VertexSources sources;  // into the input mesh (mesh 0)
    // The holes the cut left, each a loop of vertex indices in the order of
    // the mesh's border (a patch filling it runs the same way).
    std::vector<std::vector<int>> holes;
    int side = 0;  // +1: on the side the normal points to, -1: the other
};

// Throws Error when the input is not a closed manifold surface.
std::vector<MeshPiece> splitByPlane(const TriMesh& mesh, const Vec3& point, const Vec3& normal);

}  // namespace rigmesh
