// Posing benchmarks: DQS and LBS skinning of a long tube (about 6k and 100k
// vertices) on a 50-bone chain with smooth synthetic weights, on 1 and 2
// threads, from the weight lists (Skin/DQS, Skin/LBS: what a one-off pose
// does) and from a SkinningBinding made once into reused buffers
// (Skin/DQS/bound, Skin/LBS/bound: a caller skinning every frame), making
// that binding, and one IK drag step of the chain's tip.
#include <benchmark/benchmark.h>

#include <algorithm>
#include <cmath>
#include <map>

#include "BenchmarkSupport.h"
#include "mesh/MeshPrimitives.h"
#include "mesh/VertexNormals.h"
#include "pose/ForwardKinematics.h"
#include "pose/InverseKinematics.h"
#include "pose/Skinning.h"
#include "pose/SkinningBinding.h"

namespace rigmesh {
namespace {

constexpr int kBones = 50;
constexpr double kLength = 50.0;  // along z, one unit per bone
constexpr double kRadius = 1.0;
constexpr int kSegments = 32;

// A 50-bone chain along z through the tube's axis, rooted at its bottom end.
Skeleton chainSkeleton() {
    Skeleton skeleton;
    JointId previous = skeleton.addJoint(Vec3(0, 0, -kLength / 2));
    for (int i = 1; i <= kBones; ++i) {
        const JointId next = skeleton.addJoint(Vec3(0, 0, -kLength / 2 + i * kLength / kBones));
        skeleton.addBone(previous, next);
        previous = next;
    }
    return skeleton;
}

// Smooth weights: a hat function of the distance along the axis from each
// bone's centre (width 1.5 bones), so each vertex has 2-3 bones; keyed by
// bone id, as a part stores them.
WeightsById chainWeights(const TriMesh& mesh, const Skeleton& skeleton) {
    WeightsById weights;
    const double boneLength = kLength / kBones;
    for (const Vec3& v : mesh.vertices) {
        const double s = (v.z() + kLength / 2) / boneLength - 0.5;  // in bone units
        std::vector<std::pair<BoneId, double>> list;
        double sum = 0;
        for (int b = std::max(0, static_cast<int>(std::floor(s)) - 1);
             b <= std::min(kBones - 1, static_cast<int>(std::ceil(s)) + 1); ++b) {
            const double w = std::max(0.0, 1.0 - std::abs(s - b) / 1.5);
            if (w > 0) {
                list.push_back({skeleton.bones()[b].id, w});
                sum += w;
            }
        }
        for (auto& [bone, w] : list)
            w /= sum;
        weights.push_back(std::move(list));
    }
    return weights;
}

struct Rig {
    TriMesh mesh;
    std::vector<Vec3> normals;
    Skeleton skeleton;
    WeightsById weights;
    Pose pose;  // every joint bent and twisted a little
};

const Rig& rig(int rings) {
    static std::map<int, Rig> cache;
    auto found = cache.find(rings);
    if (found == cache.end()) {
        Rig r;
        r.mesh = makeCylinderTube(rings, kSegments, kRadius, kLength);
        r.normals = vertexNormals(r.mesh);
        r.skeleton = chainSkeleton();
        r.weights = chainWeights(r.mesh, r.skeleton);
        for (const Joint& joint : r.skeleton.joints())
            r.pose.setRotation(joint.id, Eigen::Quaterniond(Eigen::AngleAxisd(
                                             0.05, Vec3(1, 0.3, 0.5).normalized())));
        found = cache.emplace(rings, std::move(r)).first;
    }
    return found->second;
}

// Rings for about 6k and 100k vertices (32 per ring, plus 2 cap centres).
constexpr int kRings6k = 188;
constexpr int kRings100k = 3125;

void skin(benchmark::State& state, SkinningMethod method) {
    const Rig& r = rig(static_cast<int>(state.range(0)));
    const SkinningOptions options{method, static_cast<int>(state.range(1))};
    for (auto _ : state) {
        // Per frame: FK, per-bone transforms, then the vertices.
        const PosedSkeleton posed = forwardKinematics(r.skeleton, r.pose);
        SkinnedVertices out =
            skinVertices(r.mesh.vertices, r.normals, r.weights,
                         SkinningTransforms(r.skeleton, posed.boneTransforms), options);
        benchmark::DoNotOptimize(out.positions.data());
    }
    state.counters["vertices"] = r.mesh.vertexCount();
    state.counters["bones"] = kBones;
}

void dqs(benchmark::State& state) {
    skin(state, SkinningMethod::DualQuaternion);
}
void lbs(benchmark::State& state) {
    skin(state, SkinningMethod::LinearBlend);
}

void skinArgs(benchmark::internal::Benchmark* b) {
    b->ArgNames({"rings", "threads"});
    for (int rings : {kRings6k, kRings100k}) {
        for (int threads : {1, 2})
            b->Args({rings, threads});
    }
    b->Unit(benchmark::kMillisecond)->UseRealTime();
}

BENCHMARK(dqs)->Name("Skin/DQS")->Apply(skinArgs);
BENCHMARK(lbs)->Name("Skin/LBS")->Apply(skinArgs);

// The binding is made once, the output's buffers are the last frame's.
void skinBound(benchmark::State& state, SkinningMethod method) {
    const Rig& r = rig(static_cast<int>(state.range(0)));
    const SkinningOptions options{method, static_cast<int>(state.range(1))};
    const SkinningBinding binding(r.weights);
    SkinnedVertices out;
    for (auto _ : state) {
        const PosedSkeleton posed = forwardKinematics(r.skeleton, r.pose);
        skinVertices(r.mesh.vertices, r.normals, binding,
                     SkinningTransforms(r.skeleton, posed.boneTransforms), options, out);
        benchmark::DoNotOptimize(out.positions.data());
    }
    state.counters["vertices"] = r.mesh.vertexCount();
    state.counters["bones"] = kBones;
}

void dqsBound(benchmark::State& state) {
    skinBound(state, SkinningMethod::DualQuaternion);
}
void lbsBound(benchmark::State& state) {
    skinBound(state, SkinningMethod::LinearBlend);
}

BENCHMARK(dqsBound)->Name("Skin/DQS/bound")->Apply(skinArgs);
BENCHMARK(lbsBound)->Name("Skin/LBS/bound")->Apply(skinArgs);

// Making the binding from the weight lists (once per part and weights).
void bind(benchmark::State& state) {
    const Rig& r = rig(static_cast<int>(state.range(0)));
    for (auto _ : state) {
        const SkinningBinding binding(r.weights);
        benchmark::DoNotOptimize(binding.influenceCount());
    }
    state.counters["vertices"] = r.mesh.vertexCount();
}
BENCHMARK(bind)
    ->Name("Skin/bind")
    ->ArgName("rings")
    ->Arg(kRings6k)
    ->Arg(kRings100k)
    ->Unit(benchmark::kMillisecond);

// One drag step: the tip of the bent 50-bone chain follows a target moving
// along a circle by a small step each iteration (warm started, as in the
// viewport), plus the dragged-joint FK the caller needs afterwards.
void ikDragStep(benchmark::State& state) {
    const Rig& r = rig(kRings6k);
    const PoseHierarchy hierarchy(r.skeleton);
    const JointId tip = r.skeleton.joints().back().id;
    Pose pose = r.pose;
    const Vec3 start = forwardKinematics(hierarchy, pose).jointPositions.back();
    const Vec3 centre = start - Vec3(5, 0, 0);
    IkOptions options;
    if (state.range(0) > 0)
        options.softReach = 0.05;
    int step = 0;
    double iterations = 0;
    for (auto _ : state) {
        const double a = 0.002 * step++;
        const Vec3 target = centre + 5 * Vec3(std::cos(a), std::sin(a), 0.3 * std::sin(2 * a));
        IkResult result = dragJoint(hierarchy, pose, tip, target, {}, options);
        iterations += result.iterations;
        pose = std::move(result.pose);
        benchmark::DoNotOptimize(pose.rotations.size());
    }
    state.counters["sweeps"] = benchmark::Counter(iterations, benchmark::Counter::kAvgIterations);
}
BENCHMARK(ikDragStep)
    ->Name("IK/dragStep/bones:50")
    ->ArgName("soft")
    ->Arg(0)
    ->Arg(1)
    ->Unit(benchmark::kMicrosecond);

}  // namespace
}  // namespace rigmesh

// The benchmarks above register themselves.
int main(int argc, char** argv) {
    return rigmesh::bench::runBenchmarks(argc, argv, [] {});
}
