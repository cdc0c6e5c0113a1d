// Bone heat skin weights (Baran & Popovic 2007, RigMesh section 2.4) versus
// vertex count, for 17 and 49 bones as in the paper's Table 1, on 1 and 2
// threads.
//
// The surface is the `tube` sketch's, built by the pipeline at an edge length
// giving about 1k ... 100k vertices. The bones are a chain along the mesh's
// longest bounding-box axis through the box centre, cut to the part of that
// line inside the surface and pulled in from its ends, so every bone lies
// inside the shape.
//
//  - full:      computeBoneHeatWeights with visibility tested for every vertex
//  - factorize: constructing BoneHeatSolver with the closest visible bones
//               given, i.e. assembling and factoring L + A H only
//  - solveAll:  solving every bone with an existing solver
//
// Meshes and solvers are built lazily on first use, so a --benchmark_filter
// run only pays for the sizes it selects.
#include <benchmark/benchmark.h>

#include <Eigen/Geometry>
#include <algorithm>
#include <array>
#include <cmath>
#include <map>
#include <memory>
#include <string>
#include <utility>
#include <vector>

#include "BenchmarkSupport.h"
#include "base/Error.h"
#include "mesh/TriMesh.h"
#include "pipeline/SketchToSurface.h"
#include "rig/BoneHeatSolver.h"
#include "rig/BoneSegment.h"
#include "sketch/Sketch.h"

