// `rigmesh import FILE -o PARTS.rigmesh`: reads a file through Assimp
// (glTF, FBX, COLLADA, OBJ, PLY, ...) and writes its parts as a document.
// The studio and `rigmesh run` read imports only through this command, in a
// child process with time and memory limits (model/ImportReader.h), because
// Assimp can crash or loop on broken files.
#pragma once

#include <string>
#include <vector>

namespace rigmesh::cli {

// Returns the exit code; throws rigmesh::Error with a one-line reason.
int runImport(const std::vector<std::string>& arguments);

}  // namespace rigmesh::cli
