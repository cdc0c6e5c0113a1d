// Exporting a rigged part: the biped at 10k, 30k and 110k
// vertices written as .glb and .fbx. Assimp's own JoinIdenticalVertices made
// this about n^1.8; with our linear join the time should grow linearly.
// And a smooth clip of the biped's 10 bones with 5,000 to 20,000 keys: the
// time grows linearly in the keys (io/GltfAnimations.h: Assimp's glTF
// writer copied its whole buffer for every accessor).
#include <benchmark/benchmark.h>

#include <Eigen/Geometry>

#include <cmath>
#include <filesystem>
#include <memory>
#include <string>
#include <vector>

#include "BenchmarkSupport.h"
#include "io/SceneExport.h"
#include "pipeline/SketchToPart.h"
#include "pose/Clip.h"

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

// A smooth clip of every bone of `part` turning, with `keys` keys 0.1 s
// apart (2.4 frames at 24 fps: the export bakes the frames between them).
Clip smoothClip(const Part& part, int keys) {
    Clip clip(24.0);
    clip.interpolation = Interpolation::Smooth;
    for (int k = 0; k < keys; ++k) {
        Pose pose;
        for (const Bone& bone : part.skeleton.bones())
            pose.setRotation(bone.tail, Eigen::Quaterniond(Eigen::AngleAxisd(
                                            0.3 * std::sin(0.1 * k + bone.id), Vec3::UnitZ())));
        clip.setKey(0.1 * k, pose);
    }
    return clip;
}

void benchSmoothClip(benchmark::State& state, const std::string& extension) {
    static const Part biped =
        sketchToPart(readSketchFile(sharedSketchPath("biped")).points, "biped").part;
    const Clip clip = smoothClip(biped, static_cast<int>(state.range(0)));
    ExportPart item;
    item.part = &biped;
    item.clip = &clip;
    const std::filesystem::path folder =
        std::filesystem::temp_directory_path() / "rigmesh_bench_export_clip";
    std::filesystem::create_directories(folder);
    const std::string path = (folder / ("biped." + extension)).string();
    for (auto _ : state)
        exportScene({item}, nullptr, path);
    std::filesystem::remove_all(folder);
    state.counters["keys"] = static_cast<double>(clip.keyCount());
    state.counters["bones"] = biped.skeleton.boneCount();
}

void registerBenchmarks() {
    for (const std::string extension : {"glb", "fbx"})
        benchmark::RegisterBenchmark(("ExportSmoothClip/" + extension).c_str(), benchSmoothClip,
                                     extension)
            ->Arg(5000)
            ->Arg(10000)
            ->Arg(20000)
            ->Unit(benchmark::kMillisecond)
            ->UseRealTime();
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
