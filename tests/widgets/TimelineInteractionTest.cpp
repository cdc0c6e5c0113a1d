// The timeline dock end to end, driven with the mouse and keys
// like a person: scrubbing the ruler shows the clip's pose live with no undo
// step; clicking, Shift-clicking and box-selecting keys; dragging keys is one
// undo step per drag; Delete, Ctrl+C and Ctrl+V at the cursor; I keys the
// pose; Space plays in real time; Left/Right step. Screenshots for
// docs/STUDIO.md.
#include <gtest/gtest.h>

#include <QElapsedTimer>
#include <QTemporaryDir>
#include <QToolButton>
#include <QUndoStack>

#include "DocumentView.h"
#include "EmbeddedExamples.h"
#include "MainWindow.h"
#include "PoseDistance.h"
#include "StudioTestSupport.h"
#include "model/PartClips.h"
#include "model/TimelineItemModel.h"
#include "model/commands/ClipListCommand.h"
#include "model/commands/CreatePartCommand.h"
#include "model/commands/KeyPoseCommand.h"
#include "model/commands/SetPoseCommand.h"
#include "pose/InverseKinematics.h"
#include "sketch/Sketch.h"
#include "timeline/Playback.h"
#include "timeline/TimelineDock.h"
#include "timeline/TimelineView.h"

namespace rigmesh {
namespace {

using test::drag;
using test::sendMouse;
using test::settle;

using test::poseDistance;

class Timeline : public testing::Test {
  protected:
    void SetUp() override {
        ASSERT_TRUE(recovery.isValid());
        window = std::make_unique<widgets::MainWindow>(recovery.path());
        window->resize(1300, 860);
        window->newDocument();
        settle(window.get());
        const Sketch sketch = parseSketchJson(resources::exampleSketchJson(), "example.json");
        document()->undoStack()->push(
            model::CreatePartCommand::create(*document(), sketch.points, "biped").release());
        part = document()->parts().front().id;
        window->currentView()->viewport()->frameAll();
        // A wave: rest at 0, the hand up at 12, down at 24.
        const Skeleton& skeleton = node().part->skeleton;
        for (const Joint& joint : skeleton.joints())
            if (skeleton.degree(joint.id) == 1 && joint.position.x() > hand.second) {
                hand = {joint.id, joint.position.x()};
            }
        keyAt(0, Vec3::Zero());
        keyAt(12, Vec3(0.0, 0.35, 0.0));
        keyAt(24, Vec3(0.0, -0.25, 0.0));
        document()->setCurrentFrame(0);
        document()->undoStack()->clear();
        QTest::qWait(50);
    }
    void keyAt(int frame, const Vec3& offset) {
        const Skeleton& skeleton = node().part->skeleton;
        const Pose pose = dragJoint(skeleton, restPose(skeleton), hand.first,
                                    skeleton.joint(hand.first).position + offset, {})
                              .pose;
        document()->undoStack()->push(new model::SetPoseCommand(*document(), part, pose));
        document()->undoStack()->push(new model::KeyPoseCommand(*document(), part, frame / 24.0));
    }
    model::Document* document() const { return window->currentDocument(); }
    const model::PartNode& node() const { return document()->part(part); }
    widgets::TimelineView* view() const { return window->timeline()->view(); }
    QPointF key(int frame) const { return *view()->keyPosition(part, frame); }
    std::vector<double> keyFrames() const {
        std::vector<double> out;
        for (double t : node().clip.keyTimes())
            out.push_back(std::round(t * 24.0 * 1e9) / 1e9);
        return out;
    }
    QVector3D handOnScreen() const {
        return window->currentView()->viewport()->jointWorldPosition(part, hand.first);
    }

