// Per-vertex unit normals of a triangle mesh: the rest normals skinning
// deforms, and the normals bone visibility's cone test reads
// (rig/BoneVisibility).
#pragma once

#include <vector>

#include "mesh/TriMesh.h"

namespace rigmesh {

// Area-weighted average of the incident faces' normals (the sum of their
// unnormalised cross products), normalised; zero for vertices without a
// non-degenerate face.
std::vector<Vec3> vertexNormals(const TriMesh& mesh);

}  // namespace rigmesh
