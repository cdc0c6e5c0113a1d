// The Sketch tool's live preview: while a stroke is drawn its part inflates
// under the pen, built on a worker (jobs/SketchPreviewBuilder.h) at most
// every 33 ms; the GUI thread's own work per event stays within 8 ms; the
// release commits the part last shown as one undo step. Open strokes and
// strokes the engine refuses show nothing and say nothing until released.
#include <gtest/gtest.h>

#include <QStatusBar>
#include <QTimer>
#include <algorithm>
#include <cstdio>

#include "StudioFixture.h"
#include "jobs/SketchPreviewBuilder.h"
#include "model/PartBuilder.h"
#include "sketch/PolygonGeometry.h"

namespace rigmesh {
namespace {

class SketchPreviewStudio : public test::StudioFixture {
  protected:
    void SetUp() override {
        StudioFixture::SetUp();
        window->activateTool<widgets::SketchTool>();
    }
    widgets::DocumentView* view() const { return window->currentView(); }
    widgets::SketchPreviewBuilder* builder() const { return view()->sketchPreviewBuilder(); }
    // Lets the worker finish what it was asked and its result show.
    void waitForPreview() const {
        test::waitWhile([this] { return builder()->busy(); }, 60000);
    }
    // A shared sketch drawn on screen as a pen would: `count` points at equal
    // steps along its outline (the last one a step short of the first),
    // `height` pixels tall around the viewport's centre.
    std::vector<QPointF> penPath(const std::string& name, int count, double height) const {
        const Polyline2 outline =
            readSketchFile(std::string(RIGMESH_SHARED_SKETCHES) + "/" + name + ".json").points;
        const Polyline2 samples = resampleClosed(outline, static_cast<std::size_t>(count));
        Vec2 low = samples.front(), high = low;
        for (const Vec2& p : samples) {
            low = low.cwiseMin(p);
            high = high.cwiseMax(p);
        }
        const double scale = height / (high.y() - low.y());
        const Vec2 middle = (low + high) / 2.0;
        const QPointF centre(viewport()->width() / 2.0, viewport()->height() / 2.0);
        std::vector<QPointF> path;
        for (const Vec2& p : samples)  // screen y runs down
            path.emplace_back(centre.x() + scale * (p.x() - middle.x()),
                              centre.y() - scale * (p.y() - middle.y()));
        return path;
    }
    void press(const QPointF& at) {
        viewport()->setFocus(Qt::MouseFocusReason);
        test::sendMouse(viewport(), QEvent::MouseButtonPress, at, Qt::LeftButton, Qt::LeftButton);
    }
    void moveTo(const QPointF& at) {
        test::sendMouse(viewport(), QEvent::MouseMove, at, Qt::NoButton, Qt::LeftButton);
    }
    void release(const QPointF& at) {
        test::sendMouse(viewport(), QEvent::MouseButtonRelease, at, Qt::LeftButton, Qt::NoButton);
    }
    QString status() const { return window->statusBar()->currentMessage(); }
};

// Notes when a queued call to qApp (a worker's result coming back) starts.
class ResultCallStart : public QObject {
  public:
    explicit ResultCallStart(double& start) : start_(start) {}
    bool eventFilter(QObject* watched, QEvent* event) override {
        if (watched == qApp && event->type() == QEvent::MetaCall)
            start_ = test::threadCpuMilliseconds();
        return false;
    }