    QTemporaryDir recovery;
    std::unique_ptr<widgets::MainWindow> window;
    model::PartId part = model::kNoPart;
    std::pair<JointId, double> hand{kNoJoint, -1e9};
};

TEST_F(Timeline, ScrubbingTheRulerShowsTheClipsPoseLiveWithoutAnUndoStep) {
    const QVector3D start = handOnScreen();
    const double y = view()->rulerRect().center().y();
    std::vector<QPointF> path;
    for (int frame = 0; frame <= 12; frame += 2)
        path.emplace_back(view()->xOfFrame(frame), y);
    view()->setFocus();
    sendMouse(view(), QEvent::MouseButtonPress, path.front(), Qt::LeftButton, Qt::LeftButton);
    for (std::size_t i = 1; i < path.size(); ++i) {
        sendMouse(view(), QEvent::MouseMove, path[i], Qt::NoButton, Qt::LeftButton);
        const int frame = static_cast<int>(2 * i);
        ASSERT_EQ(document()->currentFrame(), frame);
        // The document's pose is the clip's at that frame while scrubbing.
        EXPECT_LT(poseDistance(node().pose, node().clip.evaluate(frame / 24.0)), 1e-12) << frame;
    }
    sendMouse(view(), QEvent::MouseButtonRelease, path.back(), Qt::LeftButton, Qt::NoButton);
    EXPECT_EQ(document()->currentFrame(), 12);
    EXPECT_GT((handOnScreen() - start).length(), 0.2f) << "the viewport's hand moved up";
    EXPECT_EQ(document()->undoStack()->count(), 0);
    EXPECT_FALSE(document()->isModified());
    // For docs/STUDIO.md: the part expanded into its joints, the key at 12 selected.
    view()->setExpanded(part, true);
    view()->setSelectedKeys({{part, {0.5}}});
    window->grab().save(QStringLiteral(RIGMESH_TEST_OUTPUT "/studio_timeline.png"));

    // Left / Right step one frame, Shift+Left / Shift+Right jump to the ends.
    window->activateWindow();
    window->currentView()->viewport()->setFocus();
    QTest::keyClick(window.get(), Qt::Key_Right);
    EXPECT_EQ(document()->currentFrame(), 13);
    QTest::keyClick(window.get(), Qt::Key_Left);
    QTest::keyClick(window.get(), Qt::Key_Left);
    EXPECT_EQ(document()->currentFrame(), 11);
    QTest::keyClick(window.get(), Qt::Key_Right, Qt::ShiftModifier);
    EXPECT_EQ(document()->currentFrame(), document()->timeline().endFrame);
    QTest::keyClick(window.get(), Qt::Key_Left, Qt::ShiftModifier);
    EXPECT_EQ(document()->currentFrame(), document()->timeline().startFrame);
}

TEST_F(Timeline, DraggingKeysMovesThemByWholeFramesInOneUndoStepPerDrag) {
    // Click the key at 24, Shift-click the key at 12, drag both 6 frames on.
    drag(view(), {key(24)});
    drag(view(), {key(12)}, Qt::ShiftModifier);
    ASSERT_EQ(view()->selectedKeyCount(), 2);
    const int steps = document()->undoStack()->count();
    const double step = view()->xOfFrame(1) - view()->xOfFrame(0);
    std::vector<QPointF> path;
    for (int i = 0; i <= 12; ++i)
        path.push_back(key(12) + QPointF(i * step * 0.5 + 0.3, 2));
    drag(view(), path);
    EXPECT_EQ(keyFrames(), (std::vector<double>{0, 18, 30}));
    EXPECT_EQ(document()->undoStack()->count(), steps + 1) << "one undo step for the drag";
    // A second drag is a second undo step.
    drag(view(), {key(30), key(30) + QPointF(2 * step + 0.3, 0)});
    EXPECT_EQ(keyFrames(), (std::vector<double>{0, 20, 32}));
    EXPECT_EQ(document()->undoStack()->count(), steps + 2);
    document()->undoStack()->undo();
    EXPECT_EQ(keyFrames(), (std::vector<double>{0, 18, 30}));
    document()->undoStack()->undo();
    EXPECT_EQ(keyFrames(), (std::vector<double>{0, 12, 24}));
}

TEST_F(Timeline, EscapePutsDraggedKeysBack) {
    drag(view(), {key(24)});
    const QPointF from = key(24);
    const double step = view()->xOfFrame(1) - view()->xOfFrame(0);
    view()->setFocus();
    sendMouse(view(), QEvent::MouseButtonPress, from, Qt::LeftButton, Qt::LeftButton);
    sendMouse(view(), QEvent::MouseMove, from + QPointF(5 * step, 0), Qt::NoButton, Qt::LeftButton);
    EXPECT_EQ(keyFrames(), (std::vector<double>{0, 12, 29})) << "previewed live";
    QTest::keyClick(view(), Qt::Key_Escape);
    sendMouse(view(), QEvent::MouseButtonRelease, from + QPointF(5 * step, 0), Qt::LeftButton,
              Qt::NoButton);
    EXPECT_EQ(keyFrames(), (std::vector<double>{0, 12, 24}));
    EXPECT_EQ(document()->undoStack()->count(), 0);
}

TEST_F(Timeline, BoxSelectCopyPasteAtTheCursorAndDelete) {
    // A box around the keys at 12 and 24 on the part's row.
    const double step = view()->xOfFrame(1) - view()->xOfFrame(0);
    drag(view(), {key(12) + QPointF(-0.5 * step, -8), key(24) + QPointF(0.5 * step, 8)});
    ASSERT_EQ(view()->selectedKeyCount(), 2);
    QTest::keyClick(view(), Qt::Key_C, Qt::ControlModifier);
    document()->setCurrentFrame(36);
    const int steps = document()->undoStack()->count();
    QTest::keyClick(view(), Qt::Key_V, Qt::ControlModifier);
    EXPECT_EQ(keyFrames(), (std::vector<double>{0, 12, 24, 36, 48}));
    EXPECT_EQ(document()->undoStack()->count(), steps + 1);
    EXPECT_LT(poseDistance(node().clip.key(36 / 24.0), node().clip.key(12 / 24.0)), 1e-15);
    // The pasted keys are selected: Delete in the timeline deletes them, not the part.
    EXPECT_EQ(view()->selectedKeyCount(), 2);
    QTest::keyClick(view(), Qt::Key_Delete);
    EXPECT_EQ(document()->partCount(), 1);
    EXPECT_EQ(keyFrames(), (std::vector<double>{0, 12, 24}));
    EXPECT_EQ(document()->undoStack()->count(), steps + 2);
}

TEST_F(Timeline, IKeysThePoseAtTheCurrentFrame) {
    document()->setSelection({part, kNoJoint});
    document()->setCurrentFrame(40);
    window->currentView()->viewport()->setFocus();
    QTest::keyClick(window.get(), Qt::Key_I);
    EXPECT_EQ(keyFrames(), (std::vector<double>{0, 12, 24, 40}));
    EXPECT_EQ(document()->undoStack()->count(), 1);
}

TEST_F(Timeline, SpacePlaysInRealTimeAndPauses) {
    widgets::Playback* playback = window->timeline()->playback();
    window->currentView()->viewport()->setFocus();
    QElapsedTimer clock;
    clock.start();
    QTest::keyClick(window.get(), Qt::Key_Space);
    ASSERT_TRUE(playback->isPlaying());
    std::vector<int> seen;
    while (clock.elapsed() < 1000) {
        QTest::qWait(10);
        if (seen.empty() || seen.back() != document()->currentFrame())
            seen.push_back(document()->currentFrame());
    }
    QTest::keyClick(window.get(), Qt::Key_Space);
    const double seconds = clock.nsecsElapsed() * 1e-9;
    EXPECT_FALSE(playback->isPlaying());
    // Real time: 24 frames a second, whatever the drawing costs (never more
    // than the clock allows; a quarter second of slack for the start and the
    // last tick on a loaded machine).
    const int advanced = playback->framesShown() + playback->framesDropped();
    EXPECT_LE(advanced, seconds * 24.0 + 1.0);
    EXPECT_GE(advanced, (seconds - 0.25) * 24.0);
    EXPECT_EQ(document()->currentFrame(), advanced % 49);
    // The pose shown is the clip's at the shown frame.
    EXPECT_LT(poseDistance(node().pose, node().clip.evaluate(document()->currentTime())), 1e-12);
    EXPECT_GT(seen.size(), 5u);
    EXPECT_EQ(document()->undoStack()->count(), 0);
}

TEST(PlaybackFrame, LoopsTheRangeAndStartsInIt) {
    const model::TimelineSettings range{10, 19, 24.0};
    EXPECT_EQ(widgets::playbackFrame(12, range, 0.0), 12);
    EXPECT_EQ(widgets::playbackFrame(12, range, 1.0 / 24), 13);
    EXPECT_EQ(widgets::playbackFrame(12, range, 8.0 / 24), 10);  // 20 wraps to 10
    EXPECT_EQ(widgets::playbackFrame(0, range, 0.0), 10);
    EXPECT_EQ(widgets::playbackFrame(12, range, 10.0 * 100 / 24), 12);
}

TEST_F(Timeline, NamedClipsFromTheDockAndOnionSkinShow) {
    widgets::TimelineDock* dock = window->timeline();
    document()->setSelection({part, kNoJoint});
    dock->newClip(QStringLiteral("walk"));
    EXPECT_EQ(model::clipName(node().clip), "walk");
    EXPECT_EQ(node().clip.keyCount(), 0);
    dock->activateClip(QStringLiteral("Action"));
    EXPECT_EQ(node().clip.keyCount(), 3);
    dock->renameClip(QStringLiteral("wave"));
    EXPECT_EQ(model::clipName(node().clip), "wave");
    dock->newClip(QStringLiteral("walk"));  // refused: the name is taken
    EXPECT_EQ(model::clipName(node().clip), "wave");

    // Onion skin: ghosts of the keys either side tint the frame.
    document()->setCurrentFrame(6);
    widgets::Viewport* viewport = window->currentView()->viewport();
    const QImage plain = viewport->grabFramebuffer();
    auto* onionButton = dock->findChild<QToolButton*>(QStringLiteral("timelineOnion"));
    ASSERT_NE(onionButton, nullptr);
    onionButton->click();  // the dock's toggle reaches the viewport
    EXPECT_TRUE(viewport->onionSkin());
    const QImage onion = viewport->grabFramebuffer();
    long changed = 0;
    for (int y = 0; y < plain.height(); ++y)
        for (int x = 0; x < plain.width(); ++x)
            changed += plain.pixel(x, y) != onion.pixel(x, y);
    EXPECT_GT(changed, 500);
    window->grab().save(QStringLiteral(RIGMESH_TEST_OUTPUT "/studio_onion_skin.png"));
}

}  // namespace
}  // namespace rigmesh
