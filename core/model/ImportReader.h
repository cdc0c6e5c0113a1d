// Reading files to import. Assimp 5.2.5 crashes, asserts,
// loops or allocates gigabytes on some broken COLLADA, FBX and PLY files, so
// the studio and the recipe runner never parse an import themselves: a child
// process (`rigmesh import FILE -o /dev/fd/3`) reads it under a time and
// an address-space limit and writes the parts as a document into a
// temporary file without a name (base/ChildProcess: nothing is left on disk
// and the child dies with its parent, however that ends); this side reads
// that document with the usual checks, plus Part::validate() on every part.
// A crash, a timeout, the memory limit or a bad result becomes an Error with
// a message for the user, and the caller's document is left unchanged.
#pragma once

#include <QString>
#include <cstdint>
#include <vector>

#include "io/SceneImport.h"
#include "model/PartNode.h"

namespace rigmesh::model {

struct ImportLimits {
    double seconds = 0.0;                 // the child is killed after this
    std::uint64_t addressSpaceBytes = 0;  // its address space (0 = no limit)
};

// The default limits for a file of `fileBytes`: a few seconds for a small
// file, growing with its size (5 s plus 5 s per MiB, at most 600 s; several
// times what reading real scenes takes, see ImportReader.cpp; eight times
// that in sanitizer builds, which run that much slower), and 2 GiB plus 64
// times the file size of address space, at most 8 GiB: a broken file is
// refused in seconds, and a runaway reader cannot freeze or swap the machine.
ImportLimits importLimitsFor(std::uint64_t fileBytes);

// The parts of an imported scene as document nodes without ids (in-process;
// what the child runs): name from the file when the mesh has none, rest
// pose, and the file's clip on the part it animates.
std::vector<PartNode> partNodesFromScene(ImportedScene scene, const QString& path);

// Reads `path` in a child process and returns its parts as nodes without
// ids. Throws rigmesh::Error with the reason.
std::vector<PartNode> readImportedParts(const QString& path);
std::vector<PartNode> readImportedParts(const QString& path, const ImportLimits& limits);

// The program that reads imports: RIGMESH_IMPORT_WORKER if set, else the
// `rigmesh` beside the running executable, else `rigmesh` on the PATH.
// Empty if none is found.
QString importWorkerProgram();
// Overrides the above (tests; empty restores the default search).
void setImportWorkerProgram(const QString& program);

}  // namespace rigmesh::model