  private:
    double& start_;
};

double largestVertexDistance(const Part& a, const Part& b) {
    if (a.mesh.vertexCount() != b.mesh.vertexCount())
        return INFINITY;
    double largest = 0.0;
    for (int v = 0; v < a.mesh.vertexCount(); ++v)
        largest = std::max(largest, (a.mesh.vertices[v] - b.mesh.vertices[v]).norm());
    return largest;
}

TEST_F(SketchPreviewStudio, APartInflatesUnderThePenWithin8msOfGuiWorkAndReleaseCommitsIt) {
    // The pen: a press and 200 moves along the biped's outline, one every
    // 4 ms (a 250 Hz mouse) from the event loop, as a person's arrive.
    const std::vector<QPointF> path = penPath("biped", 201, 500.0);
    const int steps = document()->undoStack()->count();
    press(path.front());
    // The GUI thread's own work (CPU time, so that other engineers' builds
    // on the same cores do not count): each mouse move's handling, and each
    // build's result handed back and shown (from the start of its queued
    // call, seen by a filter on qApp, to the end of the `built` signal,
    // after the document view's slot showed it).
    double longestMove = 0.0, longestResult = 0.0, resultStart = 0.0;
    int builds = 0, shownChanges = 0;
    ResultCallStart filter(resultStart);
    qApp->installEventFilter(&filter);
    QObject::connect(builder(), &widgets::SketchPreviewBuilder::built, &filter, [&] {
        ++builds;
        longestResult = std::max(longestResult, test::threadCpuMilliseconds() - resultStart);
    });
    QObject::connect(document(), &model::Document::partInserted, &filter, [&] { ++shownChanges; });
    QObject::connect(document(), &model::Document::partChanged, &filter, [&] { ++shownChanges; });
    // For comparison, not held to 8 ms: the longest turn of the event loop,
    // which includes the 3D view's paint (Mesa's software OpenGL under
    // Xvfb: tens of milliseconds with or without a preview).
    double longestTurn = 0.0, lastTurn = test::threadCpuMilliseconds();
    QElapsedTimer clock;
    clock.start();
    std::size_t next = 1;
    QTimer pen;
    QObject::connect(&pen, &QTimer::timeout, [&] {
        if (next >= path.size())
            return;
        const double before = test::threadCpuMilliseconds();
        moveTo(path[next++]);
        longestMove = std::max(longestMove, test::threadCpuMilliseconds() - before);
    });
    QTimer turns;
    QObject::connect(&turns, &QTimer::timeout, [&] {
        const double now = test::threadCpuMilliseconds();
        longestTurn = std::max(longestTurn, now - lastTurn);
        lastTurn = now;
    });
    pen.start(4);
    turns.start(0);
    while (next < path.size() && clock.elapsed() < 60000)
        QTest::qWait(2);
    const qint64 drawing = clock.elapsed();
    waitForPreview();
    turns.stop();
    pen.stop();
    qApp->removeEventFilter(&filter);
    std::printf(
        "live sketch: 200 moves in %lld ms, %d builds handed back, %d shown; the GUI thread's "
        "longest move %.2f ms, longest result shown %.2f ms, longest event-loop turn with "
        "paints %.2f ms (CPU)\n",
        static_cast<long long>(drawing), builds, shownChanges, longestMove, longestResult,
        longestTurn);
    EXPECT_LE(longestMove, 8.0);
    EXPECT_LE(longestResult, 8.0);
    EXPECT_GE(shownChanges, 1) << "the part showed before the release";
    EXPECT_LE(builds, clock.elapsed() / widgets::SketchPreviewBuilder::kMinimumIntervalMs + 1)
        << "at most one build every 33 ms";
    EXPECT_EQ(document()->undoStack()->count(), steps) << "a preview is no undo step";

    const model::PartId previewed = view()->sketchPreviewPart();
    ASSERT_NE(previewed, model::kNoPart);
    ASSERT_EQ(document()->partCount(), 1);
    const std::shared_ptr<const Part> shown = document()->part(previewed).part;
    EXPECT_GE(shown->skeleton.boneCount(), 5) << "arms, legs and head";
    EXPECT_FALSE(shown->weights.perVertex.empty());
    viewport()->update();
    QTest::qWait(50);
    window->grab().save(QStringLiteral(RIGMESH_TEST_OUTPUT "/tool_sketch_preview.png"));

    release(path.back());
    test::waitForJobs();
    ASSERT_EQ(document()->partCount(), 1);
    EXPECT_EQ(document()->undoStack()->count(), steps + 1) << "one undo step";
    const model::PartNode& node = document()->parts().front();
    EXPECT_EQ(node.id, previewed);
    EXPECT_LE(largestVertexDistance(*node.part, *shown), 1e-9);
    EXPECT_EQ(node.part->skeleton.jointCount(), shown->skeleton.jointCount());
    EXPECT_EQ(document()->selection().part, node.id);
    document()->undoStack()->undo();
    EXPECT_EQ(document()->partCount(), 0);
    document()->undoStack()->redo();
    ASSERT_EQ(document()->partCount(), 1);
    EXPECT_LE(largestVertexDistance(*document()->parts().front().part, *shown), 1e-9);
}

TEST_F(SketchPreviewStudio, AReleaseBeforeThePreviewIsBuiltCommitsTheStrokesPartOnce) {
    const std::vector<QPointF> path = penPath("camel_body", 120, 400.0);
    press(path.front());
    for (std::size_t i = 1; i < path.size(); ++i)
        moveTo(path[i]);
    release(path.back());
    test::waitForJobs();
    waitForPreview();
    QTest::qWait(100);  // a late preview result would show now: none may
    ASSERT_EQ(document()->partCount(), 1) << status().toStdString();
    EXPECT_EQ(document()->undoStack()->count(), 1);
    EXPECT_EQ(view()->sketchPreviewPart(), model::kNoPart);
    // The part is the stroke's, as a build from scratch makes it.
    const model::PartNode& node = document()->parts().front();
    model::BuildOptions asked;
    asked.targetEdgeLength = view()->defaultEdgeLength();
    const model::BuiltPart fresh =
        model::buildPartAtDocumentLength(0.0, node.stroke, node.name, asked);
    EXPECT_LE(largestVertexDistance(*node.part, *fresh.part), 1e-9);
}

TEST_F(SketchPreviewStudio, AnOpenStrokeShowsNoPartUntilItComesBackToItsStart) {
    const std::vector<QPointF> path = penPath("banana", 100, 400.0);
    press(path.front());
    for (std::size_t i = 1; i < 60; ++i)
        moveTo(path[i]);
    waitForPreview();
    EXPECT_EQ(document()->partCount(), 0) << "60% of the outline: still open";
    for (std::size_t i = 60; i < path.size(); ++i)
        moveTo(path[i]);
    waitForPreview();
    EXPECT_EQ(document()->partCount(), 1) << "back at its start: the part shows";
    // Esc ends the stroke: its preview goes and nothing was done.
    QTest::keyClick(viewport(), Qt::Key_Escape);
    EXPECT_EQ(document()->partCount(), 0);
    EXPECT_EQ(document()->undoStack()->count(), 0);
    EXPECT_EQ(document()->nextPartId(), 1u);
}

TEST_F(SketchPreviewStudio, ACrossingStrokeShowsNothingAndSaysWhyOnlyOnRelease) {
    const std::vector<QPointF> path = penPath("bad_figure_eight", 150, 300.0);
    window->statusBar()->clearMessage();
    press(path.front());
    for (std::size_t i = 1; i < path.size(); ++i)
        moveTo(path[i]);
    waitForPreview();
    EXPECT_EQ(document()->partCount(), 0);
    EXPECT_TRUE(status().isEmpty()) << status().toStdString();
    release(path.back());
    test::waitForJobs();
    EXPECT_EQ(document()->partCount(), 0);
    EXPECT_EQ(document()->undoStack()->count(), 0);
    EXPECT_TRUE(status().contains(QStringLiteral("crosses itself"))) << status().toStdString();
}

}  // namespace
}  // namespace rigmesh
