// Part edits at the size of the paper's camel. Merges: the Table 1 bar at
// the camel session's last step (Fig. 10: the
// head merged into the body, legs and neck, about 6k vertices): the union
// with seam remeshing and local smoothing (3.2.1), the local re-skin
// (3.2.2), the global re-skin (2.4 on the whole part), and whole merges.
//
// The camel is built by the shipped recipe (resources/recipes/camel.json) up
// to its last merge, with the model's recipe runner, once per program.
// Re-skin times are the merge's own measurement of that stage
// (MergeStats::reskinMs) reported as manual time. Cut (3.1), bone split and
// bone delete (3.3) run on the finished camel (the bar: 20, 30 and
// 40 ms at about 6.5k vertices).
#include <benchmark/benchmark.h>

#include <QCoreApplication>

#include "BenchmarkSupport.h"
#include "CamelLastMerge.h"
#include "cut/BoneEdits.h"
#include "cut/CutPart.h"
#include "merge/MergeParts.h"
#include "merge/MeshUnion.h"
#include "merge/SeamSmoothing.h"
#include "model/Document.h"
#include "model/recipe/RecipeFile.h"
#include "model/recipe/RecipeRunner.h"

namespace rigmesh::bench {
namespace {

using LastMerge = testsupport::CamelLastMerge;

const LastMerge& lastMerge() {
    return testsupport::lastCamelMerge();
}

// `Whole` is CGAL's union of the whole surfaces, for comparison with the
// near union every merge runs (merge/NearOverlapUnion.h).
void unionAndSmoothing(benchmark::State& state, UnionScope scope) {
    const LastMerge& m = lastMerge();
    const MergeResult reference = mergeParts(m.body, m.head, m.request);
    Part head = m.head;
    for (Vec3& p : head.mesh.vertices)
        p += reference.draggedTranslation;
    for (auto _ : state) {
        MeshUnionResult merged = unionMeshes(m.body.mesh, head.mesh, m.request.edgeLength, scope);
        benchmark::DoNotOptimize(smoothSeam(merged.mesh, merged.loop));
    }
    state.counters["vertices"] = reference.stats.vertices;
}

// One whole merge per iteration, timed as a whole or by its re-skin stage.
void timeMerges(benchmark::State& state, Reskin reskin, bool reskinOnly) {
    const LastMerge& m = lastMerge();
    MergeRequest request = m.request;
    request.reskin = reskin;
    MergeStats stats;
    for (auto _ : state) {
        stats = mergeParts(m.body, m.head, request).stats;
        state.SetIterationTime((reskinOnly ? stats.reskinMs : stats.totalMs) / 1000.0);
    }
    state.counters["vertices"] = stats.vertices;
    state.counters["bones"] = stats.bones;
    state.counters["vertices_involved"] = stats.verticesInvolved;
    state.counters["bones_involved"] = stats.bonesInvolved;
}

void reskinStage(benchmark::State& state, Reskin reskin) {
    timeMerges(state, reskin, true);
}

void wholeMerge(benchmark::State& state, Reskin reskin) {
    timeMerges(state, reskin, false);
}

// The finished camel: what cut and bone edits work on.
const Part& mergedCamel() {
    return testsupport::finishedCamel();
}

// Paper 3.1: across the body between the legs (it crosses once).
void cutCamel(benchmark::State& state, CutStyle style) {
    CutRequest request;
    request.point = Vec3(0.2, 0.0, 0.0);
    request.normal = Vec3(1.0, 0.1, 0.0);
    request.style = style;
    for (auto _ : state)
        benchmark::DoNotOptimize(cutPart(mergedCamel(), request));
    state.counters["vertices"] = mergedCamel().mesh.vertexCount();
}

BoneId longestBone(const Part& part) {
    BoneId best = part.skeleton.bones().front().id;
    for (const Bone& bone : part.skeleton.bones())
        if (part.skeleton.boneLength(bone.id) > part.skeleton.boneLength(best))
            best = bone.id;
    return best;
}

// Paper 3.3: the longest bone split at its middle (a knee in a leg).
void splitBone(benchmark::State& state) {
    const Part& camel = mergedCamel();
    const BoneId bone = longestBone(camel);
    const Bone& b = camel.skeleton.bone(bone);
    const Vec3 middle =
        0.5 * (camel.skeleton.joint(b.head).position + camel.skeleton.joint(b.tail).position);
    BoneEditResult result;
    for (auto _ : state)
        result = splitBoneAt(camel, bone, middle);
    state.counters["vertices"] = camel.mesh.vertexCount();
    state.counters["reskinned"] = static_cast<double>(result.reskinned.size());
}

// Paper 3.3: the neck's upper bone deleted (nearest the head's back).
void deleteBone(benchmark::State& state) {
    const Part& camel = mergedCamel();
    const BoneId bone = nearestBone(camel, Vec3(3.0, 2.2, 0.0));
    BoneEditResult result;
    for (auto _ : state)
        result = rigmesh::deleteBone(camel, bone);
    state.counters["vertices"] = camel.mesh.vertexCount();
    state.counters["reskinned"] = static_cast<double>(result.reskinned.size());
}

// A bent stroke across the body (a ruled cut surface, paper 3.1).
void cutCamelCurved(benchmark::State& state) {
    CutRequest request;
    request.sweep = Vec3::UnitZ();
    for (int i = 0; i <= 8; ++i) {
        const double y = -2.0 + 0.5 * i;
        request.stroke.push_back(Vec3(0.2 + 0.4 * (1.0 - std::abs(y) / 2.0), y, 0.0));
    }
    for (auto _ : state)
        benchmark::DoNotOptimize(cutPart(mergedCamel(), request));
    state.counters["vertices"] = mergedCamel().mesh.vertexCount();
}

BENCHMARK(cutCamelCurved)->Name("Edit/camel/cut_curved_smooth")->Unit(benchmark::kMillisecond);
BENCHMARK_CAPTURE(cutCamel, smooth, CutStyle::Smooth)
    ->Name("Edit/camel/cut_smooth")
    ->Unit(benchmark::kMillisecond);
BENCHMARK_CAPTURE(cutCamel, sharp, CutStyle::Sharp)
    ->Name("Edit/camel/cut_sharp")
    ->Unit(benchmark::kMillisecond);
BENCHMARK(splitBone)->Name("Edit/camel/split_bone")->Unit(benchmark::kMillisecond);
BENCHMARK(deleteBone)->Name("Edit/camel/delete_bone")->Unit(benchmark::kMillisecond);

BENCHMARK_CAPTURE(unionAndSmoothing, near, UnionScope::NearOverlap)
    ->Name("Merge/camel_head/union_and_smoothing")
    ->Unit(benchmark::kMillisecond);
BENCHMARK_CAPTURE(unionAndSmoothing, whole, UnionScope::Whole)
    ->Name("Merge/camel_head/union_and_smoothing_whole_union")
    ->Unit(benchmark::kMillisecond);
BENCHMARK_CAPTURE(reskinStage, local, Reskin::Local)
    ->Name("Merge/camel_head/local_reskin")
    ->UseManualTime()
    ->Unit(benchmark::kMillisecond);
BENCHMARK_CAPTURE(reskinStage, global, Reskin::Global)
    ->Name("Merge/camel_head/global_reskin")
    ->UseManualTime()
    ->Unit(benchmark::kMillisecond);
BENCHMARK_CAPTURE(wholeMerge, local, Reskin::Local)
    ->Name("Merge/camel_head/whole_merge_local")
    ->UseManualTime()
    ->Unit(benchmark::kMillisecond);
BENCHMARK_CAPTURE(wholeMerge, global, Reskin::Global)
    ->Name("Merge/camel_head/whole_merge_global")
    ->UseManualTime()
    ->Unit(benchmark::kMillisecond);

}  // namespace
}  // namespace rigmesh::bench

int main(int argc, char** argv) {
    QCoreApplication application(argc, argv);  // the commands translate their texts
    return rigmesh::bench::runBenchmarks(argc, argv, [] {});
}
