// Long work off the GUI thread: a rebuild at a fine edge
// length, an export and an import run as background jobs; the GUI thread
// never works more than 50 ms without serving events meanwhile, the progress shows with Cancel,
// the document changes only when the work is done (one undo step), and a
// cancelled job leaves nothing behind.
#include <QDir>
#include <QDoubleSpinBox>
#include <QElapsedTimer>
#include <QPushButton>
#include <QTimer>
#include <cstdio>

#include "StudioFixture.h"
#include "jobs/JobRunner.h"
#include "jobs/JobStatus.h"
#include "model/DocumentFile.h"
#include "panels/PropertiesPanel.h"
#include "viewport/Viewport.h"

namespace rigmesh {
namespace {

class BackgroundJobs : public test::StudioFixture {
  protected:
    // Selects the example biped and asks the properties panel for a rebuild
    // at a sixth of its edge length (about 36 times the vertices: seconds).
    void startFineRebuild() {
        const model::PartId biped = addExampleBiped();
        document()->setSelection({biped, kNoJoint});
        QTest::qWait(20);
        auto* panel = window->propertiesPanel();
        QDoubleSpinBox* edge = nullptr;
        for (auto* box : panel->findChildren<QDoubleSpinBox*>())
            if (box->specialValueText() == QStringLiteral("automatic"))
                edge = box;
        ASSERT_NE(edge, nullptr);
        edge->setValue(part().options.targetEdgeLength / 6.0);
        QPushButton* rebuild = nullptr;
        for (auto* button : panel->findChildren<QPushButton*>())
            if (button->text() == QStringLiteral("Rebuild"))
                rebuild = button;
        ASSERT_NE(rebuild, nullptr);
        rebuild->click();
    }
    const model::PartNode& part() const { return document()->parts().front(); }
};

TEST_F(BackgroundJobs, AFineRebuildNeverStallsTheWindowAndIsOneUndoStep) {
    startFineRebuild();
    const int steps = document()->undoStack()->count();
    const int vertices = part().part->mesh.vertexCount();
    ASSERT_TRUE(window->jobs()->busy()) << "the rebuild runs in the background";
    // A timer every 5 ms: the longest gap between its ticks is the longest
    // time the event loop was away. On a machine busy with other work the
    // scheduler alone can make a gap long, so the gap is measured twice: as
    // wall time, and as the CPU time the GUI thread itself spent in it (its
    // own work: what the studio did instead of serving events).
    QElapsedTimer clock;
    clock.start();
    qint64 last = 0, longest = 0;
    double lastCpu = test::threadCpuMilliseconds(), longestCpu = 0.0;
    bool progressShown = false, documentChanged = false;
    QTimer tick;
    QObject::connect(&tick, &QTimer::timeout, [&] {
        // Only while the job runs: applying its result (the new 100k-vertex
        // part drawn for the first time) comes after.
        if (!window->jobs()->busy())
            return;
        const qint64 now = clock.elapsed();
        const double cpu = test::threadCpuMilliseconds();
        longest = std::max(longest, now - last);
        longestCpu = std::max(longestCpu, cpu - lastCpu);
        last = now;
        lastCpu = cpu;
        progressShown = progressShown || window->jobStatus()->progressShown();
        documentChanged = documentChanged ||
                          (window->jobs()->busy() && document()->undoStack()->count() != steps);
    });
    tick.start(5);
    while (window->jobs()->busy() && clock.elapsed() < 120000)
        QTest::qWait(5);
    tick.stop();
    const qint64 took = clock.elapsed();
    std::printf(
        "fine rebuild: %lld ms, longest event-loop stall %lld ms (of which %.1f ms the "
        "GUI thread's own work)\n",
        static_cast<long long>(took), static_cast<long long>(longest), longestCpu);
    EXPECT_LE(longestCpu, 50.0) << "the GUI thread worked " << longestCpu
                                << " ms without serving events during a " << took << " ms rebuild";
    // Wall time: 22-32 ms on an idle machine; with three builds running
    // beside it 112-175 ms (the X server and llvmpipe's threads wait for
    // cores too). The bound catches a blocking wait, not a busy machine.
    EXPECT_LE(longest, 1000) << "the event loop stalled " << longest << " ms";
    EXPECT_GT(took, 300) << "the rebuild is long enough to measure";
    EXPECT_TRUE(progressShown) << "the status bar showed the progress and Cancel";
    EXPECT_FALSE(documentChanged) << "nothing changes before the work is done";
    QTest::qWait(20);
    EXPECT_EQ(document()->undoStack()->count(), steps + 1) << "one undo step";
    EXPECT_GT(part().part->mesh.vertexCount(), 10 * vertices);
    EXPECT_FALSE(window->jobStatus()->progressShown());
}

TEST_F(BackgroundJobs, TheChosenMouseBindingsNavigateWhileAJobRunsAndToolsWait) {
    widgets::StudioPreferences maya = window->preferences();
    maya.mouseBindings = widgets::MouseBindings::Maya;
    window->applyPreferences(maya);
    startFineRebuild();
    ASSERT_TRUE(window->jobs()->busy());
    const QByteArray before = model::DocumentFile::toBytes(*document());
    widgets::Viewport* view = window->currentView()->viewport();
    const QPointF middle(view->width() / 2.0, view->height() / 2.0);
    auto leftDrag = [&](Qt::KeyboardModifiers modifiers) {
        test::buttonDrag(view, Qt::LeftButton, middle, middle + QPointF(60, 20), modifiers);
    };
    // Maya's Alt + left drag orbits while the job runs.
    const QVector3D eye = view->camera().eye();
    leftDrag(Qt::AltModifier);
    EXPECT_GT((view->camera().eye() - eye).length(), 0.01f);
    EXPECT_FALSE(view->navigating());
    // A plain left drag is the tool's: it waits, the part stays.
    window->activateTool<widgets::SelectTool>();
    leftDrag(Qt::NoModifier);
    EXPECT_TRUE(window->jobs()->busy());
    EXPECT_EQ(model::DocumentFile::toBytes(*document()), before);
    test::waitForJobs();
    widgets::StudioPreferences blender = maya;
    blender.mouseBindings = widgets::MouseBindings::Blender;
    window->applyPreferences(blender);  // kept in QSettings: the next tests' default again
}

TEST_F(BackgroundJobs, CancellingARebuildLeavesTheDocumentAsItWas) {
    startFineRebuild();
    ASSERT_TRUE(window->jobs()->busy());
    const QByteArray before = model::DocumentFile::toBytes(*document());
    const int steps = document()->undoStack()->count();
    QTest::qWait(150);
    ASSERT_TRUE(window->jobStatus()->progressShown());
    window->jobStatus()->cancelButton()->click();
    EXPECT_FALSE(window->jobs()->busy()) << "the studio is back at once";
    // The worker finishes on its own; its result is dropped.
    QTest::qWait(6000);
    EXPECT_EQ(document()->undoStack()->count(), steps);
    EXPECT_EQ(model::DocumentFile::toBytes(*document()), before);
    // The studio takes edits again: a key press reaches the window.
    document()->undoStack()->undo();
    EXPECT_EQ(document()->partCount(), 0);
}

TEST_F(BackgroundJobs, ExportAndImportRunAsJobsAndACancelledExportWritesNothing) {
    addExampleBiped();
    QTemporaryDir folder;
    ASSERT_TRUE(folder.isValid());
    const QString path = folder.filePath(QStringLiteral("biped.glb"));
    window->exchange()->exportTo(path, ExportOptions{});
    EXPECT_TRUE(window->jobs()->busy());
    test::waitForJobs();
    EXPECT_TRUE(QFileInfo::exists(path));
    EXPECT_EQ(QDir(folder.path()).entryList(QDir::AllEntries | QDir::Hidden | QDir::NoDotAndDotDot),
              QStringList{QStringLiteral("biped.glb")})
        << "no staging folder left";
    // A cancelled export: no file, and no staging folder once the worker ends.
    const QString cancelled = folder.filePath(QStringLiteral("cancelled.fbx"));
    window->exchange()->exportTo(cancelled, ExportOptions{});
    window->jobs()->cancel();
    QTest::qWait(3000);
    EXPECT_FALSE(QFileInfo::exists(cancelled));
    EXPECT_EQ(QDir(folder.path()).entryList(QDir::AllEntries | QDir::Hidden | QDir::NoDotAndDotDot),
              QStringList{QStringLiteral("biped.glb")});
    // The import of what was written: one step, one more part.
    const int parts = document()->partCount();
    window->exchange()->importPath(path);
    EXPECT_TRUE(window->jobs()->busy());
    test::waitForJobs();
    EXPECT_EQ(document()->partCount(), parts + 1);
}

}  // namespace
}  // namespace rigmesh
