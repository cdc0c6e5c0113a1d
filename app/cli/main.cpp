// rigmesh: the command-line face of RigMesh Studio. It links the engine and
// the document model only, and runs what the studio runs, headless.
#include <cstdio>
#include <string>
#include <vector>

#include "BuildCommand.h"
#include "CommandFailure.h"
#include "ExportCommand.h"
#include "ImportCommand.h"
#include "RigCommand.h"
#include "RunCommand.h"
#include "base/AllocatorTuning.h"
#include "model/ModelInfo.h"

namespace {

const char* kUsage = R"(usage: rigmesh COMMAND [ARGS]

commands:
  build SKETCH [-o OUT.glb|.gltf|.fbx|.dae|.obj|.ply|.off] [--max-influences N]
               [--no-leaf-bones] [--subdivide N] [--decimate FACES]
               [--pose-demo] [--rig FILE.json] [--stats FILE.json]
               [--debug-svg FILE.svg] [--edge-length L] [--no-smoothing] [--plain-dp]
      Turns a sketched silhouette (.json or .svg) into a rigged part: a closed
      surface, a skeleton and skin weights, and prints its figures. SKETCH may
      be "example" for the embedded example. .glb, .gltf, .fbx and .dae carry
      the skeleton (one node per bone) and skin weights, .obj the rest mesh; a
      .ply is coloured by each vertex's dominant bone. --max-influences N keeps
      at most N weights per vertex (default 4; 0 = all the format allows;
      glTF keeps at most 4). Each bone node's +Y axis runs along its bone, as
      Blender expects. Each leaf bone gets an end bone `<bone>_end` at its
      tail (like Blender's FBX "Add Leaf Bones", on by default there too), so
      that every importer also knows the leaves' lengths (Blender's glTF and
      FBX importers otherwise give a leaf its parent's length); it points back
      along its leaf, so that Blender shows it inside the limb.
      --no-leaf-bones leaves them out (--leaf-bones, the default, is
      accepted). --subdivide N (0-4) refines the written
      surface by N rounds of Loop subdivision, --decimate FACES coarsens it
      to at most FACES triangles (quadric error, every kept vertex an
      original one); skin weights are carried, the rig is unchanged, and
      the --rig file describes the written surface. --pose-demo adds a 3-key animation: rest at 0 s,
      an IK bend of the end joint at 0.5 s, rest at 1 s. --rig writes joints,
      bones and weights as JSON; --plain-dp uses plain Douglas-Peucker
      instead of the paper's CDP.
  run RECIPE.json [-o OUT.rigmesh|.glb|.gltf|.fbx|.dae|.obj] [--stats FILE.json]
               [--compare-global] [--no-leaf-bones] [--dual-quaternion]
      Replays a recipe (a JSON list of the studio's commands: sketch, merge,
      pose, key, ...; see resources/recipes/camel.json) on a new document,
      prints one line per step and writes the document: .rigmesh natively,
      the other formats as for build: one skinned mesh per part, each with
      its clip, with end bones unless --no-leaf-bones, linear blend skinning
      unless --dual-quaternion. A bad step stops with "step N (command): reason". --stats
      writes each step's time and, for each merge, the vertices and bones of
      the part and of the local re-skin and its times; --compare-global also
      solves the global re-skin and reports its time and the 90th percentile
      of the per-vertex L1 difference (paper Table 1).
  import FILE -o PARTS.rigmesh
      Reads a mesh or rigged scene (.glb, .gltf, .fbx, .dae, .obj, .ply, ...)
      and writes its parts as a document. The studio and `run` read imports
      through this command in a separate process with time and memory
      limits, so a broken file cannot take them down.
  rig MESH -o OUT.rigmesh|.glb|.gltf|.fbx|.dae [--max-influences N] [--no-leaf-bones]
               [--separately] [--debug-proxy PROXY.obj]
      Reads a mesh (.obj, .ply, .off, .stl, .glb, .fbx, ... as import does)
      and rigs its parts without a skeleton as one figure (--separately:
      each part alone): a skeleton from the shape (mean curvature flow,
      bones by the same Cylindrical Douglas-Peucker rule as sketches, the
      root in the thickest part) and bone heat skin weights. A mesh that is
      not one closed piece (pieces, holes, crossing faces) is rigged on a
      closed proxy wrapped around it; the mesh itself is kept as it is and
      small floating pieces (eyes, teeth) follow one bone. --debug-proxy
      writes the surface the rig was computed on. What the rig worked
      around is listed. Writes the document or an export as for run.
  export DOC.rigmesh -o OUT.glb|.gltf|.fbx|.dae|.obj [--max-influences N]
               [--current-pose | --pose-as-key] [--no-animation] [--hidden] [--no-leaf-bones]
               [--subdivide N] [--decimate FACES] [--linear-blend | --dual-quaternion]
      Converts a saved document as the studio's File > Export does: every
      visible part (--hidden: every part) at its placement, each its own
      skinned mesh named after it, animated by its own clip
      (--no-animation: none); an .obj
      is the rest mesh, or each part's current pose with --current-pose
      (rigged formats: as their rest shape); --pose-as-key keeps the rest
      shape and writes each part's current pose as a one-key animation.
      Poses are baked with linear blend skinning (--linear-blend, the
      default), as glTF viewers and Blender deform (its Armature's Preserve
      Volume off), or with --dual-quaternion, which an .fbx's skin also
      records (SkinningType, which Maya reads).
      --max-influences, --no-leaf-bones, --subdivide and --decimate as for build. A bad document exits 1 with the reason.
  example
      Builds the embedded example sketch into a rigged part and prints its figures.
  version
      Prints the version (so does rigmesh --version).
)";

// The usage of one command: its block of kUsage (from its line "  NAME ..."
// to the next command's line), or empty for an unknown command.
std::string commandUsage(const std::string& command) {
    const std::string text = kUsage;
    std::string block;
    bool inside = false;
    for (std::size_t begin = 0; begin < text.size();) {
        std::size_t end = text.find('\n', begin);
        if (end == std::string::npos)
            end = text.size();
        const std::string line = text.substr(begin, end - begin);
        const bool commandLine =
            line.size() > 2 && line[0] == ' ' && line[1] == ' ' && line[2] != ' ';
        if (commandLine)
            inside = line.compare(2, command.size() + 1, command + " ") == 0 ||
                     line.substr(2) == command;
        if (inside)
            block += line + "\n";
        begin = end + 1;
    }
    return block.empty() ? block : "usage: rigmesh" + block.substr(1);
}

}  // namespace

