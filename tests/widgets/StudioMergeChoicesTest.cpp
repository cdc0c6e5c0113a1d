// The Merge tool's choices: a plain release over a
// candidate opens a small menu (Snap, Split, Connect); hovering an item says
// what it will do, Enter takes it, Esc puts the part back; Shift and Ctrl +
// release split and connect at once without the menu.
#include <gtest/gtest.h>

#include <QGuiApplication>
#include <QScreen>
#include <QStatusBar>
#include <QUndoStack>
#include <nlohmann/json.hpp>

#include "StudioMergeFixture.h"
#include "model/DocumentFile.h"
#include "model/commands/MergePartsCommand.h"

namespace rigmesh::widgettest {
namespace {

using test::drag;

class StudioMergeChoices : public StudioMerge {
  protected:
    // The mode of the merge the last undo step made ("" if it is no merge).
    std::string lastMergeMode() const {
        const QUndoStack* stack = document()->undoStack();
        const QUndoCommand* step = stack->command(stack->count() - 1);
        for (int i = 0; step && i < step->childCount(); ++i)
            if (const auto* merge = dynamic_cast<const model::MergePartsCommand*>(step->child(i)))
                return merge->recipeStep().at("mode").get<std::string>();
        return {};
    }
    QString status() const { return window->statusBar()->currentMessage(); }
};

TEST_F(StudioMergeChoices, APlainReleaseOffersSnapSplitAndConnectAndSplitsFromTheMenu) {
    const QByteArray before = model::DocumentFile::toBytes(*document());
    const int steps = document()->undoStack()->count();
    drag(viewport(), shortDrag());
    QMenu* menu = choices();
    ASSERT_NE(menu, nullptr);
    EXPECT_EQ(document()->partCount(), 2) << "nothing merges before a choice";
    QStringList items;
    for (QAction* action : menu->actions())
        if (!action->isSeparator())
            items << action->text();
    EXPECT_EQ(items, (QStringList{QStringLiteral("&Snap the joints together"),
                                  QStringLiteral("S&plit the bone here"),
                                  QStringLiteral("&Connect by a new bone"),
                                  QStringLiteral("Cancel (Esc)")}));
    // The drop point lies on the body's bone away from its joints: Split is
    // what it suggests, the active item.
    EXPECT_EQ(menu->activeAction()->text(), items[1]);

    QTest::keyClick(menu, Qt::Key_Down);  // hovering Connect previews it
    EXPECT_TRUE(status().startsWith(QStringLiteral("Connect "))) << status().toStdString();
    QTest::keyClick(menu, Qt::Key_Up);  // and back to Split
    EXPECT_TRUE(status().startsWith(QStringLiteral("Split a bone of body")))
        << status().toStdString();
    QTest::qWait(100);
    // The whole screen: the menu is a window of its own.
    QGuiApplication::primaryScreen()
        ->grabWindow(0)
        .copy(window->frameGeometry())
        .save(QStringLiteral(RIGMESH_TEST_OUTPUT "/studio_merge_choices.png"));

    QTest::keyClick(menu, Qt::Key_Return);
    rigmesh::test::waitForJobs();  // the merge runs in the background
    ASSERT_EQ(document()->partCount(), 1) << status().toStdString();
    EXPECT_EQ(lastMergeMode(), "split");
    EXPECT_EQ(document()->undoStack()->count(), steps + 1);
    EXPECT_TRUE(status().contains(QStringLiteral("merged in"))) << status().toStdString();
    EXPECT_EQ(mergeTool()->choices(), nullptr);
    document()->undoStack()->undo();
    EXPECT_EQ(model::DocumentFile::toBytes(*document()), before);
}

TEST_F(StudioMergeChoices, ConnectFromTheMenuJoinsTheJointsByANewBone) {
    drag(viewport(), shortDrag());
    QMenu* menu = choices();
    ASSERT_NE(menu, nullptr);
    // Down from the suggested item to Connect.
    for (int i = 0;
         i < 3 && menu->activeAction()->text() != QStringLiteral("&Connect by a new bone"); ++i)
        QTest::keyClick(menu, Qt::Key_Down);
    EXPECT_TRUE(status().startsWith(QStringLiteral("Connect "))) << status().toStdString();
    QTest::keyClick(menu, Qt::Key_Return);
    rigmesh::test::waitForJobs();  // the merge runs in the background
    ASSERT_EQ(document()->partCount(), 1) << status().toStdString();
    EXPECT_EQ(lastMergeMode(), "connect");
}

TEST_F(StudioMergeChoices, EscapeClosesTheMenuAndPutsThePartBack) {
    const model::PartId leg = document()->parts()[1].id;
    const model::Placement start = document()->part(leg).placement;
    const int steps = document()->undoStack()->count();
    drag(viewport(), shortDrag());
    QMenu* menu = choices();
    ASSERT_NE(menu, nullptr);
    EXPECT_FALSE(document()->part(leg).placement == start) << "the part waits where it was dropped";
    QTest::keyClick(menu, Qt::Key_Escape);
    QTest::qWait(20);
    EXPECT_EQ(document()->partCount(), 2);
    EXPECT_EQ(document()->part(leg).placement, start);
    EXPECT_EQ(document()->undoStack()->count(), steps);
    EXPECT_EQ(mergeTool()->choices(), nullptr);
    EXPECT_EQ(status(), QStringLiteral("Merge cancelled"));
}

TEST_F(StudioMergeChoices, ShiftAndCtrlReleaseSplitAndConnectWithoutTheMenu) {
    const QByteArray before = model::DocumentFile::toBytes(*document());
    for (const auto& [modifier, mode] :
         {std::pair{Qt::ShiftModifier, "split"}, std::pair{Qt::ControlModifier, "connect"}}) {
        drag(viewport(), shortDrag(), modifier);
        EXPECT_EQ(mergeTool()->choices(), nullptr) << mode;
        ASSERT_EQ(document()->partCount(), 1) << mode << ": " << status().toStdString();
        EXPECT_EQ(lastMergeMode(), mode);
        document()->undoStack()->undo();
        EXPECT_EQ(model::DocumentFile::toBytes(*document()), before) << mode;
    }
}

}  // namespace
}  // namespace rigmesh::widgettest
