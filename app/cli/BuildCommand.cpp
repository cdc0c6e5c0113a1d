#include "BuildCommand.h"

#include <cstdio>
#include <fstream>

#include "BuildReport.h"
#include "CommandLine.h"
#include "EmbeddedExamples.h"
#include "base/Error.h"
#include "debug/DebugSvg.h"
#include "mesh/MeshWriter.h"
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

int runBuild(const std::vector<std::string>& arguments) {
    CommandLine line(arguments, {"-o", "--stats", "--debug-svg", "--edge-length"},
                     {"--no-smoothing"});
    if (line.positional().size() != 1)
        throw Error("build needs exactly one sketch file (.json or .svg), or 'example'");
    const Sketch sketch = loadSketch(line.positional()[0]);

    SketchToSurfaceOptions options;
    if (auto length = line.number("--edge-length")) {
        if (*length <= 0)
            throw Error("--edge-length must be positive");
        options.surface.targetEdgeLength = *length;
    }
    options.surface.smooth = !line.flag("--no-smoothing");
    const SketchToSurfaceResult result = sketchToSurface(sketch.points, options);

    const MeshReport report = analyseMesh(result.surface.mesh);
    const nlohmann::json statistics = buildStatistics(sketch.name, result, report);
    if (auto out = line.value("-o"))
        writeMesh(result.surface.mesh, *out);
    if (auto svg = line.value("--debug-svg"))
        writeTextFile(*svg, debugSvg(result));
    if (auto stats = line.value("--stats"))
        writeTextFile(*stats, statistics.dump(2) + "\n");
    std::fputs(buildSummary(statistics).c_str(), stdout);
    return 0;
}

}  // namespace rigmesh::cli
