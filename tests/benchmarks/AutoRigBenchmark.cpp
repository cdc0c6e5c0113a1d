// Auto-rig of an imported mesh at 5k, 20k and 100k
// vertices: the biped sketch's surface at the matching edge length, taken as
// a bare mesh (no rig), as a file from another tool would be.
//
//  - whole:    autoRigPart (repair check, flow, bones, bone heat)
//  - skeleton: extractCurveSkeleton alone (CGAL's mean curvature flow),
//              the part measured at 0.7 s for 4.5k vertices and
//              2.6 s for 17.7k
//  - weights:  bone heat with visibility on every vertex, on the rig's bones
//
// Meshes are built lazily, so a --benchmark_filter run pays only for what it
// selects. Each case reports the mesh's vertices and the rig's bones.
#include <benchmark/benchmark.h>

#include <map>
#include <memory>
#include <string>

#include "BenchmarkSupport.h"
#include "autorig/AutoRig.h"
#include "autorig/CurveSkeleton.h"
#include "rig/BoneHeatSolver.h"

namespace rigmesh::bench {
namespace {

constexpr const char* kSketch = "biped";

struct Input {
    Part unrigged;
    AutoRigResult rigged;  // for the weights case
};

const Input& inputFor(int vertices) {
    static std::map<int, std::unique_ptr<Input>> cache;
    auto& slot = cache[vertices];
    if (!slot) {
        const std::vector<Vec2> stroke = readSketchFile(sharedSketchPath(kSketch)).points;
        const SketchToSurfaceOptions options = optionsForVertexCount(stroke, vertices);
        slot = std::make_unique<Input>();
        slot->unrigged.name = kSketch;
        slot->unrigged.mesh = sketchToSurface(stroke, options).surface.mesh;
        slot->rigged = autoRigPart(slot->unrigged);
    }
    return *slot;
}

void counters(benchmark::State& state, const Input& input) {
    state.counters["vertices"] = input.unrigged.mesh.vertexCount();
    state.counters["bones"] = input.rigged.part.skeleton.boneCount();
}

void registerBenchmarks() {
    for (int vertices : {5000, 20000, 100000}) {
        const std::string size = vertexCountLabel(vertices);
        benchmark::RegisterBenchmark(("AutoRig/whole/" + size).c_str(),
                                     [vertices](benchmark::State& state) {
                                         const Input& input = inputFor(vertices);
                                         for (auto _ : state)
                                             benchmark::DoNotOptimize(autoRigPart(input.unrigged));
                                         counters(state, input);
                                     })
            ->Unit(benchmark::kMillisecond)
            ->UseRealTime();
        benchmark::RegisterBenchmark(
            ("AutoRig/skeleton/" + size).c_str(),
            [vertices](benchmark::State& state) {
                const Input& input = inputFor(vertices);
                for (auto _ : state)
                    benchmark::DoNotOptimize(extractCurveSkeleton(input.unrigged.mesh));
                counters(state, input);
            })
            ->Unit(benchmark::kMillisecond)
            ->UseRealTime();
        benchmark::RegisterBenchmark(("AutoRig/weights/" + size).c_str(),
                                     [vertices](benchmark::State& state) {
                                         const Input& input = inputFor(vertices);
                                         const Part& part = input.rigged.part;
                                         for (auto _ : state)
                                             benchmark::DoNotOptimize(computeBoneHeatWeights(
                                                 part.mesh, part.boneSegments()));
                                         counters(state, input);
                                     })
            ->Unit(benchmark::kMillisecond)
            ->UseRealTime();
    }
}

}  // namespace
}  // namespace rigmesh::bench

int main(int argc, char** argv) {
    return rigmesh::bench::runBenchmarks(argc, argv, rigmesh::bench::registerBenchmarks);
}
