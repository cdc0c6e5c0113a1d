// What a valid result is, for the fuzz targets: a part whose numbers are all
// finite, whose mesh is a closed manifold with faces on real vertices, whose
// skeleton is a tree and whose weights partition unity; a document whose
// parts pose to finite meshes and which saves and loads to the same bytes.
#pragma once

#include <string>

#include "model/Document.h"
#include "part/Part.h"

namespace rigmesh::fuzz {

// Whether meshes must be closed manifolds: built from sketches they are;
// loaded from a document they may be anything imported.
enum class Topology { ClosedManifold, Any };

// "" when valid, else the first problem.
std::string partProblem(const Part& part, Topology topology);
std::string documentProblem(const model::Document& document, Topology topology);

}  // namespace rigmesh::fuzz
