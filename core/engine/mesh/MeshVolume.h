// The signed volume a closed, oriented mesh encloses, without the rest of
// the mesh checks (mesh/MeshChecks.h): MeshReport::volume, the same sum bit
// for bit.
#pragma once

#include "mesh/TriMesh.h"

namespace rigmesh {

// > 0 for outward orientation. Throws Error if a face index is out of range
// or a coordinate is not finite, as analyseMesh does.
double signedVolume(const TriMesh& mesh);

}  // namespace rigmesh
