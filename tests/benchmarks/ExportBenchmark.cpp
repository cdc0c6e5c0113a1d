// Exporting a rigged part: the biped at 10k, 30k and 110k
// vertices written as .glb and .fbx. Assimp's own JoinIdenticalVertices made
// this about n^1.8; with our linear join the time should grow linearly.
#include <benchmark/benchmark.h>

#include <filesystem>
#include <memory>
#include <string>
#include <vector>

#include "BenchmarkSupport.h"
#include "io/SceneExport.h"
#include "pipeline/SketchToPart.h"

namespace rigmesh::bench {
namespace {

struct ExportCase {
    int targetVertices = 0;
    std::unique_ptr<Part> part;  // built on first use
};

const Part& partOf(ExportCase& c) {
    if (!c.part) {
        const std::vector<Vec2> stroke = readSketchFile(sharedSketchPath("biped")).points;
        SketchToPartOptions options;
        options.surface = optionsForVertexCount(stroke, c.targetVertices);
        c.part = std::make_unique<Part>(sketchToPart(stroke, "biped", options).part);
    }
    return *c.part;
}

void benchExport(benchmark::State& state, ExportCase* c, const std::string& extension) {
    ExportPart item;
    item.part = &partOf(*c);
    const std::filesystem::path folder =
        std::filesystem::temp_directory_path() / "rigmesh_bench_export";
    std::filesystem::create_directories(folder);
    const std::string path = (folder / ("biped." + extension)).string();
    for (auto _ : state)
        exportScene({item}, nullptr, path);
    std::filesystem::remove_all(folder);
    state.counters["vertices"] = item.part->mesh.vertexCount();
}

void registerBenchmarks() {
    static std::vector<std::unique_ptr<ExportCase>> cases;
    for (const int count : {10000, 30000, 110000}) {
        cases.push_back(std::make_unique<ExportCase>());
        cases.back()->targetVertices = count;
        for (const std::string extension : {"glb", "fbx"})
            benchmark::RegisterBenchmark(
                ("Export/" + extension + "/biped/" + vertexCountLabel(count)).c_str(), benchExport,
                cases.back().get(), extension)
                ->Unit(benchmark::kMillisecond)
                ->UseRealTime();
    }
}

}  // namespace
}  // namespace rigmesh::bench

int main(int argc, char** argv) {
    return rigmesh::bench::runBenchmarks(argc, argv, rigmesh::bench::registerBenchmarks);
}
