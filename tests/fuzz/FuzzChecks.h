// What a valid result is, for the fuzz targets: a part whose numbers are all
// finite, whose mesh is a closed manifold with faces on real vertices, whose
// skeleton is a tree and whose weights partition unity; a document whose
// parts pose to finite meshes and which saves and loads to the same bytes.
#pragma once

#include <string>

#include "model/Document.h"
#include "part/Part.h"

namespace rigmesh::fuzz {

// Whether meshes must be closed manifolds: every surface made here is (a
// sketch, merge, cut, auto-rig); one read from another program's file
// (Part::surfaceFromFile) may be anything. documentProblem asks it of each
// part that is not from a file, unless told Any.
enum class Topology { ClosedManifold, Any };

// "" when valid, else the first problem.
std::string partProblem(const Part& part, Topology topology);
std::string documentProblem(const model::Document& document, Topology topology);

// "" when `message` is what a user should read: not empty, one line of at
// most kMaxMessageCharacters (base/MessageText.h), without a library's own
// exception text (nlohmann's "[json.exception...]").
std::string messageProblem(const std::string& message);

}  // namespace rigmesh::fuzz
