// Autosave: a recovery file appears a delay after a change, disappears when
// the document is saved, undone to its saved state or closed cleanly, and is
// listed (and readable) when left behind.
#include <QFileInfo>
#include <QSignalSpy>
#include <QTest>

#include "ModelTestSupport.h"
#include "model/Autosave.h"
#include "model/commands/RenamePartCommand.h"
#include "model/preview/PlacementPreview.h"

namespace rigmesh::model::test {
namespace {

TEST(Autosave, WritesAfterAChangeAndRemovesAfterSave) {
    QTemporaryDir dir;
    const QString recovery = dir.filePath(QStringLiteral("recovery"));
    Document document;
    Autosave autosave(&document, recovery);
    autosave.setDelay(20);
    QSignalSpy written(&autosave, &Autosave::written);

    const PartId id = addPart(document, testStrokes()[0], QStringLiteral("Draft"));
    EXPECT_FALSE(autosave.hasRecoveryFile());  // not at once: a delay after the change
    ASSERT_TRUE(QTest::qWaitFor([&] { return autosave.hasRecoveryFile(); }, 5000));
    EXPECT_EQ(written.count(), 1);

    const QList<RecoveryFile> left = Autosave::recoveryFiles(recovery);
    ASSERT_EQ(left.size(), 1);
    EXPECT_EQ(QFileInfo(left[0].path), QFileInfo(autosave.recoveryFilePath()));
    const DocumentContents recovered = DocumentFile::read(left[0].path);
    ASSERT_EQ(recovered.parts.size(), 1u);
    EXPECT_EQ(recovered.parts[0].name, QStringLiteral("Draft"));

    // Saving removes it.
    DocumentFile::save(document, dir.filePath(QStringLiteral("doc.rigmesh")));
    EXPECT_FALSE(autosave.hasRecoveryFile());
    EXPECT_TRUE(Autosave::recoveryFiles(recovery).isEmpty());

    // A new change writes again; undoing back to the saved state removes it.
    document.undoStack()->push(new RenamePartCommand(document, id, QStringLiteral("Final")));
    ASSERT_TRUE(QTest::qWaitFor([&] { return autosave.hasRecoveryFile(); }, 5000));
    document.undoStack()->undo();
    EXPECT_FALSE(autosave.hasRecoveryFile());
}

TEST(Autosave, RestartsTheDelayOnEachChange) {
    QTemporaryDir dir;
    Document document;
    Autosave autosave(&document, dir.path());
    autosave.setDelay(300);
    const PartId id = addPart(document, testStrokes()[0]);
    for (int i = 0; i < 4; ++i) {
        QTest::qWait(100);
        document.undoStack()->push(new RenamePartCommand(document, id, QString::number(i)));
    }
    EXPECT_FALSE(autosave.hasRecoveryFile());  // 400 ms of edits, never 300 ms quiet
    ASSERT_TRUE(QTest::qWaitFor([&] { return autosave.hasRecoveryFile(); }, 5000));
}

TEST(Autosave, CleanCloseRemovesTheFileAndACrashLeavesIt) {
    QTemporaryDir dir;
    QString leftBehind;
    {
        Document document;
        Autosave autosave(&document, dir.path());
        addPart(document, testStrokes()[0]);
        ASSERT_TRUE(autosave.writeNow());
        EXPECT_TRUE(autosave.hasRecoveryFile());
        leftBehind = autosave.recoveryFilePath();
    }  // closed cleanly
    EXPECT_FALSE(QFileInfo::exists(leftBehind));

    // A crash: nothing removes the file (simulated by writing it directly).
    Document crashed;
    addPart(crashed, testStrokes()[1], QStringLiteral("Lost"));
    const QString path = dir.filePath(QStringLiteral("untitled-crash.") + Autosave::kSuffix);
    DocumentFile::write(crashed, path);
    const QList<RecoveryFile> files = Autosave::recoveryFiles(dir.path());
    ASSERT_EQ(files.size(), 1);
    auto restored = std::make_unique<Document>(DocumentFile::read(files[0].path));
    EXPECT_EQ(restored->parts()[0].name, QStringLiteral("Lost"));
}

// A drag shows its placement on the document before it is an undo step: a
// recovery file written then would hold a half-done gesture. The write
// waits until the preview ends, and then holds what the undo stack holds.
TEST(Autosave, WaitsWhileAPreviewIsShownAndThenWritesTheCommittedState) {
    QTemporaryDir dir;
    Document document;
    Autosave autosave(&document, dir.path());
    autosave.setDelay(20);
    const PartId id = addPart(document, testStrokes()[0], QStringLiteral("Draft"));
    ASSERT_TRUE(autosave.writeNow());

    document.undoStack()->push(new RenamePartCommand(document, id, QStringLiteral("Renamed")));
    Placement dragged;
    dragged.translation = Vec3(3.0, 0.0, 0.0);
    {
        PlacementPreview drag(document, id);
        drag.preview(dragged);
        EXPECT_TRUE(hasLivePreview(document));
        QTest::qWait(200);  // ten delays: the write keeps waiting
        const DocumentContents during = DocumentFile::read(autosave.recoveryFilePath());
        EXPECT_EQ(during.parts[0].name, QStringLiteral("Draft"));
        EXPECT_EQ(during.parts[0].placement, Placement());
    }  // released without a commit: reverted
    EXPECT_FALSE(hasLivePreview(document));
    ASSERT_TRUE(QTest::qWaitFor(
        [&] {
            return DocumentFile::read(autosave.recoveryFilePath()).parts[0].name ==
                   QStringLiteral("Renamed");
        },
        5000));
    EXPECT_EQ(DocumentFile::read(autosave.recoveryFilePath()).parts[0].placement, Placement());

    // A committed drag is written a delay after its undo step.
    {
        PlacementPreview drag(document, id);
        drag.preview(dragged);
        ASSERT_TRUE(drag.commit());
        EXPECT_FALSE(hasLivePreview(document));
    }
    ASSERT_TRUE(QTest::qWaitFor(
        [&] {
            return DocumentFile::read(autosave.recoveryFilePath()).parts[0].placement == dragged;
        },
        5000));
}

TEST(Autosave, UnmodifiedDocumentWritesNothing) {
    QTemporaryDir dir;
    Document document;
    Autosave autosave(&document, dir.path());
    EXPECT_TRUE(autosave.writeNow());
    EXPECT_FALSE(autosave.hasRecoveryFile());
}

}  // namespace
}  // namespace rigmesh::model::test
