// Sketch to rigged part (paper sections 2.3-2.4) on every good shared sketch:
// the skeleton, the skin weights with the paper's shortcut (closest bones of
// cylindrical vertices known from construction, visibility tested only in
// connecting regions), the same weights with visibility tested for every
// vertex (Pinocchio's global cost, the paper's Table 1 "global" column), and
// the whole sketch-to-part pipeline.
#include <benchmark/benchmark.h>

#include <memory>
#include <string>
#include <vector>

#include "BenchmarkSupport.h"
#include "pipeline/SketchToPart.h"

namespace rigmesh::bench {
namespace {

struct PartCase {
    std::string name;
    std::vector<Vec2> stroke;
    std::unique_ptr<SketchToPartResult> built;  // built on first use
};

const SketchToPartResult& built(PartCase& c) {
    if (!c.built)
        c.built = std::make_unique<SketchToPartResult>(sketchToPart(c.stroke, c.name));
    return *c.built;
}

void setCounters(benchmark::State& state, const Part& part) {
    state.counters["vertices"] = part.mesh.vertexCount();
    state.counters["bones"] = part.skeleton.boneCount();
}

void benchSkeleton(benchmark::State& state, PartCase* c) {
    const SketchToPartResult& r = built(*c);
    for (auto _ : state)
        benchmark::DoNotOptimize(buildSkeleton(r.surface.decomposition, r.surface.cylinders));
    setCounters(state, r.part);
}

void benchWeights(benchmark::State& state, PartCase* c, bool knownClosestBones) {
    const SketchToPartResult& r = built(*c);
    const auto bones = r.part.boneSegments();
    for (auto _ : state) {
        ClosestBones closest =
            knownClosestBones
                ? closestBonesFromConstruction(r.surface.surface, r.surface.cylinders, r.skeleton)
                : ClosestBones{};
        benchmark::DoNotOptimize(computeBoneHeatWeights(r.part.mesh, bones, closest));
    }
    setCounters(state, r.part);
}

void benchSketchToPart(benchmark::State& state, PartCase* c, int threads) {
    SketchToPartOptions options;
    options.weights.threads = threads;
    for (auto _ : state)
        benchmark::DoNotOptimize(sketchToPart(c->stroke, c->name, options));
    setCounters(state, built(*c).part);
}

void registerBenchmarks() {
    static std::vector<std::unique_ptr<PartCase>> cases;
    for (const std::string& name : goodSharedSketchNames()) {
        cases.push_back(std::make_unique<PartCase>());
        PartCase* c = cases.back().get();
        c->name = name;
        c->stroke = readSketchFile(sharedSketchPath(name)).points;
        benchmark::RegisterBenchmark(("Part/skeleton/" + name).c_str(), benchSkeleton, c)
            ->Unit(benchmark::kMillisecond);
        benchmark::RegisterBenchmark(("Part/weights/" + name).c_str(), benchWeights, c, true)
            ->Unit(benchmark::kMillisecond)
            ->UseRealTime();
        benchmark::RegisterBenchmark(("Part/weightsVisibilityEverywhere/" + name).c_str(),
                                     benchWeights, c, false)
            ->Unit(benchmark::kMillisecond)
            ->UseRealTime();
        benchmark::RegisterBenchmark(("Part/sketchToPart/" + name).c_str(), benchSketchToPart, c, 1)
            ->Unit(benchmark::kMillisecond)
            ->UseRealTime();
        benchmark::RegisterBenchmark(("Part/sketchToPartTwoThreads/" + name).c_str(),
                                     benchSketchToPart, c, 2)
            ->Unit(benchmark::kMillisecond)
            ->UseRealTime();
    }
}

}  // namespace
}  // namespace rigmesh::bench

int main(int argc, char** argv) {
    return rigmesh::bench::runBenchmarks(argc, argv, rigmesh::bench::registerBenchmarks);
}
