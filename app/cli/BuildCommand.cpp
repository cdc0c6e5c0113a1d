#include "BuildCommand.h"

#include <cstdio>
#include <fstream>

#include "BuildReport.h"
#include "CommandLine.h"
#include "EmbeddedExamples.h"
#include "base/Error.h"
#include "debug/DebugSvg.h"
#include "io/RigJson.h"
#include "mesh/MeshWriter.h"
#include "pipeline/SketchToPart.h"
#include "sketch/Sketch.h"

namespace rigmesh::cli {
namespace {

Sketch loadSketch(const std::string& source) {
    if (source == "example")
        return parseSketchJson(resources::exampleSketchJson(), "example.json");
    return readSketchFile(source);
}

void writeTextFile(const std::string& path, const std::string& text) {
    const std::string temporary = path + ".tmp";
    {
        std::ofstream out(temporary, std::ios::binary);
        if (!out)
            throw Error("cannot write " + path + ": the folder does not exist or is read-only");
        out << text;
        if (!out.flush())
            throw Error("cannot write " + path);
    }
    if (std::rename(temporary.c_str(), path.c_str()) != 0) {
        std::remove(temporary.c_str());
        throw Error("cannot write " + path);
    }
}

}  // namespace

// The skeleton drawn over the sketch: bones as segments, joints as dots.
DebugOverlay skeletonOverlay(const Skeleton& skeleton) {
    DebugOverlay overlay;
    for (const Bone& bone : skeleton.bones())
        overlay.segments.push_back({skeleton.joint(bone.head).position.head<2>(),
                                    skeleton.joint(bone.tail).position.head<2>()});
    for (const Joint& joint : skeleton.joints())
        overlay.points.push_back(joint.position.head<2>());
    return overlay;
}

int runBuild(const std::vector<std::string>& arguments) {
    CommandLine line(arguments, {"-o", "--stats", "--debug-svg", "--edge-length", "--rig"},
                     {"--no-smoothing", "--plain-dp"});
    if (line.positional().size() != 1)
        throw Error("build needs exactly one sketch file (.json or .svg), or 'example'");
    const Sketch sketch = loadSketch(line.positional()[0]);

    SketchToPartOptions options;
    if (auto length = line.number("--edge-length")) {
        if (*length <= 0)
            throw Error("--edge-length must be positive");
        options.surface.surface.targetEdgeLength = *length;
    }
    options.surface.surface.smooth = !line.flag("--no-smoothing");
    options.skeleton.cylindrical = !line.flag("--plain-dp");
    const SketchToPartResult result = sketchToPart(sketch.points, sketch.name, options);
    const Part& part = result.part;

    const MeshReport report = analyseMesh(part.mesh);
    const nlohmann::json statistics = buildStatistics(sketch.name, result, report);
    if (auto out = line.value("-o")) {
        MeshWriteOptions write;
        write.vertexColors = dominantBoneColours(part);
        writeMesh(part.mesh, *out, write);
    }
    if (auto rig = line.value("--rig"))
        writeTextFile(*rig, rigToJson(part));
    if (auto svg = line.value("--debug-svg"))
        writeTextFile(*svg, debugSvg(result.surface, {skeletonOverlay(part.skeleton)}));
    if (auto stats = line.value("--stats"))
        writeTextFile(*stats, statistics.dump(2) + "\n");
    if (!part.weights.warning.empty())
        std::fprintf(stderr, "rigmesh: warning: %s\n", part.weights.warning.c_str());
    std::fputs(buildSummary(statistics).c_str(), stdout);
    return 0;
}

}  // namespace rigmesh::cli
