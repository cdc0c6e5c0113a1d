// Helpers shared by the benchmark programs: the shared sketches and surfaces
// built at a requested vertex count.
#pragma once

#include <benchmark/benchmark.h>

#include <algorithm>
#include <cmath>
#include <filesystem>
#include <string>
#include <vector>

#include "base/AllocatorTuning.h"
#include "pipeline/SketchToSurface.h"
#include "sketch/Sketch.h"

namespace rigmesh::bench {

inline std::string sharedSketchPath(const std::string& name) {
    return std::string(RIGMESH_SHARED_SKETCHES) + "/" + name + ".json";
}

// The good shared sketches (every .json not starting with "bad_"), sorted.
inline std::vector<std::string> goodSharedSketchNames() {
    std::vector<std::string> names;
    for (const auto& entry : std::filesystem::directory_iterator(RIGMESH_SHARED_SKETCHES)) {
        const std::string stem = entry.path().stem().string();
        if (entry.path().extension() == ".json" && stem.rfind("bad_", 0) != 0) {
            names.push_back(stem);
        }
    }
    std::sort(names.begin(), names.end());
    return names;
}

// "1k", "30k", "100k", or the plain number below a thousand.
inline std::string vertexCountLabel(int count) {
    if (count >= 1000 && count % 1000 == 0) {
        return std::to_string(count / 1000) + "k";
    }
    return std::to_string(count);
}

// Pipeline options whose surface has about `targetVertices` vertices. The
// vertex count grows with the inverse square of the edge length, so the
// default spacing (the cleaned outline's) is scaled by sqrt(defaultCount /
// targetVertices); one correction step with the count actually obtained
// absorbs what the caps and connecting regions make non-quadratic.
inline SketchToSurfaceOptions optionsForVertexCount(const std::vector<Vec2>& stroke,
                                                    int targetVertices) {
    const SketchToSurfaceResult reference = sketchToSurface(stroke);
    SketchToSurfaceOptions options;
    options.surface.targetEdgeLength =
        reference.targetEdgeLength *
        std::sqrt(static_cast<double>(reference.surface.mesh.vertexCount()) / targetVertices);
    const int obtained = sketchToSurface(stroke, options).surface.mesh.vertexCount();
    if (std::abs(obtained - targetVertices) > 0.05 * targetVertices) {
        options.surface.targetEdgeLength *=
            std::sqrt(static_cast<double>(obtained) / targetVertices);
    }
    return options;
}

// The main() of every benchmark program (after a Qt application where one
// is needed): malloc as the studio sets it (base/AllocatorTuning.h),
// register (after Google Benchmark has read its flags; benchmarks declared
// with BENCHMARK register themselves), then run what the filter selects.
inline int runBenchmarks(int argc, char** argv, void (*registerBenchmarks)()) {
    tuneAllocatorForEditing();
    benchmark::Initialize(&argc, argv);
    if (benchmark::ReportUnrecognizedArguments(argc, argv))
        return 1;
    registerBenchmarks();
    benchmark::RunSpecifiedBenchmarks();
    benchmark::Shutdown();
    return 0;
}

}  // namespace rigmesh::bench
