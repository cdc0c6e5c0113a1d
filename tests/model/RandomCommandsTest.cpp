// Random sequences of commands (seeded): undoing everything gives back the
// initial document, redoing everything the final one, and every step in
// between matches the snapshot taken when it was done (compared by saved
// bytes), poses and pins included. The item model watches the whole run under
// QAbstractItemModelTester (fatal mode) and must mirror the document.
#include <QAbstractItemModelTester>
#include <map>
#include <random>

#include "ModelTestSupport.h"
#include "PoseTestSupport.h"
#include "base/Error.h"
#include "model/SceneItemModel.h"
#include "model/commands/DeletePartCommand.h"
#include "model/commands/MovePartCommand.h"
#include "model/commands/RebuildPartCommand.h"
#include "model/commands/RenamePartCommand.h"
#include "model/commands/ResetPoseCommand.h"
#include "model/commands/SetJointPinnedCommand.h"
#include "model/commands/SetPartVisibleCommand.h"
#include "model/commands/SetPoseCommand.h"

namespace rigmesh::model::test {
namespace {

class RandomSession {
  public:
    explicit RandomSession(unsigned seed) : rng_(seed) {}

    // One random user action; returns false if it pushed nothing.
    bool step(Document& document) {
        QUndoStack& stack = *document.undoStack();
        const int parts = document.partCount();
        const int action = parts == 0 ? 0 : pick(0, 13);
        if (action == 0 && parts >= 5)
            return false;
        switch (action) {
            case 0: {  // create, sometimes from a bad stroke
                const auto& strokes = testStrokes();
                if (pick(0, 5) == 0) {
                    const int count = stack.count();
                    EXPECT_THROW(CreatePartCommand::create(document, badStroke()), rigmesh::Error);
                    EXPECT_EQ(stack.count(), count);
                    return false;
                }
                stack.push(
                    CreatePartCommand::create(document, strokes[pick(0, int(strokes.size()) - 1)])
                        .release());
                return true;
            }
            case 1:
                stack.push(new DeletePartCommand(document, randomPart(document)));
                return true;
            case 2:
                stack.push(new RenamePartCommand(document, randomPart(document),
                                                 QStringLiteral("Name %1").arg(pick(0, 1000))));
                return true;
            case 3:
            case 4:
            case 5: {  // moves: often the same part again, to exercise merging
                if (!document.contains(lastMoved_) || pick(0, 2) == 0)
                    lastMoved_ = randomPart(document);
                Placement p = document.part(lastMoved_).placement;
                p.translation += Vec3(real(), real(), real());
                if (pick(0, 3) == 0)
                    p.rotation = (p.rotation * Eigen::Quaterniond(Eigen::AngleAxisd(
                                                   real(), Vec3(real(), 1.0, real()).normalized())))
                                     .normalized();
                stack.push(new MovePartCommand(document, lastMoved_, p));
                return true;
            }
            case 6: {
                const PartId id = randomPart(document);
                stack.push(new SetPartVisibleCommand(document, id, !document.part(id).visible));
                return true;
            }
            case 7: {
                BuildOptions options;
                options.targetEdgeLength = std::array{0.0, 0.1, 0.15}[pick(0, 2)];
                options.smoothing = pick(0, 1) == 1;
                stack.push(
                    RebuildPartCommand::create(document, randomPart(document), options).release());
                return true;
            }
            case 8:
            case 9:
                return poseDrag(document);
            case 10: {  // pin or unpin a joint
                const PartId id = randomPart(document);
                const JointId joint = randomJoint(document, id);
                stack.push(new SetJointPinnedCommand(
                    document, id, joint, !document.part(id).pinnedJoints.contains(joint)));
                return true;
            }
            case 11:
                stack.push(new ResetPoseCommand(document, randomPart(document)));
                return true;
            default: {  // selection: not undoable, pushes nothing
                const PartId id = randomPart(document);
                const Skeleton& skeleton = document.part(id).part->skeleton;
                document.setSelection(
                    {id, skeleton.joints()[pick(0, skeleton.jointCount() - 1)].id});
                return false;
            }
        }
    }

