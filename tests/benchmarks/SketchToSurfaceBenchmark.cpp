// Sketch to surface (paper sections 2.1-2.2), stage by stage (and the
// built surface's closing check, with and without its mirror) and as a
// whole, on every good shared sketch, plus the whole pipeline on the biped at
// growing mesh resolutions.
//
// Benchmarks are registered at start-up but their inputs are built lazily on
// first use, so a --benchmark_filter run only pays for what it selects.
#include <benchmark/benchmark.h>

#include <chrono>
#include <map>
#include <memory>
#include <string>
#include <utility>
#include <vector>

#include "BenchmarkSupport.h"
#include "axis/ChordalAxis.h"
#include "axis/Decomposition.h"
#include "base/Error.h"
#include "geometry/ConstrainedTriangulation.h"
#include "pipeline/SketchToSurface.h"
#include "pipeline/SurfaceLimits.h"
#include "sketch/Sketch.h"
#include "sketch/StrokeCleaner.h"
#include "surface/CrossSections.h"
#include "surface/SketchSurface.h"

namespace rigmesh::bench {
namespace {

// The input of every stage of one sketch, computed once with default options.
struct StageInputs {
    std::vector<Vec2> stroke;
    CleanPolygon polygon;
    PolygonTriangulation cdt;
    ChordalAxis axis;
    Decomposition decomposition;
    double targetEdgeLength = 0;
    std::vector<CylinderSections> cylinders;
};

struct SketchData {
    std::string name;
    std::vector<Vec2> stroke;  // read once, at registration
    std::unique_ptr<StageInputs> inputs;
    std::unique_ptr<SketchSurface> built;  // the pipeline's surface, for its checks
    std::string error;                     // why the stage inputs could not be built
};

const StageInputs* stageInputs(SketchData& sketch, benchmark::State& state) {
    if (!sketch.inputs && sketch.error.empty()) {
        try {
            auto inputs = std::make_unique<StageInputs>();
            inputs->stroke = sketch.stroke;
            inputs->polygon = cleanStroke(inputs->stroke);
            inputs->cdt = triangulatePolygon(inputs->polygon.points);
            inputs->axis = computeChordalAxis(inputs->cdt);
            inputs->decomposition = decompose(inputs->axis);
            inputs->targetEdgeLength = inputs->polygon.spacing;
            for (std::size_t c = 0; c < inputs->decomposition.cylinders.size(); ++c) {
                inputs->cylinders.push_back(buildCrossSections(
                    inputs->decomposition, static_cast<int>(c), inputs->targetEdgeLength));
            }
            sketch.inputs = std::move(inputs);
        } catch (const Error& error) {
            sketch.error = sketch.name + ": " + error.what();
        }
    }
    if (!sketch.inputs) {
        state.SkipWithError(sketch.error.c_str());
    }
    return sketch.inputs.get();
}

using Clock = std::chrono::steady_clock;

double secondsSince(Clock::time_point start) {
    return std::chrono::duration<double>(Clock::now() - start).count();
}

void benchClean(benchmark::State& state, SketchData* sketch) {
    const StageInputs* in = stageInputs(*sketch, state);
    if (!in) {
        return;
    }
    for (auto _ : state) {
        CleanPolygon polygon = cleanStroke(in->stroke);
        benchmark::DoNotOptimize(polygon.points.data());
        benchmark::ClobberMemory();
    }
    state.counters["vertices"] = static_cast<double>(in->polygon.points.size());
}

void benchTriangulate(benchmark::State& state, SketchData* sketch) {
    const StageInputs* in = stageInputs(*sketch, state);
    if (!in) {
        return;
    }
    for (auto _ : state) {
        PolygonTriangulation cdt = triangulatePolygon(in->polygon.points);
        benchmark::DoNotOptimize(cdt.triangles.data());
        benchmark::ClobberMemory();
    }
    state.counters["vertices"] = static_cast<double>(in->cdt.points.size());
    state.counters["triangles"] = static_cast<double>(in->cdt.triangles.size());
}

// computeChordalAxis takes its triangulation by value: the copy is made
// outside the measured interval (manual timing).
void benchChordalAxis(benchmark::State& state, SketchData* sketch) {
    const StageInputs* in = stageInputs(*sketch, state);
    if (!in) {
        return;
    }
    for (auto _ : state) {
        PolygonTriangulation cdt = in->cdt;
        const Clock::time_point start = Clock::now();
        ChordalAxis axis = computeChordalAxis(std::move(cdt));
        benchmark::DoNotOptimize(axis.branches.data());
        benchmark::ClobberMemory();
        state.SetIterationTime(secondsSince(start));
    }
    state.counters["vertices"] = static_cast<double>(in->cdt.points.size());
    state.counters["branches"] = static_cast<double>(in->axis.branches.size());
}

// decompose takes its chordal axis by value: copied outside the measured interval.
void benchDecompose(benchmark::State& state, SketchData* sketch) {
    const StageInputs* in = stageInputs(*sketch, state);
    if (!in) {
        return;
    }
    for (auto _ : state) {
        ChordalAxis axis = in->axis;
        const Clock::time_point start = Clock::now();
        Decomposition decomposition = decompose(std::move(axis));
        benchmark::DoNotOptimize(decomposition.cylinders.data());
        benchmark::ClobberMemory();
        state.SetIterationTime(secondsSince(start));
    }
    state.counters["vertices"] = static_cast<double>(in->cdt.points.size());
    state.counters["cylinders"] = static_cast<double>(in->decomposition.cylinders.size());
    state.counters["connecting"] = static_cast<double>(in->decomposition.connecting.size());
}

void benchCrossSections(benchmark::State& state, SketchData* sketch) {
    const StageInputs* in = stageInputs(*sketch, state);
    if (!in) {
        return;
    }
    for (auto _ : state) {
        std::vector<CylinderSections> cylinders;
        for (std::size_t c = 0; c < in->decomposition.cylinders.size(); ++c) {
            cylinders.push_back(
                buildCrossSections(in->decomposition, static_cast<int>(c), in->targetEdgeLength));
        }
        benchmark::DoNotOptimize(cylinders.data());
        benchmark::ClobberMemory();
    }
    std::size_t sections = 0;
    for (const CylinderSections& cylinder : in->cylinders) {
        sections += cylinder.sections.size();
    }
    state.counters["vertices"] = static_cast<double>(in->cdt.points.size());
    state.counters["sections"] = static_cast<double>(sections);
}

void benchSurface(benchmark::State& state, SketchData* sketch, bool smooth) {
    const StageInputs* in = stageInputs(*sketch, state);
    if (!in) {
        return;
    }
    SurfaceOptions options;
    options.targetEdgeLength = in->targetEdgeLength;
    options.smooth = smooth;
    int vertices = 0;
    int faces = 0;
    for (auto _ : state) {
        SketchSurface surface = buildSurface(in->decomposition, in->cylinders, options);
        benchmark::DoNotOptimize(surface.mesh.vertices.data());
        benchmark::ClobberMemory();
        vertices = surface.mesh.vertexCount();
        faces = surface.mesh.faceCount();
    }
    state.counters["vertices"] = vertices;
    state.counters["faces"] = faces;
}

// The closing check of the built surface (pipeline/SurfaceLimits.h:
// checkBuiltMesh): with its mirror, as the pipeline runs it (the height
// field proof of mesh/MirroredHeightField.h, the faces over its folds tested
// pairwise), or without, every pair of faces whose boxes meet tested.
void benchChecks(benchmark::State& state, SketchData* sketch, bool withMirror) {
    if (!sketch->built && sketch->error.empty()) {
        try {
            sketch->built =
                std::make_unique<SketchSurface>(sketchToSurface(sketch->stroke).surface);
        } catch (const Error& error) {
            sketch->error = sketch->name + ": " + error.what();
        }
    }
    if (!sketch->built) {
        state.SkipWithError(sketch->error.c_str());
        return;
    }
    const SketchSurface& surface = *sketch->built;
    const std::vector<int> noMirror;
    for (auto _ : state) {
        checkBuiltMesh(surface.mesh, withMirror ? surface.mirror : noMirror);
        benchmark::ClobberMemory();
    }
    state.counters["faces"] = surface.mesh.faceCount();
}

void runPipeline(benchmark::State& state, const std::vector<Vec2>& stroke,
                 const SketchToSurfaceOptions& options) {
    int vertices = 0;
    int faces = 0;
    StageTimings ms;
    for (auto _ : state) {
        SketchToSurfaceResult result = sketchToSurface(stroke, options);
        benchmark::DoNotOptimize(result.surface.mesh.vertices.data());
        benchmark::ClobberMemory();
        vertices = result.surface.mesh.vertexCount();
        faces = result.surface.mesh.faceCount();
        ms = result.milliseconds;
    }
    state.counters["vertices"] = vertices;
    state.counters["faces"] = faces;
    // Each stage's milliseconds in the last run, to see which one grows faster than n.
    for (const auto& [stage, value] : {std::pair{"ms_clean", ms.clean},
                                       {"ms_triangulate", ms.triangulate},
                                       {"ms_chordal_axis", ms.chordalAxis},
                                       {"ms_decompose", ms.decompose},
                                       {"ms_cross_sections", ms.crossSections},
                                       {"ms_surface", ms.surface},
                                       {"ms_smoothing", ms.smoothing},
                                       {"ms_checks", ms.checks}})
        state.counters[stage] = value;
}

void benchPipeline(benchmark::State& state, SketchData* sketch) {
    if (!sketch->error.empty()) {
        state.SkipWithError(sketch->error.c_str());
        return;
    }
    try {
        runPipeline(state, sketch->stroke, {});
    } catch (const Error& error) {
        state.SkipWithError((sketch->name + ": " + error.what()).c_str());
    }
}

// The whole pipeline at about `targetVertices` vertices; the edge length is
// found on first use (BenchmarkSupport.h).
struct ScalingCase {
    SketchData* sketch;
    int targetVertices;
    std::unique_ptr<SketchToSurfaceOptions> options;
};

void benchScaling(benchmark::State& state, ScalingCase* scaling) {
    try {
        if (!scaling->options) {
            scaling->options = std::make_unique<SketchToSurfaceOptions>(
                optionsForVertexCount(scaling->sketch->stroke, scaling->targetVertices));
        }
        runPipeline(state, scaling->sketch->stroke, *scaling->options);
        state.counters["targetEdgeLength"] = scaling->options->surface.targetEdgeLength;
    } catch (const Error& error) {
        state.SkipWithError((scaling->sketch->name + ": " + error.what()).c_str());
    }
}

void registerBenchmarks() {
    static std::vector<std::unique_ptr<SketchData>> sketches;
    static std::vector<std::unique_ptr<ScalingCase>> scalingCases;

    for (const std::string& name : goodSharedSketchNames()) {
        auto sketch = std::make_unique<SketchData>();
        sketch->name = name;
        try {
            sketch->stroke = readSketchFile(sharedSketchPath(name)).points;
        } catch (const Error& error) {
            sketch->error = name + ": " + error.what();
        }
        sketches.push_back(std::move(sketch));
    }

    for (const auto& owned : sketches) {
        SketchData* sketch = owned.get();
        const std::string& name = sketch->name;
        benchmark::RegisterBenchmark(("Stage/clean/" + name).c_str(), benchClean, sketch)
            ->Unit(benchmark::kMillisecond);
        benchmark::RegisterBenchmark(("Stage/triangulate/" + name).c_str(), benchTriangulate,
                                     sketch)
            ->Unit(benchmark::kMillisecond);
        benchmark::RegisterBenchmark(("Stage/chordalAxis/" + name).c_str(), benchChordalAxis,
                                     sketch)
            ->UseManualTime()
            ->Unit(benchmark::kMillisecond);
        benchmark::RegisterBenchmark(("Stage/decompose/" + name).c_str(), benchDecompose, sketch)
            ->UseManualTime()
            ->Unit(benchmark::kMillisecond);
        benchmark::RegisterBenchmark(("Stage/crossSections/" + name).c_str(), benchCrossSections,
                                     sketch)
            ->Unit(benchmark::kMillisecond);
        benchmark::RegisterBenchmark(("Stage/surfaceNoSmooth/" + name).c_str(), benchSurface,
                                     sketch, false)
            ->Unit(benchmark::kMillisecond);
        benchmark::RegisterBenchmark(("Stage/surfaceSmooth/" + name).c_str(), benchSurface, sketch,
                                     true)
            ->Unit(benchmark::kMillisecond);
        benchmark::RegisterBenchmark(("Stage/checks/" + name).c_str(), benchChecks, sketch, true)
            ->Unit(benchmark::kMillisecond);
        benchmark::RegisterBenchmark(("Stage/checksEveryFacePair/" + name).c_str(), benchChecks,
                                     sketch, false)
            ->Unit(benchmark::kMillisecond);
        benchmark::RegisterBenchmark(("Pipeline/" + name).c_str(), benchPipeline, sketch)
            ->UseRealTime()
            ->Unit(benchmark::kMillisecond);
    }

    for (const auto& owned : sketches) {
        if (owned->name != "biped") {
            continue;
        }
        // 110k: the size once measured (surface stage about n^1.4 there).
        for (int target : {1000, 3000, 10000, 30000, 110000}) {
            scalingCases.push_back(
                std::make_unique<ScalingCase>(ScalingCase{owned.get(), target, nullptr}));
            benchmark::RegisterBenchmark(
                ("Scaling/pipeline/biped/" + vertexCountLabel(target)).c_str(), benchScaling,
                scalingCases.back().get())
                ->UseRealTime()
                ->Unit(benchmark::kMillisecond);
        }
    }
}

}  // namespace
}  // namespace rigmesh::bench

int main(int argc, char** argv) {
    return rigmesh::bench::runBenchmarks(argc, argv, rigmesh::bench::registerBenchmarks);
}
