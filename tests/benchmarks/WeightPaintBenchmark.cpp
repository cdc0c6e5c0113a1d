// Weight painting on a 50k-vertex biped: one dab (bar:
// 1 ms), a stroke of 100 dabs (bar: 50 ms) through the engine's
// WeightPainter, the same stroke as the studio pushes it (one
// PaintWeightsCommand: every dab plus one copy of the part), and Smooth All.
#include <benchmark/benchmark.h>

#include <QCoreApplication>
#include <memory>

#include "BenchmarkSupport.h"
#include "model/Document.h"
#include "model/commands/PaintWeightsCommand.h"
#include "model/commands/WeightCleanupCommand.h"
#include "part/WeightCleanup.h"
#include "part/WeightPaint.h"
#include "pipeline/SketchToPart.h"

namespace rigmesh {
namespace {

constexpr int kVertices = 50000;
constexpr int kStrokeDabs = 100;

// The biped at about 50k vertices, built once.
const Part& bigBiped() {
    static const Part part = [] {
        const std::vector<Vec2> stroke = readSketchFile(bench::sharedSketchPath("biped")).points;
        SketchToPartOptions options;
        options.surface = bench::optionsForVertexCount(stroke, kVertices);
        return sketchToPart(stroke, "biped", options).part;
    }();
    return part;
}

// A brush as the studio makes it: 40 px on a part 600 px tall, i.e. 1/15
// of the part's height, centred on surface vertices along the body.
struct Brush {
    double radius;
    std::vector<Vec3> centres;  // kStrokeDabs of them, a stroke down the body
};

Brush brushFor(const Part& part) {
    Eigen::AlignedBox3d box;
    for (const Vec3& v : part.mesh.vertices)
        box.extend(v);
    Brush brush{box.sizes().y() / 15.0, {}};
    // The front-most vertex in each of kStrokeDabs horizontal slices.
    std::vector<int> best(kStrokeDabs, -1);
    for (int v = 0; v < part.mesh.vertexCount(); ++v) {
        const Vec3& p = part.mesh.vertices[v];
        const int slice =
            std::clamp(static_cast<int>((p.y() - box.min().y()) / box.sizes().y() * kStrokeDabs), 0,
                       kStrokeDabs - 1);
        if (std::abs(p.x() - box.center().x()) < brush.radius &&
            (best[slice] < 0 || p.z() > part.mesh.vertices[best[slice]].z()))
            best[slice] = v;
    }
    for (int v : best)
        brush.centres.push_back(part.mesh.vertices[v < 0 ? 0 : v]);
    return brush;
}

// The bone painted: the largest at the stroke's middle (so Smooth has a
// gradient to even out and Add and Subtract have room both ways).
BoneId paintedBone(const Part& part, const Brush& brush) {
    int nearest = 0;
    const Vec3& middle = brush.centres[brush.centres.size() / 2];
    for (int v = 0; v < part.mesh.vertexCount(); ++v)
        if ((part.mesh.vertices[v] - middle).squaredNorm() <
            (part.mesh.vertices[nearest] - middle).squaredNorm())
            nearest = v;
    const auto& list = part.weights.perVertex[nearest];
    const auto largest = std::max_element(list.begin(), list.end(),
                                          [](auto& a, auto& b) { return a.second < b.second; });
    return largest->first;
}

WeightDab dabAt(const Part& part, const Brush& brush, int i, BrushMode mode) {
    WeightDab dab;
    static const BoneId bone = paintedBone(part, brush);
    dab.bone = bone;
    dab.mode = mode;
    dab.centre = brush.centres[i % brush.centres.size()];
    dab.radius = brush.radius;
    dab.strength = 0.5;
    dab.towardsViewer = Vec3(0.0, 0.0, 1.0);
    return dab;
}

// One dab; Add and Subtract alternate so every dab changes weights.
void BM_Dab(benchmark::State& state) {
    Part part = bigBiped();
    const Brush brush = brushFor(part);
    WeightPainter painter(part.mesh);
    const auto smooth = static_cast<BrushMode>(state.range(0));
    long changed = 0;
    int i = 0;
    for (auto _ : state) {
        const BrushMode mode =
            smooth == BrushMode::Smooth ? smooth : (i % 2 ? BrushMode::Subtract : BrushMode::Add);
        changed += painter.paint(part, dabAt(part, brush, kStrokeDabs / 2, mode)).changed.size();
        ++i;
    }
    state.counters["vertices"] = part.mesh.vertexCount();
    state.counters["changedPerDab"] = double(changed) / double(std::max(i, 1));
}

// A stroke: a new painter (as each studio stroke makes) and 100 dabs.
void BM_Stroke(benchmark::State& state) {
    const Part& original = bigBiped();
    const Brush brush = brushFor(original);
    const auto mode = static_cast<BrushMode>(state.range(0));
    for (auto _ : state) {
        state.PauseTiming();
        Part part = original;
        state.ResumeTiming();
        WeightPainter painter(part.mesh);
        for (int i = 0; i < kStrokeDabs; ++i)
            painter.paint(part, dabAt(part, brush, i, mode));
        benchmark::DoNotOptimize(part.weights.perVertex.data());
    }
    state.counters["vertices"] = original.mesh.vertexCount();
}

// The stroke as one command, as the studio pushes it on release.
void BM_StrokeCommand(benchmark::State& state) {
    model::Document document;
    model::PartNode node;
    node.id = document.allocatePartId();
    node.name = QStringLiteral("biped");
    node.part = std::make_shared<const Part>(bigBiped());
    document.insertPart(0, node);
    const Brush brush = brushFor(bigBiped());
    std::vector<WeightDab> dabs;
    for (int i = 0; i < kStrokeDabs; ++i)
        dabs.push_back(dabAt(bigBiped(), brush, i, BrushMode::Add));
    for (auto _ : state) {
        auto command = model::PaintWeightsCommand::create(document, node.id, dabs);
        benchmark::DoNotOptimize(command->changedVertices());
    }
}

void BM_SmoothAll(benchmark::State& state) {
    const Part& original = bigBiped();
    for (auto _ : state) {
        state.PauseTiming();
        Part part = original;
        state.ResumeTiming();
        benchmark::DoNotOptimize(smoothAllWeights(part, {0.5, 1}));
    }
}

BENCHMARK(BM_Dab)
    ->Name("Paint/dab/biped/50k")
    ->ArgName("mode")
    ->Arg(static_cast<int>(BrushMode::Add))
    ->Arg(static_cast<int>(BrushMode::Smooth))
    ->Unit(benchmark::kMillisecond);
BENCHMARK(BM_Stroke)
    ->Name("Paint/stroke100/biped/50k")
    ->ArgName("mode")
    ->Arg(static_cast<int>(BrushMode::Add))
    ->Arg(static_cast<int>(BrushMode::Smooth))
    ->Unit(benchmark::kMillisecond);
BENCHMARK(BM_StrokeCommand)
    ->Name("Paint/stroke100command/biped/50k")
    ->Unit(benchmark::kMillisecond);
BENCHMARK(BM_SmoothAll)->Name("Weights/smoothAll/biped/50k")->Unit(benchmark::kMillisecond);

}  // namespace
}  // namespace rigmesh

int main(int argc, char** argv) {
    QCoreApplication application(argc, argv);  // the document's undo stack wants one
    return rigmesh::bench::runBenchmarks(argc, argv, [] {});
}
