// Playback of the timeline: the biped at 10k, 50k and 100k vertices with
// a three-key smooth clip, one frame after another in a 960x540 viewport as
// the studio plays it: the clip evaluated at the new frame and the pose set
// (Document::setCurrentFrame), forward kinematics, GPU skinning and drawing,
// up to reading the frame back (grabFramebuffer, which waits for the
// drawing; 2 MB at this size). Frame/... is that whole frame; Still/... the
// same drawing and read-back with the frame unchanged; Unskinned/... that
// drawing of the mesh without its rig (what llvmpipe alone costs for it,
// the bound any skinning has to live within);
// Evaluate/... the document side alone. Runs under Xvfb (Mesa llvmpipe: the
// GPU is the CPU here).
//
// usage: xvfb-run -a -s "-screen 0 1400x900x24" bench_playback
#include <benchmark/benchmark.h>

#include <QApplication>
#include <QSurfaceFormat>
#include <QTest>
#include <chrono>
#include <memory>
#include <vector>

#include "BenchmarkSupport.h"
#include "model/Document.h"
#include "pipeline/SketchToPart.h"
#include "pose/InverseKinematics.h"
#include "timeline/Playback.h"
#include "viewport/Viewport.h"

namespace rigmesh::bench {
namespace {

struct PlaybackCase {
    int targetVertices = 0;
    bool unskinned = false;  // the same mesh without its rig: llvmpipe's own cost
    std::unique_ptr<model::Document> document;
    std::unique_ptr<widgets::Viewport> viewport;
};

// The biped at about `targetVertices`, keyed at frames 0, 12 and 24 (an IK
// drag of its first end joint up, then down), smooth, the range 0..24.
std::unique_ptr<model::Document> keyedBiped(int targetVertices) {
    const std::vector<Vec2> stroke = readSketchFile(sharedSketchPath("biped")).points;
    SketchToPartOptions options;
    options.surface = optionsForVertexCount(stroke, targetVertices);
    model::PartNode node;
    node.id = 1;
    node.name = QStringLiteral("biped");
    node.part = std::make_shared<const Part>(sketchToPart(stroke, "biped", options).part);
    const Skeleton& skeleton = node.part->skeleton;
    JointId end = kNoJoint;
    for (const Joint& joint : skeleton.joints())
        if (joint.id != skeleton.root() && skeleton.degree(joint.id) == 1)
            end = joint.id;
    node.clip.interpolation = Interpolation::Smooth;
    const double size = 0.3;
    for (const auto& [time, lift] : {std::pair{0.0, 0.0}, {0.5, size}, {1.0, -size}})
        node.clip.setKey(time, dragJoint(skeleton, restPose(skeleton), end,
                                         skeleton.joint(end).position + Vec3(0, lift, 0), {})
                                   .pose);
    node.pose = node.clip.evaluate(0.0);
    model::DocumentContents contents;
    contents.parts.push_back(std::move(node));
    contents.timeline = {0, 24, 24.0};
    return std::make_unique<model::Document>(std::move(contents));
}

void setUp(PlaybackCase& c) {
    if (c.viewport)
        return;
    c.document = keyedBiped(c.targetVertices);
    if (c.unskinned) {
        model::DocumentContents contents;
        model::PartNode node = c.document->parts().front();
        Part plain = *node.part;
        plain.skeleton = Skeleton();
        plain.weights = SkinWeightsById();
        node.part = std::make_shared<const Part>(std::move(plain));
        node.clip = Clip();
        node.pose = Pose();
        contents.parts.push_back(std::move(node));
        c.document = std::make_unique<model::Document>(std::move(contents));
    }
    c.viewport = std::make_unique<widgets::Viewport>(c.document.get());
    c.viewport->resize(960, 540);
    c.viewport->show();
    if (!QTest::qWaitForWindowExposed(c.viewport.get()))
        QTest::qWait(500);
    c.viewport->frameAll();
    c.viewport->grabFramebuffer();  // the mesh is uploaded once, before timing
}

void benchFrame(benchmark::State& state, PlaybackCase* c) {
    setUp(*c);
    int frame = 0;
    for (auto _ : state) {
        const auto start = std::chrono::steady_clock::now();
        frame = (frame + 1) % 25;
        c->document->setCurrentFrame(frame);
        // Draws the frame now (paintGL into the widget's framebuffer) and
        // reads it back, which waits for the drawing to finish.
        benchmark::DoNotOptimize(c->viewport->grabFramebuffer());
        const std::chrono::duration<double> elapsed = std::chrono::steady_clock::now() - start;
        state.SetIterationTime(elapsed.count());
    }
    state.counters["vertices"] = c->document->parts().front().part->mesh.vertexCount();
}

void benchStill(benchmark::State& state, PlaybackCase* c) {
    setUp(*c);
    c->document->setCurrentFrame(6);  // posed: the vertex shader skins every vertex
    for (auto _ : state) {
        const auto start = std::chrono::steady_clock::now();
        c->viewport->update();
        benchmark::DoNotOptimize(c->viewport->grabFramebuffer());
        const std::chrono::duration<double> elapsed = std::chrono::steady_clock::now() - start;
        state.SetIterationTime(elapsed.count());
    }
}

void benchEvaluate(benchmark::State& state, PlaybackCase* c) {
    setUp(*c);
    int frame = 0;
    for (auto _ : state) {
        frame = (frame + 1) % 25;
        c->document->setCurrentFrame(frame);
        benchmark::DoNotOptimize(c->document->parts().front().pose);
    }
}

// Owned here and cleared before the QApplication goes.
std::vector<std::unique_ptr<PlaybackCase>> cases;

// Two seconds of the studio's playback (widgets/timeline/Playback) with the
// viewport drawing as the event loop lets it: frames shown and dropped per
// second (24 advance per second in real time, whatever the drawing costs).
void benchRealTime(benchmark::State& state, PlaybackCase* c) {
    setUp(*c);
    widgets::Playback playback;
    playback.setDocument(c->document.get());
    widgets::Viewport* viewport = c->viewport.get();
    const QMetaObject::Connection drawing =
        QObject::connect(c->document.get(), &model::Document::currentFrameChanged, viewport,
                         [viewport] { viewport->repaint(); });
    for (auto _ : state) {
        playback.play();
        QTest::qWait(2000);
        playback.pause();
    }
    QObject::disconnect(drawing);
    state.counters["shown_per_s"] = playback.framesShown() / 2.0;
    state.counters["dropped_per_s"] = playback.framesDropped() / 2.0;
}

void registerBenchmarks() {
    for (const int count : {10000, 50000, 100000}) {
        cases.push_back(std::make_unique<PlaybackCase>());
        cases.back()->targetVertices = count;
        PlaybackCase* rigged = cases.back().get();
        cases.push_back(std::make_unique<PlaybackCase>());
        cases.back()->targetVertices = count;
        cases.back()->unskinned = true;
        PlaybackCase* unskinned = cases.back().get();
        const std::string size = std::to_string(count / 1000) + "k";
        benchmark::RegisterBenchmark(("Playback/frame/biped/" + size).c_str(), benchFrame, rigged)
            ->UseManualTime()
            ->Unit(benchmark::kMillisecond);
        benchmark::RegisterBenchmark(("Playback/still/biped/" + size).c_str(), benchStill, rigged)
            ->UseManualTime()
            ->Unit(benchmark::kMillisecond);
        benchmark::RegisterBenchmark(("Playback/unskinned/biped/" + size).c_str(), benchStill,
                                     unskinned)
            ->UseManualTime()
            ->Unit(benchmark::kMillisecond);
        benchmark::RegisterBenchmark(("Playback/realtime/biped/" + size).c_str(), benchRealTime,
                                     rigged)
            ->Iterations(1)
            ->Unit(benchmark::kMillisecond);
        benchmark::RegisterBenchmark(("Playback/evaluate/biped/" + size).c_str(), benchEvaluate,
                                     rigged)
            ->Unit(benchmark::kMillisecond);
    }
}

}  // namespace
}  // namespace rigmesh::bench

int main(int argc, char** argv) {
    QSurfaceFormat::setDefaultFormat(rigmesh::widgets::Viewport::requiredFormat());
    QApplication app(argc, argv);
    const int status =
        rigmesh::bench::runBenchmarks(argc, argv, &rigmesh::bench::registerBenchmarks);
    rigmesh::bench::cases.clear();
    return status;
}
