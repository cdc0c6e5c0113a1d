// The outliner's item model: structure, in-place rename and visibility
// through commands, and incremental updates.
#include <QAbstractItemModelTester>
#include <QSignalSpy>

#include "ModelTestSupport.h"
#include "model/SceneItemModel.h"
#include "model/commands/DeletePartCommand.h"
#include "model/commands/RebuildPartCommand.h"

namespace rigmesh::model::test {
namespace {

using Kind = SceneNode::Kind;

Kind kindOf(const QModelIndex& index) {
    return static_cast<Kind>(index.data(SceneItemModel::KindRole).toInt());
}

// Each joint row says how many vertices the bone ending at
// it leads; over all bones they are every vertex.
TEST(SceneItemModel, JointRowsShowTheVertexCountOfTheirBone) {
    Document document;
    const PartId id = addPart(document, testStrokes()[3], QStringLiteral("Y"));
    SceneItemModel model(&document);
    const Part& part = *document.part(id).part;
    int total = 0;
    for (const Bone& bone : part.skeleton.bones()) {
        const QString info = model.indexOfJoint(id, bone.tail).siblingAtColumn(1).data().toString();
        const QString marker = QStringLiteral("bone %1: ").arg(bone.id);
        ASSERT_TRUE(info.contains(marker)) << info.toStdString();
        total += info.section(marker, 1).section(QLatin1Char(' '), 0, 0).toInt();
    }
    EXPECT_EQ(total, part.mesh.vertexCount());
}

TEST(SceneItemModel, PartsSkeletonAndJointHierarchy) {
    Document document;
    const PartId id = addPart(document, testStrokes()[3], QStringLiteral("Y"));
    SceneItemModel model(&document);
    QAbstractItemModelTester tester(&model, QAbstractItemModelTester::FailureReportingMode::Fatal);

    ASSERT_EQ(model.rowCount(), 1);
    EXPECT_EQ(model.columnCount(), 2);
    const QModelIndex part = model.index(0, 0);
    EXPECT_EQ(kindOf(part), Kind::Part);
    EXPECT_EQ(part.data().toString(), QStringLiteral("Y"));
    EXPECT_TRUE(model.index(0, 1).data().toString().contains(QStringLiteral("vertices")));
    ASSERT_EQ(model.rowCount(part), 1);
    const QModelIndex skeletonRow = model.index(0, 0, part);
    EXPECT_EQ(kindOf(skeletonRow), Kind::Skeleton);
    EXPECT_EQ(skeletonRow.data().toString(), QStringLiteral("Skeleton"));

    const Skeleton& skeleton = document.part(id).part->skeleton;
    ASSERT_EQ(model.rowCount(skeletonRow), 1);  // one tree: the root joint
    const QModelIndex root = model.index(0, 0, skeletonRow);
    EXPECT_EQ(kindOf(root), Kind::Joint);
    EXPECT_EQ(root.data(SceneItemModel::JointIdRole).toUInt(), skeleton.root());
    EXPECT_TRUE(root.data().toString().contains(QStringLiteral("root")));
    EXPECT_EQ(model.rowCount(root), static_cast<int>(skeleton.childrenOf(skeleton.root()).size()));

    // Every joint's children are its skeleton children.
    for (const Joint& joint : skeleton.joints()) {
        const QModelIndex index = model.indexOfJoint(id, joint.id);
        ASSERT_TRUE(index.isValid());
        std::vector<JointId> expected;
        for (BoneId bone : skeleton.childrenOf(joint.id))
            expected.push_back(skeleton.bone(bone).tail);
        std::vector<JointId> actual;
        for (int r = 0; r < model.rowCount(index); ++r)
            actual.push_back(model.index(r, 0, index).data(SceneItemModel::JointIdRole).toUInt());
        EXPECT_EQ(actual, expected);
        if (joint.id != skeleton.root()) {
            const auto parentBone = std::find_if(skeleton.bones().begin(), skeleton.bones().end(),
                                                 [&](const Bone& b) { return b.tail == joint.id; });
            ASSERT_NE(parentBone, skeleton.bones().end());
            EXPECT_EQ(index.parent().data(SceneItemModel::JointIdRole).toUInt(), parentBone->head);
        }
    }
}

TEST(SceneItemModel, EditingANamePushesARename) {
    Document document;
    const PartId id = addPart(document, testStrokes()[0], QStringLiteral("Old"));
    SceneItemModel model(&document);
    QAbstractItemModelTester tester(&model, QAbstractItemModelTester::FailureReportingMode::Fatal);
    QSignalSpy changed(&model, &QAbstractItemModel::dataChanged);
    const QModelIndex index = model.indexOfPart(id);
    EXPECT_TRUE(model.flags(index) & Qt::ItemIsEditable);
    EXPECT_FALSE(model.flags(model.index(0, 0, index)) & Qt::ItemIsEditable);
    const int count = document.undoStack()->count();
    EXPECT_TRUE(model.setData(index, QStringLiteral("New")));
    EXPECT_EQ(document.part(id).name, QStringLiteral("New"));
    EXPECT_EQ(document.undoStack()->count(), count + 1);
    EXPECT_EQ(changed.count(), 1);
    EXPECT_FALSE(model.setData(index, QStringLiteral("  ")));  // empty names are refused
    document.undoStack()->undo();
    EXPECT_EQ(index.data().toString(), QStringLiteral("Old"));
    EXPECT_EQ(changed.count(), 2);
}

TEST(SceneItemModel, CheckingAPartPushesShowHide) {
    Document document;
    const PartId id = addPart(document, testStrokes()[0]);
    SceneItemModel model(&document);
    QAbstractItemModelTester tester(&model, QAbstractItemModelTester::FailureReportingMode::Fatal);
    const QModelIndex index = model.indexOfPart(id);
    EXPECT_TRUE(model.flags(index) & Qt::ItemIsUserCheckable);
    EXPECT_TRUE(model.setData(index, Qt::Unchecked, Qt::CheckStateRole));
    EXPECT_FALSE(document.part(id).visible);
    EXPECT_EQ(index.data(Qt::CheckStateRole).value<Qt::CheckState>(), Qt::Unchecked);
    EXPECT_EQ(document.undoStack()->text(document.undoStack()->index() - 1).left(4),
              QStringLiteral("Hide"));
    document.undoStack()->undo();
    EXPECT_EQ(index.data(Qt::CheckStateRole).value<Qt::CheckState>(), Qt::Checked);
}

TEST(SceneItemModel, UpdatesIncrementallyWithoutResets) {
    Document document;
    const PartId a = addPart(document, testStrokes()[0]);
    SceneItemModel model(&document);
    QAbstractItemModelTester tester(&model, QAbstractItemModelTester::FailureReportingMode::Fatal);
    QSignalSpy resets(&model, &QAbstractItemModel::modelReset);
    QSignalSpy inserted(&model, &QAbstractItemModel::rowsInserted);
    QSignalSpy removed(&model, &QAbstractItemModel::rowsRemoved);

    const PartId b = addPart(document, testStrokes()[1]);
    ASSERT_EQ(inserted.count(), 1);
    EXPECT_FALSE(inserted[0][0].value<QModelIndex>().isValid());
    EXPECT_EQ(inserted[0][1].toInt(), 1);
    const QPersistentModelIndex first = model.indexOfPart(a);

    document.undoStack()->push(new DeletePartCommand(document, a));
    EXPECT_EQ(removed.count(), 1);
    EXPECT_FALSE(first.isValid());
    EXPECT_EQ(model.indexOfPart(b).row(), 0);

    // A rebuild replaces the part's skeleton subtree only.
    const QPersistentModelIndex bIndex = model.indexOfPart(b);
    BuildOptions options;
    options.smoothing = false;
    document.undoStack()->push(RebuildPartCommand::create(document, b, options).release());
    EXPECT_TRUE(bIndex.isValid());
    EXPECT_EQ(model.rowCount(bIndex), 1);
    EXPECT_EQ(resets.count(), 0);
}

}  // namespace
}  // namespace rigmesh::model::test