  private:
    // An IK drag step: often the same joint again, to exercise merging.
    bool poseDrag(Document& document) {
        if (!document.contains(lastPosed_) || pick(0, 2) == 0) {
            lastPosed_ = randomPart(document);
            const std::vector<JointId> ends = endJoints(document.part(lastPosed_).part->skeleton);
            if (ends.empty())
                return false;
            lastDragged_ = ends[pick(0, int(ends.size()) - 1)];
        }
        const PartNode& node = document.part(lastPosed_);
        const Vec3 offset = 0.2 * Vec3(real(), real(), real());
        document.undoStack()->push(new SetPoseCommand(
            document, lastPosed_, dragged(node, lastDragged_, offset), lastDragged_));
        return true;
    }
    JointId randomJoint(const Document& document, PartId id) {
        const Skeleton& skeleton = document.part(id).part->skeleton;
        return skeleton.joints()[pick(0, skeleton.jointCount() - 1)].id;
    }
    int pick(int lo, int hi) { return std::uniform_int_distribution<int>(lo, hi)(rng_); }
    double real() { return std::uniform_real_distribution<double>(-1.0, 1.0)(rng_); }
    PartId randomPart(const Document& document) {
        return document.parts()[pick(0, document.partCount() - 1)].id;
    }

    std::mt19937 rng_;
    PartId lastMoved_ = kNoPart;
    PartId lastPosed_ = kNoPart;
    JointId lastDragged_ = kNoJoint;
};

// The item model's top level and skeleton rows against the document.
void expectModelMirrors(const SceneItemModel& model, const Document& document) {
    ASSERT_EQ(model.rowCount(), document.partCount());
    for (int row = 0; row < document.partCount(); ++row) {
        const PartNode& part = document.parts()[row];
        const QModelIndex index = model.index(row, 0);
        EXPECT_EQ(index.data(SceneItemModel::PartIdRole).toUInt(), part.id);
        EXPECT_EQ(index.data().toString(), part.name);
        EXPECT_EQ(index.data(Qt::CheckStateRole).value<Qt::CheckState>(),
                  part.visible ? Qt::Checked : Qt::Unchecked);
        ASSERT_EQ(model.rowCount(index), 1);
        const QModelIndex skeleton = model.index(0, 0, index);
        int joints = 0;
        std::vector<QModelIndex> pending = {skeleton};
        while (!pending.empty()) {
            const QModelIndex next = pending.back();
            pending.pop_back();
            for (int r = 0; r < model.rowCount(next); ++r) {
                ++joints;
                pending.push_back(model.index(r, 0, next));
            }
        }
        EXPECT_EQ(joints, part.part->skeleton.jointCount());
    }
}

class RandomCommands : public ::testing::TestWithParam<unsigned> {};

TEST_P(RandomCommands, UndoAllAndRedoAllRestoreTheDocument) {
    Document document;
    // Start from a non-empty document, as a loaded one would be.
    addPart(document, testStrokes()[0], QStringLiteral("Start"));
    document.undoStack()->clear();
    document.undoStack()->setClean();

    SceneItemModel model(&document);
    QAbstractItemModelTester tester(&model, QAbstractItemModelTester::FailureReportingMode::Fatal);

    QUndoStack& stack = *document.undoStack();
    std::map<int, QByteArray> snapshots = {{0, bytesOf(document)}};
    RandomSession session(GetParam());
    int pushed = 0;
    for (int i = 0; i < 40; ++i) {
        if (session.step(document))
            ++pushed;
        snapshots[stack.index()] = bytesOf(document);
        expectModelMirrors(model, document);
        // Occasionally step back and forth in the middle of the session.
        if (i % 9 == 8 && stack.canUndo()) {
            stack.undo();
            EXPECT_EQ(bytesOf(document), snapshots.at(stack.index()));
            expectModelMirrors(model, document);
            stack.redo();
            EXPECT_EQ(bytesOf(document), snapshots.at(stack.index()));
        }
    }
    EXPECT_GT(pushed, 10);
    EXPECT_LE(stack.count(), pushed);  // merged moves are one step
    const QByteArray final = bytesOf(document);
    const int top = stack.index();
    ASSERT_EQ(top, stack.count());

    while (stack.canUndo()) {
        stack.undo();
        EXPECT_EQ(bytesOf(document), snapshots.at(stack.index())) << "at step " << stack.index();
        expectModelMirrors(model, document);
    }
    EXPECT_EQ(bytesOf(document), snapshots.at(0));
    EXPECT_FALSE(document.isModified());

    while (stack.canRedo())
        stack.redo();
    EXPECT_EQ(bytesOf(document), final);
    expectModelMirrors(model, document);

    // The final document also survives a file round trip exactly.
    EXPECT_EQ(DocumentFile::toBytes(DocumentFile::fromBytes(final)), final);
}

INSTANTIATE_TEST_SUITE_P(Seeds, RandomCommands, ::testing::Values(1u, 2u, 3u, 42u));

}  // namespace
}  // namespace rigmesh::model::test
