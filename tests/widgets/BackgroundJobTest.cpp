// Long work off the GUI thread (issue 16 item 3): a rebuild at a fine edge
// length, an export and an import run as background jobs; the event loop
// never stalls more than 50 ms meanwhile, the progress shows with Cancel,
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
    // time the event loop was away.
    QElapsedTimer clock;
    clock.start();
    qint64 last = 0, longest = 0;
    bool progressShown = false, documentChanged = false;
    QTimer tick;
    QObject::connect(&tick, &QTimer::timeout, [&] {
        // Only while the job runs: applying its result (the new 100k-vertex
        // part drawn for the first time) comes after.
        if (!window->jobs()->busy())
            return;
        const qint64 now = clock.elapsed();
        longest = std::max(longest, now - last);
        last = now;
        progressShown = progressShown || window->jobStatus()->progressShown();
        documentChanged = documentChanged ||
                          (window->jobs()->busy() && document()->undoStack()->count() != steps);
    });
    tick.start(5);
    while (window->jobs()->busy() && clock.elapsed() < 120000)
        QTest::qWait(5);
    tick.stop();
    const qint64 took = clock.elapsed();
    std::printf("fine rebuild: %lld ms, longest event-loop stall %lld ms\n",
                static_cast<long long>(took), static_cast<long long>(longest));
    EXPECT_LE(longest, 50) << "the event loop stalled " << longest << " ms during a " << took
                           << " ms rebuild";
    EXPECT_GT(took, 300) << "the rebuild is long enough to measure";
    EXPECT_TRUE(progressShown) << "the status bar showed the progress and Cancel";
    EXPECT_FALSE(documentChanged) << "nothing changes before the work is done";
    QTest::qWait(20);
    EXPECT_EQ(document()->undoStack()->count(), steps + 1) << "one undo step";
    EXPECT_GT(part().part->mesh.vertexCount(), 10 * vertices);
    EXPECT_FALSE(window->jobStatus()->progressShown());
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
    window->exportTo(path, ExportOptions{});
    EXPECT_TRUE(window->jobs()->busy());
    test::waitForJobs();
    EXPECT_TRUE(QFileInfo::exists(path));
    EXPECT_EQ(QDir(folder.path()).entryList(QDir::AllEntries | QDir::Hidden | QDir::NoDotAndDotDot),
              QStringList{QStringLiteral("biped.glb")})
        << "no staging folder left";
    // A cancelled export: no file, and no staging folder once the worker ends.
    const QString cancelled = folder.filePath(QStringLiteral("cancelled.fbx"));
    window->exportTo(cancelled, ExportOptions{});
    window->jobs()->cancel();
    QTest::qWait(3000);
    EXPECT_FALSE(QFileInfo::exists(cancelled));
    EXPECT_EQ(QDir(folder.path()).entryList(QDir::AllEntries | QDir::Hidden | QDir::NoDotAndDotDot),
              QStringList{QStringLiteral("biped.glb")});
    // The import of what was written: one step, one more part.
    const int parts = document()->partCount();
    window->importPath(path);
    EXPECT_TRUE(window->jobs()->busy());
    test::waitForJobs();
    EXPECT_EQ(document()->partCount(), parts + 1);
}

}  // namespace
}  // namespace rigmesh
