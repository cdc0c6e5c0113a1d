// Each vertex's partner across a mirror plane, as Blender's X-mirror finds
// it for weight painting (the vertex nearest the vertex's reflection,
// within a tolerance): a dab's change at a vertex is copied to its partner
// on the bone's mirror image, so the two sides stay equal vertex by vertex
// even where the surface is not exactly symmetric. Partners are mutual (each
// the other's nearest), so the pairing is an involution; a vertex on the
// plane is its own partner.
#pragma once

#include <vector>

#include "mesh/TriMesh.h"
#include "rig/MirrorSymmetry.h"

namespace rigmesh {

inline constexpr int kNoMirrorVertex = -1;

// The distance within which a vertex's reflection must find its partner:
// half the mean edge length (a reflection farther than that from every
// vertex lands between vertices, where no one vertex is its image).
double vertexMirrorTolerance(const TriMesh& mesh);

// Each vertex's partner: the vertex nearest its reflection through `plane`
// when that one is within `tolerance` of it and the vertex is in turn the
// nearest to the partner's reflection; itself on the plane; kNoMirrorVertex
// otherwise.
std::vector<int> mirrorVertices(const TriMesh& mesh, const MirrorPlane& plane, double tolerance);

}  // namespace rigmesh
