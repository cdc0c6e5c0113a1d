// The timeline's item model: rows are parts with one child per
// joint, columns frames; keys, holds, the current frame and the range are
// its data. A random session of clip, part and timeline commands with undo
// and redo runs under QAbstractItemModelTester (fatal mode), and after every
// step the model must mirror the document.
#include <QAbstractItemModelTester>
#include <QSignalSpy>
#include <random>

#include "ModelTestSupport.h"
#include "PoseTestSupport.h"
#include "base/Error.h"
#include "model/PartClips.h"
#include "model/TimelineItemModel.h"
#include "model/commands/ClipListCommand.h"
#include "model/commands/DeleteKeyCommand.h"
#include "model/commands/DeletePartCommand.h"
#include "model/commands/KeyPoseCommand.h"
#include "model/commands/MoveKeysCommand.h"
#include "model/commands/RebuildPartCommand.h"
#include "model/commands/SetPoseCommand.h"
#include "model/commands/SetTimelineCommand.h"

namespace rigmesh::model::test {
namespace {

using Role = TimelineItemModel::Role;

// Every row, column and key of the model as the document says.
void expectModelMirrors(const TimelineItemModel& model, const Document& document) {
    const TimelineSettings& timeline = document.timeline();
    int lastFrame = timeline.endFrame;
    for (const PartNode& node : document.parts())
        for (double time : node.clip.keyTimes())
            lastFrame = std::max(lastFrame, static_cast<int>(timeline.frameOfTime(time)));
    ASSERT_EQ(model.columnCount(), lastFrame + 1);
    ASSERT_EQ(model.rowCount(), document.partCount());
    for (int r = 0; r < document.partCount(); ++r) {
        const PartNode& node = document.parts()[r];
        const QModelIndex row = model.index(r, 0);
        EXPECT_EQ(row.data(Role::PartIdRole).toUInt(), node.id);
        EXPECT_EQ(row.data(Qt::DisplayRole).toString(), node.name);
        EXPECT_EQ(row.data(Role::ClipNameRole).toString().toStdString(), clipName(node.clip));
        ASSERT_EQ(model.rowCount(row), node.part->skeleton.jointCount());
        std::set<int> keyed;
        for (double time : node.clip.keyTimes())
            keyed.insert(static_cast<int>(timeline.frameOfTime(time)));
        for (int frame = 0; frame < model.columnCount(); ++frame) {
            const QModelIndex cell = model.index(r, frame);
            ASSERT_EQ(cell.data(Role::KeyRole).toBool(), keyed.contains(frame)) << frame;
            if (keyed.contains(frame)) {
                EXPECT_TRUE(node.clip.hasKey(cell.data(Role::KeyTimeRole).toDouble()));
            }
        }
    }
    for (int frame = 0; frame < model.columnCount(); ++frame)
        ASSERT_EQ(model.headerData(frame, Qt::Horizontal, Role::CurrentFrameRole).toBool(),
                  frame == document.currentFrame());
}

TEST(TimelineItemModel, RowsAreJointsAndColumnsFrames) {
    Document document;
    const PartId id = addPart(document, sharedStroke("y_branch"), QStringLiteral("Y"));
    TimelineItemModel model(&document);
    QAbstractItemModelTester tester(&model, QAbstractItemModelTester::FailureReportingMode::Fatal);
    const PartNode& node = document.part(id);
    const JointId end = endJoints(node.part->skeleton).front();
    EXPECT_EQ(model.columnCount(), 49);  // frames 0..48
    EXPECT_EQ(model.rowCount(model.index(0, 0)), node.part->skeleton.jointCount());

    // Keys at 0 and 12 with the same pose of every joint but `end`'s.
    document.undoStack()->push(new KeyPoseCommand(document, id, 0.0));
    document.undoStack()->push(
        new SetPoseCommand(document, id, dragged(node, end, Vec3(0.1, 0.2, 0)), end));
    document.undoStack()->push(new KeyPoseCommand(document, id, 0.5));
    EXPECT_TRUE(model.index(0, 0).data(Role::KeyRole).toBool());
    EXPECT_TRUE(model.index(0, 12).data(Role::KeyRole).toBool());
    EXPECT_FALSE(model.index(0, 6).data(Role::KeyRole).toBool());
    EXPECT_EQ(model.index(0, 12).data(Role::KeyTimeRole).toDouble(), 0.5);
    // Joints off the dragged limb hold still between the keys (a hold bar);
    // a joint the drag turned does not.
    const QModelIndex part = model.index(0, 0);
    int holding = 0, moving = 0;
    for (int j = 0; j < model.rowCount(part); ++j) {
        const QModelIndex joint = model.index(j, 0, part);
        ASSERT_TRUE(joint.data(Role::KeyRole).toBool());
        const JointId id2 = static_cast<JointId>(joint.data(Role::JointIdRole).toUInt());
        const bool same = node.clip.key(0.0).rotation(id2).angularDistance(
                              node.clip.key(0.5).rotation(id2)) < 1e-9;
        EXPECT_EQ(joint.data(Role::HoldRole).toBool(), same) << id2;
        (same ? holding : moving) += 1;
    }
    EXPECT_GT(holding, 0);
    EXPECT_GT(moving, 0);

    // A key past the range adds columns; the header knows seconds and range.
    document.undoStack()->push(new KeyPoseCommand(document, id, 3.0));
    EXPECT_EQ(model.columnCount(), 73);
    EXPECT_FALSE(model.headerData(60, Qt::Horizontal, Role::InRangeRole).toBool());
    EXPECT_TRUE(model.headerData(48, Qt::Horizontal, Role::InRangeRole).toBool());
    EXPECT_DOUBLE_EQ(model.headerData(36, Qt::Horizontal, Role::SecondsRole).toDouble(), 1.5);
    QSignalSpy header(&model, &QAbstractItemModel::headerDataChanged);
    document.setCurrentFrame(5);
    EXPECT_EQ(header.count(), 2);  // the old and the new current frame
    EXPECT_TRUE(model.headerData(5, Qt::Horizontal, Role::CurrentFrameRole).toBool());
    expectModelMirrors(model, document);
}

class TimelineItemModelRandom : public testing::TestWithParam<unsigned> {};

TEST_P(TimelineItemModelRandom, MirrorsTheDocumentThroughRandomEditsUndoAndRedo) {
    Document document;
    addPart(document, sharedStroke("y_branch"), QStringLiteral("Y"));
    addPart(document, sharedStroke("tube"), QStringLiteral("T"));
    TimelineItemModel model(&document);
    QAbstractItemModelTester tester(&model, QAbstractItemModelTester::FailureReportingMode::Fatal);
    std::mt19937 rng(GetParam());
    auto pick = [&](int n) { return std::uniform_int_distribution<int>(0, n - 1)(rng); };
    QUndoStack& stack = *document.undoStack();
    int made = 0;
    for (int i = 0; i < 60; ++i) {
        const int action = pick(11);
        try {
            if (document.partCount() == 0 || action == 0) {
                addPart(document, testStrokes()[pick(2)], QStringLiteral("P%1").arg(made++));
            } else {
                const PartNode& node = document.parts()[pick(document.partCount())];
                const PartId id = node.id;
                const double frame = pick(70);
                const double time = document.timeline().timeOfFrame(frame);
                switch (action) {
                    case 1:
                    case 2: {
                        const auto ends = endJoints(node.part->skeleton);
                        if (!ends.empty())
                            stack.push(new SetPoseCommand(
                                document, id,
                                dragged(node, ends[pick(int(ends.size()))], Vec3(0.05, 0.1, 0))));
                        stack.push(new KeyPoseCommand(document, id, time));
                        break;
                    }
                    case 3:
                        if (node.clip.keyCount() > 0)
                            stack.push(new DeleteKeyCommand(document, id, node.clip.keyTimes()[0]));
                        break;
                    case 4:
                        if (node.clip.keyCount() > 0)
                            stack.push(new MoveKeysCommand(document, id, node.clip.keyTimes(),
                                                           (pick(9) - 4) / 24.0));
                        break;
                    case 5:
                        stack.push(ClipListCommand::create(document, id, "c" + std::to_string(i))
                                       .release());
                        break;
                    case 6:
                        if (!node.otherClips.empty())
                            stack.push(ClipListCommand::activate(document, id,
                                                                 clipName(node.otherClips[0]))
                                           .release());
                        break;
                    case 7:
                        stack.push(new SetTimelineCommand(
                            document, {pick(5), 20 + pick(60), pick(2) ? 24.0 : 30.0}));
                        break;
                    case 8:
                        document.setCurrentFrame(pick(80));
                        break;
                    case 9: {
                        BuildOptions options = node.options;
                        options.smoothing = !options.smoothing;
                        stack.push(RebuildPartCommand::create(document, id, options).release());
                        break;
                    }
                    default:
                        if (pick(3) == 0)
                            stack.push(new DeletePartCommand(document, id));
                        else if (stack.canUndo())
                            stack.undo();
                        else if (stack.canRedo())
                            stack.redo();
                }
            }
        } catch (const Error&) {
            // A refused edit (a key moved out of range) changes nothing.
        }
        expectModelMirrors(model, document);
        if (testing::Test::HasFatalFailure())
            return;
    }
    EXPECT_GT(stack.count(), 15) << "the session made edits";
    while (stack.canUndo()) {
        stack.undo();
        expectModelMirrors(model, document);
    }
    while (stack.canRedo()) {
        stack.redo();
        expectModelMirrors(model, document);
    }
}

INSTANTIATE_TEST_SUITE_P(Seeds, TimelineItemModelRandom, testing::Values(1u, 2u, 3u, 4u));

}  // namespace
}  // namespace rigmesh::model::test