int main(int argc, char** argv) {
    rigmesh::tuneAllocatorForEditing();
    std::vector<std::string> arguments(argv + 1, argv + argc);
    if (arguments.empty() || arguments[0] == "--help" || arguments[0] == "-h" ||
        arguments[0] == "help") {
        std::fputs(kUsage, arguments.empty() ? stderr : stdout);
        return arguments.empty() ? rigmesh::cli::kExitUsage : rigmesh::cli::kExitSuccess;
    }
    const std::string command = arguments[0];
    arguments.erase(arguments.begin());
    // `rigmesh COMMAND --help`: that command's usage.
    for (const std::string& argument : arguments) {
        if (argument != "--help" && argument != "-h")
            continue;
        const std::string usage = commandUsage(command);
        if (usage.empty())
            break;  // an unknown command: reported below
        std::fputs(usage.c_str(), stdout);
        return 0;
    }
    try {
        if (command == "build")
            return rigmesh::cli::runBuild(arguments);
        if (command == "run")
            return rigmesh::cli::runRecipe(arguments);
        if (command == "import")
            return rigmesh::cli::runImport(arguments);
        if (command == "rig")
            return rigmesh::cli::runRig(arguments);
        if (command == "export")
            return rigmesh::cli::runExport(arguments);
        if (command == "example")
            return rigmesh::cli::runBuild({"example"});
        if (command == "version" || command == "--version") {
            std::printf("%s\n", rigmesh::model::buildInfo().toStdString().c_str());
            return 0;
        }
        std::fprintf(stderr, "rigmesh: unknown command '%s' (see rigmesh --help)\n",
                     command.c_str());
        return rigmesh::cli::kExitUsage;
    } catch (...) {
        return rigmesh::cli::reportFailure(std::current_exception());
    }
}
