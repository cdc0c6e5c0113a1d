// `rigmesh export DOC.rigmesh -o OUT.(glb|gltf|fbx|dae|obj) [options]`:
// converts a saved document headless through the studio's own export
// (model/DocumentExport): every visible part at its placement and pose, the
// keyed clip of every part with keys.
#pragma once

#include <string>
#include <vector>

namespace rigmesh::cli {

// Runs the export command; returns the process exit code. Throws
// rigmesh::Error (a bad document: DocumentFileError) with a one-line reason.
int runExport(const std::vector<std::string>& arguments);

}  // namespace rigmesh::cli
