// Each command on its own: what it changes, its undo, its text, merging and
// the "nothing pushed on a bad stroke" rule.
#include <QSignalSpy>

#include "ModelTestSupport.h"
#include "base/Error.h"
#include "model/commands/DeletePartCommand.h"
#include "model/commands/MovePartCommand.h"
#include "model/commands/RebuildPartCommand.h"
#include "model/commands/RenamePartCommand.h"
#include "model/commands/SetPartVisibleCommand.h"
#include "model/preview/PlacementPreview.h"

namespace rigmesh::model::test {
namespace {

Placement movedBy(const Placement& p, double dx) {
    Placement out = p;
    out.translation.x() += dx;
    return out;
}

TEST(Commands, CreateBuildsARiggedPartWithAFreshId) {
    Document document;
    QSignalSpy inserted(&document, &Document::partInserted);
    const PartId first = addPart(document, testStrokes()[0], QStringLiteral("Body"));
    const PartId second = addPart(document, testStrokes()[1]);
    EXPECT_NE(first, second);
    ASSERT_EQ(document.partCount(), 2);
    EXPECT_EQ(inserted.count(), 2);
    const PartNode& node = document.part(first);
    EXPECT_EQ(node.name, QStringLiteral("Body"));
    ASSERT_TRUE(node.part);
    EXPECT_GT(node.part->mesh.vertexCount(), 0);
    EXPECT_GT(node.part->skeleton.jointCount(), 0);
    EXPECT_EQ(node.stroke, testStrokes()[0]);
    EXPECT_EQ(document.part(second).name, QStringLiteral("Part %1").arg(second));
    EXPECT_EQ(document.undoStack()->text(0), QStringLiteral("Create Body"));
    EXPECT_TRUE(document.isModified());

    document.undoStack()->undo();
    EXPECT_FALSE(document.contains(second));
    document.undoStack()->undo();
    EXPECT_EQ(document.partCount(), 0);
    EXPECT_FALSE(document.isModified());
    EXPECT_EQ(document.nextPartId(), 1u);  // undo restores the counter exactly
    document.undoStack()->redo();
    EXPECT_EQ(document.part(first).name, QStringLiteral("Body"));
}

TEST(Commands, IdsAreNotReusedWhileTheirPartOrCommandLives) {
    Document document;
    const PartId a = addPart(document, testStrokes()[0]);
    document.undoStack()->push(new DeletePartCommand(document, a));
    const PartId b = addPart(document, testStrokes()[1]);
    EXPECT_NE(a, b);  // a's deletion is on the stack and may be undone
    document.undoStack()->undo();
    document.undoStack()->undo();
    EXPECT_TRUE(document.contains(a));
    EXPECT_FALSE(document.contains(b));
}

TEST(Commands, BadStrokeThrowsAndLeavesTheDocumentUnchanged) {
    Document document;
    addPart(document, testStrokes()[0]);
    const QByteArray before = bytesOf(document);
    const int count = document.undoStack()->count();
    const PartId nextId = document.nextPartId();
    for (const std::vector<Vec2>& stroke :
         {badStroke(), sharedStroke("bad_figure_eight"), sharedStroke("bad_nan")}) {
        try {
            auto command = CreatePartCommand::create(document, stroke);
            FAIL() << "a bad stroke built a part";
        } catch (const rigmesh::Error& e) {
            EXPECT_FALSE(std::string(e.what()).empty());
        }
    }
    EXPECT_EQ(document.undoStack()->count(), count);
    EXPECT_EQ(document.nextPartId(), nextId);
    EXPECT_EQ(bytesOf(document), before);
}

TEST(Commands, DeleteRestoresPositionAndId) {
    Document document;
    const PartId a = addPart(document, testStrokes()[0]);
    const PartId b = addPart(document, testStrokes()[1]);
    const PartId c = addPart(document, testStrokes()[0]);
    const QByteArray before = bytesOf(document);
    document.setSelection({b, kNoJoint});
    QSignalSpy selection(&document, &Document::selectionChanged);
    document.undoStack()->push(new DeletePartCommand(document, b));
    EXPECT_EQ(document.partCount(), 2);
    EXPECT_EQ(document.selection(), Selection{});  // the deleted part is unselected
    EXPECT_EQ(selection.count(), 1);
    document.undoStack()->undo();
    EXPECT_EQ(document.indexOf(a), 0);
    EXPECT_EQ(document.indexOf(b), 1);
    EXPECT_EQ(document.indexOf(c), 2);
    EXPECT_EQ(bytesOf(document), before);
}

TEST(Commands, RenameAndVisibilityEmitFineGrainedChanges) {
    Document document;
    const PartId id = addPart(document, testStrokes()[0], QStringLiteral("Arm"));
    QSignalSpy changed(&document, &Document::partChanged);
    document.undoStack()->push(new RenamePartCommand(document, id, QStringLiteral("Leg")));
    EXPECT_EQ(document.undoStack()->text(document.undoStack()->index() - 1),
              QStringLiteral("Rename Arm to Leg"));
    document.undoStack()->push(new SetPartVisibleCommand(document, id, false));
    EXPECT_EQ(document.undoStack()->text(document.undoStack()->index() - 1),
              QStringLiteral("Hide Leg"));
    ASSERT_EQ(changed.count(), 2);
    EXPECT_EQ(changed[0][1].value<Document::Changes>(), Document::Changes(Document::Change::Name));
    EXPECT_EQ(changed[1][1].value<Document::Changes>(),
              Document::Changes(Document::Change::Visibility));
    EXPECT_FALSE(document.part(id).visible);
    document.undoStack()->undo();
    document.undoStack()->undo();
    EXPECT_TRUE(document.part(id).visible);
    EXPECT_EQ(document.part(id).name, QStringLiteral("Arm"));
}

TEST(Commands, ConsecutiveMovesOfOnePartMergeIntoOneStep) {
    Document document;
    const PartId a = addPart(document, testStrokes()[0]);
    const int base = document.undoStack()->count();
    const Placement start = document.part(a).placement;
    Placement p = start;
    for (int i = 0; i < 5; ++i) {
        p = movedBy(p, 0.1);
        document.undoStack()->push(new MovePartCommand(document, a, p));
    }
    EXPECT_EQ(document.undoStack()->count(), base + 1);
    EXPECT_EQ(document.part(a).placement, p);
    document.undoStack()->undo();
    EXPECT_EQ(document.part(a).placement, start);
}

TEST(Commands, MovesOfDifferentPartsAreSeparateSteps) {
    Document document;
    const PartId a = addPart(document, testStrokes()[0]);
    const PartId b = addPart(document, testStrokes()[1]);
    const int base = document.undoStack()->count();
    document.undoStack()->push(new MovePartCommand(document, a, movedBy({}, 1.0)));
    document.undoStack()->push(new MovePartCommand(document, b, movedBy({}, 2.0)));
    EXPECT_EQ(document.undoStack()->count(), base + 2);
    document.undoStack()->undo();
    EXPECT_EQ(document.part(b).placement, Placement{});
    EXPECT_EQ(document.part(a).placement, movedBy({}, 1.0));
}

TEST(Commands, MoveBackToTheStartBecomesObsolete) {
    Document document;
    const PartId a = addPart(document, testStrokes()[0]);
    const int base = document.undoStack()->count();
    document.undoStack()->push(new MovePartCommand(document, a, movedBy({}, 1.0)));
    document.undoStack()->push(new MovePartCommand(document, a, Placement{}));
    EXPECT_EQ(document.undoStack()->count(), base);
    EXPECT_EQ(document.part(a).placement, Placement{});
}

TEST(Commands, RotationIsPartOfTheMove) {
    Document document;
    const PartId a = addPart(document, testStrokes()[0]);
    Placement turned;
    turned.rotation = Eigen::Quaterniond(Eigen::AngleAxisd(0.3, Vec3::UnitY()));
    document.undoStack()->push(new MovePartCommand(document, a, turned));
    EXPECT_TRUE(document.undoStack()->text(document.undoStack()->index() - 1).startsWith("Rotate"));
    EXPECT_EQ(document.part(a).placement, turned);
}

// A drag previewed live is one undo step from where it started, pushed
// once; a second drag is a second step (no merging); a reverted preview
// leaves no step and puts the part back.
TEST(Commands, PlacementPreviewCommitsOneStepFromWhereItStarted) {
    Document document;
    const PartId a = addPart(document, testStrokes()[0]);
    const Placement from = document.part(a).placement;
    const Placement to = movedBy(from, 0.5);
    const int stepsBefore = document.undoStack()->count();
    {
        PlacementPreview preview(document, a);
        preview.preview(movedBy(from, 0.25));
        preview.preview(to);
        EXPECT_EQ(document.part(a).placement, to);
        EXPECT_EQ(document.undoStack()->count(), stepsBefore);
        EXPECT_TRUE(preview.commit());
    }
    EXPECT_EQ(document.undoStack()->count(), stepsBefore + 1);
    EXPECT_EQ(document.part(a).placement, to);
    {
        PlacementPreview second(document, a);
        second.preview(movedBy(to, 0.5));
        EXPECT_TRUE(second.commit());
    }
    EXPECT_EQ(document.undoStack()->count(), stepsBefore + 2);
    document.undoStack()->undo();
    document.undoStack()->undo();
    EXPECT_EQ(document.part(a).placement, from);
    document.undoStack()->redo();
    EXPECT_EQ(document.part(a).placement, to);
    {
        PlacementPreview dropped(document, a);
        dropped.preview(movedBy(to, 3.0));
    }  // destroyed uncommitted: reverted
    EXPECT_EQ(document.part(a).placement, to);
    EXPECT_EQ(document.undoStack()->count(), stepsBefore + 2);
}

TEST(Commands, RebuildIsOneUndoableStep) {
    Document document;
    const PartId a = addPart(document, testStrokes()[0]);
    const auto original = document.part(a).part;
    // A new part records the edge length it was built with.
    const BuildOptions created = document.part(a).options;
    EXPECT_GT(created.targetEdgeLength, 0.0);
    const int count = document.undoStack()->count();
    QSignalSpy changed(&document, &Document::partChanged);
    BuildOptions options;
    options.targetEdgeLength = 0.12;
    options.smoothing = false;
    document.undoStack()->push(RebuildPartCommand::create(document, a, options).release());
    EXPECT_EQ(document.undoStack()->count(), count + 1);
    ASSERT_EQ(changed.count(), 1);
    EXPECT_TRUE(changed[0][1].value<Document::Changes>() & Document::Change::Geometry);
    EXPECT_TRUE(changed[0][1].value<Document::Changes>() & Document::Change::Options);
    EXPECT_NE(document.part(a).part, original);
    EXPECT_EQ(document.part(a).options, options);
    document.undoStack()->undo();
    EXPECT_EQ(document.part(a).part, original);  // undo swaps the pointer back
    EXPECT_EQ(document.part(a).options, created);
}

TEST(Commands, RebuildWithBadOptionsPushesNothing) {
    Document document;
    const PartId a = addPart(document, testStrokes()[0]);
    BuildOptions bad;
    bad.targetEdgeLength = -1.0;
    EXPECT_THROW(RebuildPartCommand::create(document, a, bad), rigmesh::Error);
    EXPECT_THROW(RebuildPartCommand::create(document, 999, {}), rigmesh::Error);
}

TEST(Document, SelectionIsValidatedAndNotUndoable) {
    Document document;
    const PartId a = addPart(document, testStrokes()[0]);
    const JointId root = document.part(a).part->skeleton.root();
    QSignalSpy spy(&document, &Document::selectionChanged);
    document.setSelection({a, root});
    EXPECT_EQ(document.selection(), (Selection{a, root}));
    document.setSelection({a, 987654});
    EXPECT_EQ(document.selection(), (Selection{a, kNoJoint}));
    document.setSelection({999, kNoJoint});
    EXPECT_EQ(document.selection(), Selection{});
    EXPECT_EQ(spy.count(), 3);
    EXPECT_EQ(document.undoStack()->count(), 1);
}

}  // namespace
}  // namespace rigmesh::model::test
