#include "BuildCommand.h"

#include <algorithm>
#include <cctype>
#include <chrono>
#include <cmath>
#include <cstdio>
#include <filesystem>
#include <fstream>
#include <limits>
#include <optional>

#include "BuildReport.h"
#include "CommandLine.h"
#include "DocumentOutput.h"
#include "EmbeddedExamples.h"
#include "base/Error.h"
#include "base/StagedFile.h"
#include "base/Stopwatch.h"
#include "debug/DebugSvg.h"
#include "io/PoseDemoClip.h"
#include "io/RigJson.h"
#include "io/SceneExport.h"
#include "mesh/MeshWriter.h"
#include "part/PartDetail.h"
#include "pipeline/SketchToPart.h"
#include "sketch/Sketch.h"

namespace rigmesh::cli {
namespace {

Sketch loadSketch(const std::string& source) {
    if (source == "example")
        return parseSketchJson(resources::exampleSketchJson(), "example.json");
    return readSketchFile(source);
}

// --rig, --debug-svg and --stats: complete or untouched (base/StagedFile.h).
void writeTextFile(const std::string& path, const std::string& text) {
    writeFileAtomically(path, text);
}

std::string lowerExtension(const std::string& path) {
    std::string extension = std::filesystem::path(path).extension().string();
    std::transform(extension.begin(), extension.end(), extension.begin(),
                   [](unsigned char c) { return static_cast<char>(std::tolower(c)); });
    return extension;
}

// .ply and .off go through the mesh writer; the scene formats through
// exportScene (rigged: skeleton, weights and, with --pose-demo, a clip).
void writeOutput(const Part& part, const std::string& path, const ExportOptions& options,
                 const std::optional<Clip>& clip) {
    const std::string extension = lowerExtension(path);
    if (extension == ".ply" || extension == ".off") {
        MeshWriteOptions write;
        write.vertexColors = dominantBoneColours(part);
        writeMesh(part.mesh, path, write);
        return;
    }
    if (extension != ".glb" && extension != ".gltf" && extension != ".fbx" && extension != ".dae" &&
        extension != ".obj")
        throw Error("cannot write " + path + ": unknown format '" + extension +
                    "'; use .glb, .gltf, .fbx, .dae, .obj, .ply or .off");
    ExportPart item;
    item.part = &part;
    item.pose = restPose(part.skeleton);
    exportScene({item}, clip ? &*clip : nullptr, path, options);
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
    CommandLine line(
        arguments,
        {"-o", "--stats", "--debug-svg", "--edge-length", "--rig", "--max-influences",
         "--subdivide", "--decimate"},
        {"--no-smoothing", "--plain-dp", "--pose-demo", "--leaf-bones", "--no-leaf-bones"});
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
    const ExportOptions exportSettings = exportOptions(line);
    const SketchToPartResult result = sketchToPart(sketch.points, sketch.name, options);
    const Part& part = result.part;

    const auto checksStart = std::chrono::steady_clock::now();
    const MeshReport report = analyseMesh(part.mesh);
    const double checksMilliseconds = millisecondsSince(checksStart);
    const nlohmann::json statistics =
        buildStatistics(sketch.name, result, report, checksMilliseconds);
    // At a detail level, every file (mesh, rig JSON) describes the written
    // surface, not the built one.
    std::optional<Part> detailed;
    ExportOptions writeSettings = exportSettings;
    if (exportSettings.subdivisionLevels > 0 || exportSettings.decimateToFaces > 0) {
        detailed = subdividedPart(part, exportSettings.subdivisionLevels);
        if (exportSettings.decimateToFaces > 0)
            detailed = decimatedPart(*detailed, exportSettings.decimateToFaces);
        writeSettings.subdivisionLevels = writeSettings.decimateToFaces = 0;
    }
    const Part& written = detailed ? *detailed : part;
    if (auto out = line.value("-o")) {
        std::optional<Clip> clip;
        if (line.flag("--pose-demo"))
            clip = poseDemoClip(written);
        writeOutput(written, *out, writeSettings, clip);
    }
    if (auto rig = line.value("--rig")) {
        // The rig names the mesh it indexes: the -o file, in the same vertex order.
        const auto out = line.value("-o");
        writeTextFile(
            *rig, rigToJson(written, out ? std::filesystem::path(*out).filename().string() : ""));
    }
    if (auto svg = line.value("--debug-svg"))
        writeTextFile(*svg, debugSvg(result.surface, {skeletonOverlay(part.skeleton)}));
    if (auto stats = line.value("--stats"))
        writeTextFile(*stats, statistics.dump(2) + "\n");
    for (const Message& warning : part.weights.warnings)
        std::fprintf(stderr, "rigmesh: warning: %s\n", englishText(warning).c_str());
    std::fputs(buildSummary(statistics).c_str(), stdout);
    return 0;
}

}  // namespace rigmesh::cli