namespace rigmesh::bench {
namespace {

constexpr const char* kSketch = "tube";

// Parameters t where the line origin + t * direction crosses a triangle of `mesh`.
std::vector<double> lineCrossings(const TriMesh& mesh, const Vec3& origin, const Vec3& direction) {
    std::vector<double> hits;
    for (const std::array<int, 3>& face : mesh.faces) {
        const Vec3& a = mesh.vertices[face[0]];
        const Vec3 e1 = mesh.vertices[face[1]] - a;
        const Vec3 e2 = mesh.vertices[face[2]] - a;
        const Vec3 p = direction.cross(e2);
        const double det = e1.dot(p);
        if (std::abs(det) < 1e-14 * e1.norm() * e2.norm()) {
            continue;
        }
        const Vec3 s = origin - a;
        const double u = s.dot(p) / det;
        const Vec3 q = s.cross(e1);
        const double v = direction.dot(q) / det;
        if (u < 0 || v < 0 || u + v > 1) {
            continue;
        }
        hits.push_back(e2.dot(q) / det);
    }
    std::sort(hits.begin(), hits.end());
    return hits;
}

// A chain of `count` bones along the longest bounding-box axis through the box
// centre, inside the surface.
std::vector<BoneSegment> boneChainAlongPrincipalAxis(const TriMesh& mesh, int count) {
    Vec3 low = mesh.vertices.front();
    Vec3 high = low;
    for (const Vec3& v : mesh.vertices) {
        low = low.cwiseMin(v);
        high = high.cwiseMax(v);
    }
    const Vec3 extent = high - low;
    const Vec3 centre = 0.5 * (low + high);
    int axis = 0;
    extent.maxCoeff(&axis);
    std::array<double, 3> sorted = {extent.x(), extent.y(), extent.z()};
    std::sort(sorted.begin(), sorted.end());
    const double width = sorted[1];  // the middle extent: about the shape's thickness
    const Vec3 direction = Vec3::Unit(axis);

    // Merge crossings at shared edges and vertices, then take the inside
    // interval that contains the centre (or else the longest inside interval).
    std::vector<double> hits;
    for (double t : lineCrossings(mesh, centre, direction)) {
        if (hits.empty() || t - hits.back() > 1e-9 * extent[axis]) {
            hits.push_back(t);
        }
    }
    double from = -0.5 * extent[axis];
    double to = 0.5 * extent[axis];
    double best = -1;
    for (std::size_t i = 0; i + 1 < hits.size(); i += 2) {
        const bool containsCentre = hits[i] <= 0 && 0 <= hits[i + 1];
        const double length = hits[i + 1] - hits[i] + (containsCentre ? extent[axis] : 0.0);
        if (length > best) {
            best = length;
            from = hits[i];
            to = hits[i + 1];
        }
    }
    const double margin = std::min(0.25 * width, 0.25 * (to - from));
    from += margin;
    to -= margin;

    std::vector<BoneSegment> bones;
    for (int b = 0; b < count; ++b) {
        const double t0 = from + (to - from) * b / count;
        const double t1 = from + (to - from) * (b + 1) / count;
        bones.push_back({centre + t0 * direction, centre + t1 * direction});
    }
    return bones;
}

struct MeshCase {
    TriMesh mesh;
    std::string error;
};

// The tube surface at about `targetVertices` vertices, built once.
const MeshCase& meshWithAbout(int targetVertices) {
    static std::map<int, MeshCase> cache;
    auto found = cache.find(targetVertices);
    if (found == cache.end()) {
        MeshCase entry;
        try {
            const std::vector<Vec2> stroke = readSketchFile(sharedSketchPath(kSketch)).points;
            entry.mesh =
                sketchToSurface(stroke, optionsForVertexCount(stroke, targetVertices)).surface.mesh;
        } catch (const Error& error) {
            entry.error = std::string(kSketch) + ": " + error.what();
        }
        found = cache.emplace(targetVertices, std::move(entry)).first;
    }
    return found->second;
}

struct Case {
    int targetVertices;
    int bones;
    int threads;
};

struct Prepared {
    const TriMesh* mesh = nullptr;
    std::vector<BoneSegment> bones;
    BoneHeatOptions options;
};

bool prepare(benchmark::State& state, const Case& c, Prepared& out) {
    const MeshCase& mesh = meshWithAbout(c.targetVertices);
    if (!mesh.error.empty()) {
        state.SkipWithError(mesh.error.c_str());
        return false;
    }
    out.mesh = &mesh.mesh;
    out.bones = boneChainAlongPrincipalAxis(mesh.mesh, c.bones);
    out.options.threads = c.threads;
    state.counters["vertices"] = mesh.mesh.vertexCount();
    state.counters["bones"] = c.bones;
    return true;
}

// A solver per case, kept for the closest bones (factorize) and solveAll.
const BoneHeatSolver& solverFor(const Case& c, const Prepared& prepared) {
    static std::map<std::array<int, 3>, std::unique_ptr<BoneHeatSolver>> cache;
    auto& slot = cache[{c.targetVertices, c.bones, c.threads}];
    if (!slot) {
        slot = std::make_unique<BoneHeatSolver>(*prepared.mesh, prepared.bones, ClosestBones{},
                                                prepared.options);
    }
    return *slot;
}

void benchFull(benchmark::State& state, Case c) {
    Prepared prepared;
    if (!prepare(state, c, prepared)) {
        return;
    }
    std::size_t failed = 0;
    for (auto _ : state) {
        SkinWeights weights =
            computeBoneHeatWeights(*prepared.mesh, prepared.bones, {}, prepared.options);
        benchmark::DoNotOptimize(weights.perVertex.data());
        benchmark::ClobberMemory();
        failed = weights.failedBones.size();
    }
    state.counters["failedBones"] = static_cast<double>(failed);
}

void benchFactorize(benchmark::State& state, Case c) {
    Prepared prepared;
    if (!prepare(state, c, prepared)) {
        return;
    }
    const BoneHeatSolver& reference = solverFor(c, prepared);
    const ClosestBones& closest = reference.closestBones();
    state.counters["withoutVisibleBone"] = reference.verticesWithoutVisibleBone();
    for (auto _ : state) {
        BoneHeatSolver solver(*prepared.mesh, prepared.bones, closest, prepared.options);
        benchmark::DoNotOptimize(solver.isFactorized());
        benchmark::ClobberMemory();
    }
    if (!reference.isFactorized()) {
        state.SkipWithError("CHOLMOD could not factor the system");
    }
}

void benchSolveAll(benchmark::State& state, Case c) {
    Prepared prepared;
    if (!prepare(state, c, prepared)) {
        return;
    }
    const BoneHeatSolver& solver = solverFor(c, prepared);
    for (auto _ : state) {
        SkinWeights weights = solver.solveAll();
        benchmark::DoNotOptimize(weights.perVertex.data());
        benchmark::ClobberMemory();
    }
}

void registerBenchmarks() {
    const std::vector<std::pair<const char*, void (*)(benchmark::State&, Case)>> kinds = {
        {"full", benchFull}, {"factorize", benchFactorize}, {"solveAll", benchSolveAll}};
    for (const auto& [kind, function] : kinds) {
        for (int vertices : {1000, 3000, 6000, 10000, 30000, 100000}) {
            for (int bones : {17, 49}) {
                for (int threads : {1, 2}) {
                    const std::string name = std::string("BoneHeat/") + kind + "/" + kSketch + "/" +
                                             vertexCountLabel(vertices) +
                                             "/bones:" + std::to_string(bones) +
                                             "/threads:" + std::to_string(threads);
                    benchmark::RegisterBenchmark(name.c_str(), function,
                                                 Case{vertices, bones, threads})
                        ->UseRealTime()
                        ->Unit(benchmark::kMillisecond);
                }
            }
        }
    }
}

}  // namespace
}  // namespace rigmesh::bench

int main(int argc, char** argv) {
    return rigmesh::bench::runBenchmarks(argc, argv, rigmesh::bench::registerBenchmarks);
}
