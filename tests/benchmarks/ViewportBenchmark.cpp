// Frame times of the studio's viewport with a 50k-triangle part (the
// weight views colour on the GPU, so they should cost no more
// than the plain view). One frame = paintGL into the widget's framebuffer
// plus reading it back (QOpenGLWidget::grabFramebuffer), at 1200 x 800 under
// Xvfb with Mesa llvmpipe: an upper bound of what the screen shows.
#include <benchmark/benchmark.h>

#include <QApplication>
#include <QSurfaceFormat>
#include <QTemporaryDir>
#include <QTest>
#include <memory>

#include "BenchmarkSupport.h"
#include "DocumentView.h"
#include "MainWindow.h"
#include "model/Document.h"
#include "pipeline/SketchToPart.h"
#include "viewport/Viewport.h"

namespace rigmesh {
namespace {

constexpr int kTriangles = 50000;

struct Studio {
    QTemporaryDir recovery;
    std::unique_ptr<widgets::MainWindow> window;
    widgets::Viewport* viewport = nullptr;
    int triangles = 0;
};

std::unique_ptr<Studio>& studioSlot() {
    static std::unique_ptr<Studio> slot;
    return slot;
}

Studio& studio() {
    std::unique_ptr<Studio>& slot = studioSlot();
    if (!slot) {
        slot = std::make_unique<Studio>();
        Studio& s = *slot;
        const std::vector<Vec2> stroke = readSketchFile(bench::sharedSketchPath("biped")).points;
        SketchToPartOptions options;
        // A closed surface has about twice as many triangles as vertices.
        options.surface = bench::optionsForVertexCount(stroke, kTriangles / 2);
        auto document = std::make_unique<model::Document>();
        model::PartNode node;
        node.id = document->allocatePartId();
        node.name = QStringLiteral("biped");
        node.part = std::make_shared<const Part>(sketchToPart(stroke, "biped", options).part);
        s.triangles = node.part->mesh.faceCount();
        const Skeleton& skeleton = node.part->skeleton;
        const JointId joint = skeleton.bones().front().tail;
        document->insertPart(0, node);
        document->setSelection({node.id, joint});
        s.window = std::make_unique<widgets::MainWindow>(s.recovery.path());
        s.window->resize(1200, 800);
        s.window->addDocument(std::move(document));
        s.window->show();
        if (!QTest::qWaitForWindowExposed(s.window.get()))
            QTest::qWait(500);
        s.viewport = s.window->currentView()->viewport();
        s.viewport->frameAll();
    }
    return *slot;
}

void BM_Frame(benchmark::State& state) {
    Studio& s = studio();
    s.viewport->setWeightView(static_cast<widgets::WeightView>(state.range(0)));
    benchmark::DoNotOptimize(s.viewport->grabFramebuffer());  // uploads, first-use buffers
    for (auto _ : state)
        benchmark::DoNotOptimize(s.viewport->grabFramebuffer());
    state.counters["triangles"] = s.triangles;
    state.counters["pixels"] = s.viewport->width() * s.viewport->height();
}

BENCHMARK(BM_Frame)
    ->Name("Viewport/frame/biped/50kTriangles")
    ->ArgName("weightView")
    ->DenseRange(static_cast<int>(widgets::WeightView::Off),
                 static_cast<int>(widgets::WeightView::GlobalDifference))
    ->Unit(benchmark::kMillisecond)
    ->UseRealTime();

}  // namespace
}  // namespace rigmesh

int main(int argc, char** argv) {
    QSurfaceFormat::setDefaultFormat(rigmesh::widgets::Viewport::requiredFormat());
    QApplication application(argc, argv);
    const int result = rigmesh::bench::runBenchmarks(argc, argv, [] {});
    rigmesh::studioSlot().reset();
    return result;
}
