// `rigmesh rig MESH -o OUT`: reads a mesh (as `import` does, in a child
// process), rigs every part that has no skeleton (the studio's Rig command,
// model/commands/RigPartCommand) and writes the document or an export.
#pragma once

#include <string>
#include <vector>

namespace rigmesh::cli {

// Returns the exit code; throws rigmesh::Error with a one-line reason.
int runRig(const std::vector<std::string>& arguments);

}  // namespace rigmesh::cli
