// `rigmesh rig MESH -o OUT [--separately] [--debug-proxy PROXY.obj]`: reads
// a mesh (as `import` does, in a child process), rigs its parts that have
// no skeleton as one figure (the studio's Rig command,
// model/commands/RigPartCommand; --separately: each part alone) and writes
// the document or an export. --debug-proxy writes the surface the skeleton
// and weights were computed on (the wrapped proxy, or the mesh itself when
// it needed none), for a developer to look at.
#pragma once

#include <string>
#include <vector>

namespace rigmesh::cli {

// Returns the exit code; throws rigmesh::Error with a one-line reason.
int runRig(const std::vector<std::string>& arguments);

}  // namespace rigmesh::cli
