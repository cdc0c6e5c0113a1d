// The outliner's pin marker: pinned joints say so in the info column, and
// the model tells views when pins change.
#include <QAbstractItemModelTester>
#include <QSignalSpy>

#include "ModelTestSupport.h"
#include "PoseTestSupport.h"
#include "model/SceneItemModel.h"
#include "model/commands/SetJointPinnedCommand.h"

namespace rigmesh::model::test {
namespace {

TEST(SceneItemModel, PinnedJointsShowAMarker) {
    Document document;
    const PartId id = addPart(document, testStrokes()[3], QStringLiteral("Y"));
    SceneItemModel model(&document);
    QAbstractItemModelTester tester(&model, QAbstractItemModelTester::FailureReportingMode::Fatal);
    const JointId joint = endJoints(document.part(id).part->skeleton).at(0);
    const QModelIndex info = model.indexOfJoint(id, joint, SceneItemModel::InfoColumn);
    ASSERT_TRUE(info.isValid());
    EXPECT_FALSE(info.data().toString().contains(QStringLiteral("(pinned)")));

    QSignalSpy changed(&model, &QAbstractItemModel::dataChanged);
    document.undoStack()->push(new SetJointPinnedCommand(document, id, joint, true));
    EXPECT_TRUE(info.data().toString().endsWith(QStringLiteral(" (pinned)")));
    bool covered = false;
    for (const QList<QVariant>& args : changed) {
        const auto top = args.at(0).value<QModelIndex>();
        const auto bottom = args.at(1).value<QModelIndex>();
        covered |= top.parent() == info.parent() && top.row() <= info.row() &&
                   bottom.row() >= info.row() && top.column() <= SceneItemModel::InfoColumn &&
                   bottom.column() >= SceneItemModel::InfoColumn;
    }
    EXPECT_TRUE(covered);

    document.undoStack()->undo();
    EXPECT_FALSE(info.data().toString().contains(QStringLiteral("(pinned)")));
    // Only the pinned joint is marked.
    document.undoStack()->redo();
    const JointId other = endJoints(document.part(id).part->skeleton).at(1);
    EXPECT_FALSE(model.indexOfJoint(id, other, SceneItemModel::InfoColumn)
                     .data()
                     .toString()
                     .contains(QStringLiteral("(pinned)")));
}

}  // namespace
}  // namespace rigmesh::model::test
