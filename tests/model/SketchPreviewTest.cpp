// A part shown while its stroke is drawn (model/preview/SketchPreview.h):
// in the document without an undo step, swapped as the stroke grows, gone
// with its id on revert, and committed as the one CreatePartCommand a
// release pushes, with the id it was shown with.
#include "ModelTestSupport.h"
#include "model/preview/SketchPreview.h"

namespace rigmesh::model::test {
namespace {

std::shared_ptr<const SketchedPart> sketched(const Document& document,
                                             const std::vector<Vec2>& stroke, const QString& name) {
    return std::make_shared<const SketchedPart>(
        SketchedPart{stroke, name, buildPartForDocument(document, stroke, name, {}), {}});
}

TEST(SketchPreview, ShowsTheStrokesPartWithoutAnUndoStepAndRevertGivesItsIdBack) {
    Document document;
    addPart(document, testStrokes()[0]);
    const PartId next = document.nextPartId();
    const int steps = document.undoStack()->count();
    SketchPreview preview(document);
    EXPECT_EQ(preview.upcomingId(), next);
    preview.preview(sketched(document, ellipseStroke(1.0, 0.4), QStringLiteral("Part 2")));
    ASSERT_TRUE(document.contains(next));
    EXPECT_EQ(document.partCount(), 2);
    EXPECT_EQ(preview.upcomingId(), next);
    const int firstVertices = document.part(next).part->mesh.vertexCount();
    // The stroke grew: the same part, the new shape.
    const auto grown = sketched(document, ellipseStroke(2.0, 0.6), QStringLiteral("Part 2"));
    preview.preview(grown);
    EXPECT_EQ(document.partCount(), 2);
    EXPECT_EQ(document.part(next).part, grown->built.part);
    EXPECT_NE(document.part(next).part->mesh.vertexCount(), firstVertices);
    EXPECT_EQ(document.undoStack()->count(), steps);
    preview.revert();
    EXPECT_FALSE(document.contains(next));
    EXPECT_EQ(document.partCount(), 1);
    EXPECT_EQ(document.nextPartId(), next);
    EXPECT_EQ(document.undoStack()->count(), steps);
}

TEST(SketchPreview, CommitIsOneCreateStepOfThePreviewedPartWithItsId) {
    Document document;
    addPart(document, testStrokes()[0]);
    const PartId next = document.nextPartId();
    const int steps = document.undoStack()->count();
    SketchPreview preview(document);
    const auto shown = sketched(document, ellipseStroke(2.0, 0.6), QStringLiteral("Part 2"));
    preview.preview(shown);
    EXPECT_EQ(preview.commit(), next);
    EXPECT_FALSE(preview.previewing());
    ASSERT_EQ(document.undoStack()->count(), steps + 1);
    EXPECT_EQ(document.undoStack()->text(steps), QStringLiteral("Create Part 2"));
    const PartNode& node = document.part(next);
    EXPECT_EQ(node.part, shown->built.part) << "the very part shown, not a rebuild";
    EXPECT_EQ(node.stroke, shown->stroke);
    EXPECT_EQ(node.options, shown->built.options);
    document.undoStack()->undo();
    EXPECT_FALSE(document.contains(next));
    EXPECT_EQ(document.nextPartId(), next);
    document.undoStack()->redo();
    ASSERT_TRUE(document.contains(next));
    EXPECT_EQ(document.part(next).part, shown->built.part);
    // Nothing shown: nothing to commit.
    EXPECT_EQ(preview.commit(), kNoPart);
    EXPECT_EQ(document.undoStack()->count(), steps + 1);
}

TEST(SketchPreview, APreviewDestroyedUncommittedLeavesNothing) {
    Document document;
    const PartId next = document.nextPartId();
    {
        SketchPreview preview(document);
        preview.preview(sketched(document, ellipseStroke(1.0, 0.5), QStringLiteral("Part 1")));
        EXPECT_TRUE(document.contains(next));
    }
    EXPECT_EQ(document.partCount(), 0);
    EXPECT_EQ(document.nextPartId(), next);
    EXPECT_FALSE(document.isModified());
}

}  // namespace
}  // namespace rigmesh::model::test
