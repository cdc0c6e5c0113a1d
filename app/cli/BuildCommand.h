// `rigmesh build SKETCH [-o OUT] [--stats FILE] [--debug-svg FILE] ...`
#pragma once

#include <string>
#include <vector>

namespace rigmesh::cli {

// Runs the build command; returns the process exit code. Throws
// rigmesh::Error with a one-line reason on bad input.
int runBuild(const std::vector<std::string>& arguments);

}  // namespace rigmesh::cli
