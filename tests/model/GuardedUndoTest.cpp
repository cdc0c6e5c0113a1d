// model/GuardedUndo: a command whose redo() or undo() throws half-way
// leaves the document as it was and the undo stack consistent with it.
#include <QSignalSpy>
#include <stdexcept>

#include "ModelTestSupport.h"
#include "ThrowingCommand.h"
#include "base/Error.h"
#include "model/GuardedUndo.h"
#include "model/PoseChange.h"
#include "model/commands/RenamePartCommand.h"
#include "model/commands/ResetPoseCommand.h"

namespace rigmesh::model::test {
namespace {

using rigmesh::test::kBrokenOnPurpose;
using rigmesh::test::ThrowingCommand;
using Throws = ThrowingCommand::Throws;

// Everything a failed change must leave as it was.
struct DocumentState {
    QByteArray bytes;
    PartId nextPartId = 0;
    Selection selection;
    std::vector<PartId> order;
    bool modified = false;

    explicit DocumentState(const Document& document)
        : bytes(bytesOf(document)),
          nextPartId(document.nextPartId()),
          selection(document.selection()),
          modified(document.isModified()) {
        for (const PartNode& node : document.parts())
            order.push_back(node.id);
    }
    friend bool operator==(const DocumentState&, const DocumentState&) = default;
};

// Two parts, the second selected, and a rename on the stack.
struct TwoParts {
    Document document;
    PartId first = addPart(document, testStrokes()[0], QStringLiteral("Body"));
    PartId second = addPart(document, testStrokes()[1], QStringLiteral("Arm"));
    TwoParts() {
        pushCommand(document,
                    std::make_unique<RenamePartCommand>(document, first, QStringLiteral("Torso")));
        document.setSelection({second, kNoJoint});
    }
};

template <typename Change>
void expectLogicError(Change&& change) {
    try {
        change();
        ADD_FAILURE() << "nothing thrown";
    } catch (const std::logic_error& error) {
        EXPECT_STREQ(error.what(), kBrokenOnPurpose);
    }
}

TEST(GuardedUndo, PushWhoseRedoThrowsLeavesDocumentAndHistoryAsTheyWere) {
    TwoParts scene;
    Document& document = scene.document;
    const DocumentState before(document);
    const int count = document.undoStack()->count();
    expectLogicError([&] {
        pushCommand(document, std::make_unique<ThrowingCommand>(
                                  document, scene.first, QStringLiteral("New"), Throws::OnRedo));
    });
    EXPECT_EQ(DocumentState(document), before);
    EXPECT_EQ(document.part(scene.first).name, QStringLiteral("Torso"));
    EXPECT_EQ(document.undoStack()->count(), count);
    EXPECT_EQ(document.undoStack()->index(), count);
    // The history still works from there.
    undoCommand(document);
    EXPECT_EQ(document.part(scene.first).name, QStringLiteral("Body"));
}

TEST(GuardedUndo, PushWhoseRedoThrowsAnErrorLeavesTheDocumentAsItWas) {
    TwoParts scene;
    Document& document = scene.document;
    const DocumentState before(document);
    // A refusal half-way: a part removed, then an unknown part renamed.
    struct Refused : QUndoCommand {
        Document& document;
        PartId removed;
        Refused(Document& d, PartId id) : document(d), removed(id) {}
        void redo() override {
            document.removePart(removed);
            document.setName(removed, QStringLiteral("gone"));
        }
    };
    EXPECT_THROW(pushCommand(document, std::make_unique<Refused>(document, scene.second)), Error);
    EXPECT_EQ(DocumentState(document), before);
    EXPECT_EQ(document.selection().part, scene.second);
}

TEST(GuardedUndo, UndoThatThrowsPutsTheDocumentBackAndClearsTheHistoryKeepingItModified) {
    TwoParts scene;
    Document& document = scene.document;
    pushCommand(document, std::make_unique<ThrowingCommand>(document, scene.first,
                                                            QStringLiteral("New"), Throws::OnUndo));
    const DocumentState before(document);
    ASSERT_TRUE(document.isModified());
    QSignalSpy modified(&document, &Document::modifiedChanged);
    expectLogicError([&] { undoCommand(document); });
    EXPECT_EQ(DocumentState(document), before);
    EXPECT_EQ(document.part(scene.first).name, QStringLiteral("New"));
    // The command that failed cannot be undone, nor anything below it.
    EXPECT_EQ(document.undoStack()->count(), 0);
    EXPECT_TRUE(document.isModified());
    EXPECT_EQ(modified.count(), 0);
}

TEST(GuardedUndo, RedoThatThrowsPutsTheDocumentBackAndDropsTheStepsFromThere) {
    TwoParts scene;
    Document& document = scene.document;
    pushCommand(document, std::make_unique<ThrowingCommand>(
                              document, scene.first, QStringLiteral("New"), Throws::OnLaterRedo));
    pushCommand(document,
                std::make_unique<RenamePartCommand>(document, scene.second, QStringLiteral("Leg")));
    undoCommand(document);
    undoCommand(document);
    const int index = document.undoStack()->index();
    const DocumentState before(document);
    expectLogicError([&] { redoCommand(document); });
    EXPECT_EQ(DocumentState(document), before);
    EXPECT_EQ(document.part(scene.first).name, QStringLiteral("Torso"));
    EXPECT_EQ(document.undoStack()->index(), index);
    EXPECT_EQ(document.undoStack()->count(), index);  // nothing left to redo
    EXPECT_FALSE(document.undoStack()->canRedo());
    // The steps before it are still there.
    undoCommand(document);
    EXPECT_EQ(document.part(scene.first).name, QStringLiteral("Body"));
}

TEST(GuardedUndo, HistoryJumpStopsAtTheStepThatThrowsWithTheStepsBeforeItDone) {
    TwoParts scene;
    Document& document = scene.document;
    const int start = document.undoStack()->index();
    pushCommand(document,
                std::make_unique<RenamePartCommand>(document, scene.second, QStringLiteral("Leg")));
    pushCommand(document, std::make_unique<ThrowingCommand>(
                              document, scene.first, QStringLiteral("New"), Throws::OnLaterRedo));
    pushCommand(document, std::make_unique<RenamePartCommand>(document, scene.second,
                                                              QStringLiteral("Tail")));
    moveToUndoIndex(document, start);
    EXPECT_EQ(document.part(scene.second).name, QStringLiteral("Arm"));
    expectLogicError([&] { moveToUndoIndex(document, start + 3); });
    EXPECT_EQ(document.undoStack()->index(), start + 1);
    EXPECT_EQ(document.undoStack()->count(), start + 1);
    EXPECT_EQ(document.part(scene.second).name, QStringLiteral("Leg"));
    EXPECT_EQ(document.part(scene.first).name, QStringLiteral("Torso"));
    EXPECT_EQ(document.partCount(), 2);
}

TEST(GuardedUndo, AutoKeyedPoseChangeWhoseCommandThrowsLeavesNoStep) {
    TwoParts scene;
    Document& document = scene.document;
    document.setAutoKey(true);
    const DocumentState before(document);
    const int count = document.undoStack()->count();
    expectLogicError([&] {
        pushPoseChange(
            document, scene.first,
            new ThrowingCommand(document, scene.first, QStringLiteral("New"), Throws::OnRedo));
    });
    EXPECT_EQ(DocumentState(document), before);
    EXPECT_EQ(document.undoStack()->count(), count);
    EXPECT_EQ(document.undoStack()->index(), count);
    // A pose change that works still keys as one step.
    pushPoseChange(document, scene.first, new ResetPoseCommand(document, scene.first));
    EXPECT_EQ(document.undoStack()->count(), count + 1);
}

}  // namespace
}  // namespace rigmesh::model::test
