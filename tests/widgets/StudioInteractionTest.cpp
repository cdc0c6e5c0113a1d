// The studio end to end, as a newcomer uses it: sketch a part, see it in the
// outliner, undo and redo it, pose it by dragging a joint.
#include <gtest/gtest.h>

#include <QAction>
#include <QCheckBox>
#include <QCursor>
#include <QDoubleSpinBox>
#include <QIcon>
#include <QImage>
#include <QSettings>
#include <QStatusBar>
#include <QTemporaryDir>
#include <QTreeView>
#include <QUndoStack>
#include <QtMath>
#include <algorithm>
#include <set>

#include "DocumentView.h"
#include "EmbeddedExamples.h"
#include "MainWindow.h"
#include "StudioTestSupport.h"
#include "model/Document.h"
#include "model/DocumentExport.h"
#include "model/DocumentFile.h"
#include "model/commands/CreatePartCommand.h"
#include "model/commands/ImportPartsCommand.h"
#include "panels/OutlinerPanel.h"
#include "pose/PoseHierarchy.h"
#include "pose/Skinning.h"
#include "sketch/Sketch.h"
#include "viewport/ViewMath.h"

namespace rigmesh {
namespace {

using test::drag;
using test::ellipseStroke;
using test::settle;

class Studio : public testing::Test {
  protected:
    void SetUp() override {
        ASSERT_TRUE(recovery.isValid());
        window = std::make_unique<widgets::MainWindow>(recovery.path());
        window->resize(1200, 800);
        window->newDocument();
        settle(window.get());
    }
    widgets::Viewport* viewport() const { return window->currentView()->viewport(); }
    // The example biped as a part, framed: its id.
    model::PartId addExampleBiped() {
        const Sketch sketch = parseSketchJson(resources::exampleSketchJson(), "example.json");
        document()->undoStack()->push(
            model::CreatePartCommand::create(*document(), sketch.points, "biped").release());
        viewport()->frameAll();
        return document()->parts().front().id;
    }
    // A hand: the leaf joint farthest sideways.
    static JointId sidewaysHand(const Skeleton& skeleton) {
        JointId hand = kNoJoint;
        double side = -1;
        for (const Joint& joint : skeleton.joints())
            if (skeleton.degree(joint.id) == 1 && std::abs(joint.position.x()) > side) {
                side = std::abs(joint.position.x());
                hand = joint.id;
            }
        return hand;
    }
    // The quadruped kept with the tests (tests/data/sketches) as a part,
    // framed: its id.
    model::PartId addQuadruped() {
        const Sketch sketch =
            readSketchFile(std::string(RIGMESH_TEST_DATA) + "/sketches/quadruped.json");
        document()->undoStack()->push(
            model::CreatePartCommand::create(*document(), sketch.points, "quadruped").release());
        viewport()->frameAll();
        return document()->parts().front().id;
    }
    // The joint below the nearest junction (or the root) on the way up from
    // `joint`: the first joint a limb drag of `joint` moves.
    static JointId limbTop(const Skeleton& skeleton, JointId joint) {
        const PoseHierarchy h(skeleton);
        int top = h.indexOf(joint);
        while (h.parent(h.parent(top)) >= 0 && h.children(h.parent(top)).size() == 1)
            top = h.parent(top);
        return h.jointId(top);
    }
    // Bone indices of the subtree below `joint`, the bone ending at it
    // included: every bone a turn of that bone moves.
    static std::set<int> bonesFrom(const Skeleton& skeleton, JointId joint) {
        const PoseHierarchy h(skeleton);
        std::vector<bool> below(h.jointCount(), false);
        for (int j : h.parentFirstOrder())
            below[j] = h.jointId(j) == joint || (h.parent(j) >= 0 && below[h.parent(j)]);
        std::set<int> bones;
        for (int b = 0; b < h.boneCount(); ++b)
            if (below[h.boneTailJoint(b)])
                bones.insert(b);
        return bones;
    }
    // How many of the vertices weighted only by bones outside `moving` moved
    // from the rest shape in the part's current pose; `checked` counts them.
    int movedOutside(model::PartId id, const std::set<int>& moving, int& checked) const {
        const model::PartNode& node = document()->part(id);
        const std::vector<Vec3> posed = posePart(*node.part, node.pose).mesh.vertices;
        int moved = 0;
        checked = 0;
        for (std::size_t v = 0; v < posed.size(); ++v) {
            bool outside = true;
            for (const auto& [bone, w] : node.part->weights.perVertex[v])
                outside = outside && !moving.contains(bone);
            if (!outside)
                continue;
            ++checked;
            moved += (posed[v] - node.part->mesh.vertices[v]).norm() > 1e-9 ? 1 : 0;
        }
        return moved;
    }
    // A screen drag of `joint` by (dx, dy) pixels in ten steps.
    void dragJointBy(model::PartId id, JointId joint, double dx, double dy,
                     Qt::KeyboardModifiers modifiers = Qt::NoModifier) {
        const QVector3D at = viewport()->camera().project(viewport()->jointWorldPosition(id, joint),
                                                          QSizeF(viewport()->size()));
        std::vector<QPointF> path;
        for (int i = 0; i <= 10; ++i)
            path.emplace_back(at.x() + dx * i / 10, at.y() + dy * i / 10);
        drag(viewport(), path, modifiers);
    }
    // Sketches a long ellipse across the viewport: the new part's id.
    model::PartId sketchEllipse() {
        window->activateSketchTool();
        const QPointF centre(viewport()->width() / 2.0, viewport()->height() / 2.0);
        drag(viewport(), ellipseStroke(centre, 260, 50));
        EXPECT_EQ(document()->partCount(), 1);
        return document()->partCount() > 0 ? document()->parts().front().id : model::kNoPart;
    }
    model::Document* document() const { return window->currentDocument(); }

    QTemporaryDir recovery;
    std::unique_ptr<widgets::MainWindow> window;
};

TEST_F(Studio, ToolIconsAreOurOwnAndDraw) {
    // A missing SVG icon engine (libqt6svg6) would leave the tools blank.
    for (const char* name : {"sketch", "select", "pose"}) {
        const QIcon icon(QStringLiteral(":/icons/%1.svg").arg(QLatin1String(name)));
        const QImage image = icon.pixmap(24, 24).toImage();
        ASSERT_FALSE(image.isNull()) << name;
        int drawn = 0;
        for (int y = 0; y < image.height(); ++y)
            for (int x = 0; x < image.width(); ++x)
                drawn += qAlpha(image.pixel(x, y)) > 0 ? 1 : 0;
        EXPECT_GT(drawn, 40) << name << " draws almost nothing";
    }
    window->grab().copy(0, 0, 400, 60).save(QStringLiteral(RIGMESH_TEST_OUTPUT "/toolbar.png"));
}

TEST_F(Studio, SelectedPartIsOutlined) {
    const model::PartId id = sketchEllipse();
    ASSERT_NE(id, model::kNoPart);
    // Pixels of the outline's orange (1.0, 0.55, 0.1), flat, unlit.
    auto outlinePixels = [&] {
        const QImage frame = viewport()->grabFramebuffer().convertToFormat(QImage::Format_RGB32);
        int count = 0;
        for (int y = 0; y < frame.height(); ++y)
            for (int x = 0; x < frame.width(); ++x) {
                const QRgb p = frame.pixel(x, y);
                count += qRed(p) > 240 && std::abs(qGreen(p) - 140) < 12 && qBlue(p) < 40 ? 1 : 0;
            }
        return count;
    };
    document()->setSelection({id, kNoJoint});
    const int selected = outlinePixels();
    document()->clearSelection();
    const int unselected = outlinePixels();
    EXPECT_GT(selected, 500) << "an outline around the selected part";
    EXPECT_LT(unselected, selected / 20);
}

TEST(StudioFirstRun, MouseHintShowsOnceUntilTheFirstPartIsMade) {
    QSettings().remove(QStringLiteral("hints/mouseShown"));
    QTemporaryDir recovery;
    auto window = std::make_unique<widgets::MainWindow>(recovery.path());
    window->resize(1200, 800);
    window->newDocument();
    settle(window.get());
    auto* hint = window->findChild<QWidget*>(QStringLiteral("MouseHint"));
    ASSERT_NE(hint, nullptr);
    EXPECT_TRUE(hint->isVisible()) << "a first run shows the mouse gestures";
    window->grab().save(QStringLiteral(RIGMESH_TEST_OUTPUT "/studio_first_run.png"));
    window->activateSketchTool();
    widgets::Viewport* viewport = window->currentView()->viewport();
    drag(viewport,
         ellipseStroke(QPointF(viewport->width() / 2.0, viewport->height() / 2.0), 200, 60));
    ASSERT_EQ(window->currentDocument()->partCount(), 1);
    EXPECT_FALSE(hint->isVisible()) << "the first part closes it";
    // The next start does not show it again.
    auto again = std::make_unique<widgets::MainWindow>(recovery.path());
    again->newDocument();
    settle(again.get());
    EXPECT_FALSE(again->findChild<QWidget*>(QStringLiteral("MouseHint"))->isVisible());
}

TEST_F(Studio, MouseStrokeInTheViewportCreatesARiggedPart) {
    window->activateSketchTool();
    const QPointF centre(viewport()->width() / 2.0, viewport()->height() / 2.0);
    // For people: the stroke half drawn, as the window shows it.
    const auto stroke = ellipseStroke(centre, 220, 60);
    test::sendMouse(viewport(), QEvent::MouseButtonPress, stroke.front(), Qt::LeftButton,
                    Qt::LeftButton);
    for (std::size_t i = 1; i < stroke.size() / 2; ++i)
        test::sendMouse(viewport(), QEvent::MouseMove, stroke[i], Qt::NoButton, Qt::LeftButton);
    QTest::qWait(50);
    window->grab().save(QStringLiteral(RIGMESH_TEST_OUTPUT "/studio_sketching.png"));
    for (std::size_t i = stroke.size() / 2; i < stroke.size(); ++i)
        test::sendMouse(viewport(), QEvent::MouseMove, stroke[i], Qt::NoButton, Qt::LeftButton);
    test::sendMouse(viewport(), QEvent::MouseButtonRelease, stroke.back(), Qt::LeftButton,
                    Qt::NoButton);
    test::waitForJobs();  // the part is built in the background
    ASSERT_EQ(document()->partCount(), 1);
    const model::PartNode& node = document()->parts().front();
    EXPECT_GT(node.part->mesh.vertexCount(), 100);
    EXPECT_GE(node.part->skeleton.boneCount(), 1);
    EXPECT_EQ(document()->undoStack()->count(), 1);
    // The outliner lists it.
    EXPECT_EQ(window->outliner()->view()->model()->rowCount(), 1);
}

TEST_F(Studio, CtrlZRemovesTheSketchedPartAndCtrlShiftZBringsItBack) {
    window->activateSketchTool();
    const QPointF centre(viewport()->width() / 2.0, viewport()->height() / 2.0);
    drag(viewport(), ellipseStroke(centre, 200, 70));
    ASSERT_EQ(document()->partCount(), 1);
    QTest::keyClick(window.get(), Qt::Key_Z, Qt::ControlModifier);
    EXPECT_EQ(document()->partCount(), 0);
    EXPECT_EQ(window->outliner()->view()->model()->rowCount(), 0);
    QTest::keyClick(window.get(), Qt::Key_Z, Qt::ControlModifier | Qt::ShiftModifier);
    EXPECT_EQ(document()->partCount(), 1);
}

TEST_F(Studio, TooShortStrokeChangesNothing) {
    window->activateSketchTool();
    drag(viewport(), {QPointF(100, 100), QPointF(102, 101), QPointF(103, 103)});
    EXPECT_EQ(document()->partCount(), 0);
    EXPECT_EQ(document()->undoStack()->count(), 0);
}

TEST_F(Studio, ClickInTheSketchToolDoesNothingAndSaysNothing) {
    window->activateSketchTool();
    window->statusBar()->clearMessage();
    drag(viewport(), {QPointF(200, 200), QPointF(200, 200)});
    EXPECT_EQ(document()->partCount(), 0);
    EXPECT_EQ(document()->undoStack()->count(), 0);
    EXPECT_FALSE(window->statusBar()->currentMessage().contains(QStringLiteral("too short")));
}

TEST_F(Studio, LargeCircleDrawnFastInFewEventsBecomesAPart) {
    window->activateSketchTool();
    const QPointF centre(viewport()->width() / 2.0, viewport()->height() / 2.0);
    // 13 mouse events around a circle of radius 150 px: a quick flick.
    drag(viewport(), ellipseStroke(centre, 150, 150, 13));
    EXPECT_EQ(document()->partCount(), 1) << window->statusBar()->currentMessage().toStdString();
}

TEST_F(Studio, DraggingAJointChangesThePoseInOneUndoStep) {
    const model::PartId id = sketchEllipse();
    ASSERT_NE(id, model::kNoPart);
    const Skeleton& skeleton = document()->part(id).part->skeleton;
    ASSERT_GE(skeleton.boneCount(), 1);
    // The joint farthest from the root: dragging it bends the chain.
    JointId end = skeleton.joints().front().id;
    double farthest = -1;
    for (const Joint& joint : skeleton.joints()) {
        const double d = (joint.position - skeleton.joint(skeleton.root()).position).norm();
        if (d > farthest)
            farthest = d, end = joint.id;
    }
    const QVector3D screen = viewport()->camera().project(viewport()->jointWorldPosition(id, end),
                                                          QSizeF(viewport()->size()));
    const int stepsBefore = document()->undoStack()->count();
    window->activatePoseTool();
    std::vector<QPointF> path;
    for (int i = 0; i <= 10; ++i)
        path.emplace_back(screen.x(), screen.y() - 8.0 * i);
    drag(viewport(), path);
    EXPECT_FALSE(document()->part(id).pose.rotations.empty());
    EXPECT_EQ(document()->undoStack()->count(), stepsBefore + 1) << "a drag is one undo step";
    // For people: the posed part as the window shows it.
    window->grab().save(QStringLiteral(RIGMESH_TEST_OUTPUT "/studio_posed.png"));
    const QVector3D moved = viewport()->jointWorldPosition(id, end);
    EXPECT_GT((moved - viewport()->jointWorldPosition(id, skeleton.root())).length(), 0.0f);
    // A second drag of the same joint is a second undo step, and undoing it
    // goes back to the pose after the first drag.
    const rigmesh::Pose afterFirst = document()->part(id).pose;
    const QVector3D from = viewport()->camera().project(viewport()->jointWorldPosition(id, end),
                                                        QSizeF(viewport()->size()));
    std::vector<QPointF> again;
    for (int i = 0; i <= 10; ++i)
        again.emplace_back(from.x() + 6.0 * i, from.y());
    drag(viewport(), again);
    EXPECT_EQ(document()->undoStack()->count(), stepsBefore + 2) << "two drags, two undo steps";
    EXPECT_FALSE(model::identicalPoses(document()->part(id).pose, afterFirst));
    QTest::keyClick(window.get(), Qt::Key_Z, Qt::ControlModifier);
    EXPECT_TRUE(model::identicalPoses(document()->part(id).pose, afterFirst));
    QTest::keyClick(window.get(), Qt::Key_Z, Qt::ControlModifier);
    const auto& rotations = document()->part(id).pose.rotations;
    for (const auto& [joint, q] : rotations)
        EXPECT_NEAR(q.angularDistance(Eigen::Quaterniond::Identity()), 0.0, 1e-12);
}

TEST_F(Studio, TypedJointRotationPosesTheJointOneUndoStepPerValue) {
    const model::PartId id = sketchEllipse();
    ASSERT_NE(id, model::kNoPart);
    const Skeleton& skeleton = document()->part(id).part->skeleton;
    const JointId joint = skeleton.root();
    document()->setSelection({id, joint});
    auto* x = window->findChild<QDoubleSpinBox*>(QStringLiteral("jointRotationX"));
    auto* z = window->findChild<QDoubleSpinBox*>(QStringLiteral("jointRotationZ"));
    ASSERT_NE(x, nullptr);
    ASSERT_NE(z, nullptr);
    EXPECT_TRUE(x->isVisibleTo(window.get()));
    const int stepsBefore = document()->undoStack()->count();
    x->setValue(30.0);
    z->setValue(-45.0);
    EXPECT_EQ(document()->undoStack()->count(), stepsBefore + 2) << "one undo step per value";
    const Eigen::Quaterniond expected =
        Eigen::AngleAxisd(-M_PI / 4, Vec3::UnitZ()) * Eigen::AngleAxisd(M_PI / 6, Vec3::UnitX());
    EXPECT_LT(document()->part(id).pose.rotation(joint).angularDistance(expected), 1e-9);
    EXPECT_NEAR(x->value(), 30.0, 1e-6) << "the panel shows the angles as typed";
    EXPECT_NEAR(z->value(), -45.0, 1e-6);
    // For people: the panel beside the turned part.
    window->grab().save(QStringLiteral(RIGMESH_TEST_OUTPUT "/studio_joint_rotation.png"));
    document()->undoStack()->undo();
    EXPECT_LT(document()->part(id).pose.rotation(joint).angularDistance(
                  Eigen::Quaterniond(Eigen::AngleAxisd(M_PI / 6, Vec3::UnitX()))),
              1e-9);
    EXPECT_NEAR(z->value(), 0.0, 1e-6) << "the panel follows undo";
    document()->undoStack()->undo();
    EXPECT_LT(
        document()->part(id).pose.rotation(joint).angularDistance(Eigen::Quaterniond::Identity()),
        1e-12);
    document()->clearSelection();
    EXPECT_FALSE(x->isVisibleTo(window.get()));
}

// Sweeps the cursor `degrees` around `pivot` from `from` (pixels).
std::vector<QPointF> sweep(const QPointF& pivot, const QPointF& from, double degrees) {
    std::vector<QPointF> arc;
    const QPointF arm = from - pivot;
    for (int i = 0; i <= 10; ++i) {
        const double a = qDegreesToRadians(degrees * i / 10);
        arc.emplace_back(pivot.x() + arm.x() * std::cos(a) - arm.y() * std::sin(a),
                         pivot.y() + arm.x() * std::sin(a) + arm.y() * std::cos(a));
    }
    return arc;
}

TEST_F(Studio, DraggingABoneAnywhereTurnsItAboutItsHead) {
    const model::PartId id = sketchEllipse();
    ASSERT_NE(id, model::kNoPart);
    const Skeleton& skeleton = document()->part(id).part->skeleton;
    // A bone whose head is not the root: FK turns that bone only, by the
    // rotation of the joint it ends at.
    const Bone* grabbed = nullptr;
    for (const Bone& bone : skeleton.bones())
        if (bone.head != skeleton.root())
            grabbed = &bone;
    ASSERT_NE(grabbed, nullptr);
    window->activatePoseTool();  // first: the tool's options may resize the viewport
    QTest::qWait(50);
    const QSizeF size(viewport()->size());
    const QVector3D head =
        viewport()->camera().project(viewport()->jointWorldPosition(id, grabbed->head), size);
    const QVector3D tail =
        viewport()->camera().project(viewport()->jointWorldPosition(id, grabbed->tail), size);
    const QPointF middle((head.x() + tail.x()) / 2, (head.y() + tail.y()) / 2);
    const QPointF pivot(head.x(), head.y());
    ASSERT_FALSE(viewport()->jointAt(middle).has_value()) << "the bone's middle is no joint";
    const int stepsBefore = document()->undoStack()->count();
    drag(viewport(), sweep(pivot, middle, 30.0));
    EXPECT_EQ(document()->undoStack()->count(), stepsBefore + 1) << "one drag, one undo step";
    const rigmesh::Pose& pose = document()->part(id).pose;
    EXPECT_NEAR(pose.rotation(grabbed->tail).angularDistance(Eigen::Quaterniond::Identity()),
                qDegreesToRadians(30.0), qDegreesToRadians(3.0));  // perspective
    for (const auto& [joint, q] : pose.rotations) {
        if (joint != grabbed->tail) {
            EXPECT_NEAR(q.angularDistance(Eigen::Quaterniond::Identity()), 0.0, 1e-12)
                << "joint " << joint << " turned";
        }
    }
    EXPECT_EQ(document()->selection().joint, grabbed->tail)
        << "the joint standing for the turned bone is selected";
}

// Issue 11 item 5, FK by bone at a junction: turning the biped's upper arm
// (the bone leaving the chest) moves its arm only, never the head, the
// other arm or the body.
TEST_F(Studio, TurningABoneLeavingAJunctionMovesNoSibling) {
    const model::PartId id = addExampleBiped();
    const Skeleton& skeleton = document()->part(id).part->skeleton;
    const JointId shoulder = limbTop(skeleton, sidewaysHand(skeleton));
    const JointId chest = widgets::poseParent(skeleton, shoulder);
    ASSERT_GE(skeleton.degree(chest), 3) << "the upper arm leaves a junction";
    window->activatePoseTool();
    QTest::qWait(50);
    const QSizeF size(viewport()->size());
    const QVector3D head =
        viewport()->camera().project(viewport()->jointWorldPosition(id, chest), size);
    const QVector3D tail =
        viewport()->camera().project(viewport()->jointWorldPosition(id, shoulder), size);
    const QPointF middle((head.x() + tail.x()) / 2, (head.y() + tail.y()) / 2);
    ASSERT_FALSE(viewport()->jointAt(middle).has_value());
    drag(viewport(), sweep(QPointF(head.x(), head.y()), middle, -35.0));
    const rigmesh::Pose& pose = document()->part(id).pose;
    EXPECT_GT(pose.rotation(shoulder).angularDistance(Eigen::Quaterniond::Identity()),
              qDegreesToRadians(25.0));
    for (const auto& [joint, q] : pose.rotations)
        if (joint != shoulder) {
            EXPECT_EQ(q.coeffs(), Eigen::Quaterniond::Identity().coeffs()) << "joint " << joint;
        }
    int checked = 0;
    EXPECT_EQ(movedOutside(id, bonesFrom(skeleton, shoulder), checked), 0);
    EXPECT_GT(checked, static_cast<int>(document()->part(id).part->mesh.vertexCount()) / 2);
    EXPECT_EQ(document()->selection().joint, shoulder);
    window->grab().save(QStringLiteral(RIGMESH_TEST_OUTPUT "/studio_pose_fk_junction.png"));
}

TEST_F(Studio, PoseToolOptionReachesThroughTheWholeBody) {
    const model::PartId id = addExampleBiped();
    const Skeleton& skeleton = document()->part(id).part->skeleton;
    window->activatePoseTool();
    QTest::qWait(50);
    auto* wholeBody = window->findChild<QCheckBox*>(QStringLiteral("poseWholeBody"));
    ASSERT_NE(wholeBody, nullptr);
    EXPECT_TRUE(wholeBody->isVisibleTo(window.get())) << "the Tool Options dock shows it";
    wholeBody->setChecked(true);
    // A hand (the leaf farthest sideways), dragged: with the option on, the
    // chain passes its junction, so the bone ending at a joint of degree 3
    // or more (the spine, into the chest) turns.
    const JointId hand = sidewaysHand(skeleton);
    const QVector3D at = viewport()->camera().project(viewport()->jointWorldPosition(id, hand),
                                                      QSizeF(viewport()->size()));
    std::vector<QPointF> path;
    for (int i = 0; i <= 10; ++i)
        path.emplace_back(at.x() - 4.0 * i, at.y() - 8.0 * i);
    drag(viewport(), path);
    bool junctionTurned = false;
    for (const auto& [joint, q] : document()->part(id).pose.rotations)
        junctionTurned =
            junctionTurned || (skeleton.degree(joint) >= 3 &&
                               q.angularDistance(Eigen::Quaterniond::Identity()) > 1e-6);
    EXPECT_TRUE(junctionTurned);
    wholeBody->setChecked(false);
    window->activateSketchTool();
    EXPECT_FALSE(wholeBody->isVisibleTo(window.get())) << "other tools show their own options";
}

TEST_F(Studio, DraggingTheRingOfTheSelectedJointTurnsIt) {
    const model::PartId id = sketchEllipse();
    ASSERT_NE(id, model::kNoPart);
    const Skeleton& skeleton = document()->part(id).part->skeleton;
    const JointId joint = skeleton.root();
    window->activatePoseTool();
    QTest::qWait(50);
    document()->setSelection({id, joint});
    const QVector3D at = viewport()->camera().project(viewport()->jointWorldPosition(id, joint),
                                                      QSizeF(viewport()->size()));
    const QPointF centre(at.x(), at.y());
    // Grab the ring straight above the joint (44 px out) and sweep 40 degrees.
    std::vector<QPointF> arc;
    for (int i = 0; i <= 10; ++i) {
        const double a = qDegreesToRadians(-90.0 + 4.0 * i);
        arc.emplace_back(centre.x() + 44.0 * std::cos(a), centre.y() + 44.0 * std::sin(a));
    }
    ASSERT_FALSE(viewport()->jointAt(arc.front()).has_value());
    const int stepsBefore = document()->undoStack()->count();
    drag(viewport(), arc);
    window->grab().save(QStringLiteral(RIGMESH_TEST_OUTPUT "/studio_pose_ring.png"));
    EXPECT_EQ(document()->undoStack()->count(), stepsBefore + 1);
    const double turned =
        document()->part(id).pose.rotation(joint).angularDistance(Eigen::Quaterniond::Identity());
    EXPECT_NEAR(turned, qDegreesToRadians(40.0), qDegreesToRadians(4.0));
}

// Issue 11 items 2 and 5: a plain drag of a hand turns its arm's bones up to
// and including the one leaving the chest, and no vertex weighted only by
// other bones (the other arm, the head, the body, the legs) moves; with Alt
// the chain reaches the root, so the chest turns and the other arm and the
// head move with it.
TEST_F(Studio, DraggingAHandMovesNoVertexOutsideItsArmUnlessAltIsHeld) {
    const model::PartId id = addExampleBiped();
    const Skeleton& skeleton = document()->part(id).part->skeleton;
    const JointId hand = sidewaysHand(skeleton);
    const JointId shoulder = limbTop(skeleton, hand);
    ASSERT_NE(shoulder, hand) << "the arm has two bones";
    const std::set<int> arm = bonesFrom(skeleton, shoulder);
    window->activatePoseTool();
    QTest::qWait(50);
    const QVector3D shoulderBefore = viewport()->jointWorldPosition(id, shoulder);
    dragJointBy(id, hand, -30.0, -60.0);
    ASSERT_FALSE(document()->part(id).pose.rotations.empty());
    int checked = 0;
    const int moved = movedOutside(id, arm, checked);
    std::fprintf(stderr, "vertices weighted only outside the dragged arm: %d, moved %d\n", checked,
                 moved);
    EXPECT_EQ(moved, 0) << "vertices outside the arm moved (of " << checked << ")";
    EXPECT_GT(checked, static_cast<int>(document()->part(id).part->mesh.vertexCount()) / 2);
    EXPECT_GT((viewport()->jointWorldPosition(id, shoulder) - shoulderBefore).length(), 1e-4f)
        << "the arm's first bone, leaving the chest, turned too";
    window->grab().save(QStringLiteral(RIGMESH_TEST_OUTPUT "/studio_pose_limb.png"));

    // Alt: whole-body reach, the other arm and the head come along.
    document()->undoStack()->undo();
    dragJointBy(id, hand, -30.0, -60.0, Qt::AltModifier);
    EXPECT_GT(movedOutside(id, arm, checked), 0) << "Alt + drag moved nothing outside the arm";
    for (const Joint& joint : skeleton.joints())
        if (skeleton.degree(joint.id) == 1 && joint.id != hand && joint.position.y() > 0) {
            const QVector3D rest = QVector3D(joint.position.x(), joint.position.y(), 0);
            EXPECT_GT((viewport()->jointWorldPosition(id, joint.id) - rest).length(), 1e-4f)
                << "joint " << joint.id << " (the other hand or the head) stayed with Alt";
        }
}

// Issue 11 "Done when": the quadruped's head pulled with the pose tool moves
// the neck and head only, never a leg.
TEST_F(Studio, DraggingTheQuadrupedsHeadMovesNoLeg) {
    const model::PartId id = addQuadruped();
    const Skeleton& skeleton = document()->part(id).part->skeleton;
    JointId head = kNoJoint;  // the highest leaf
    for (const Joint& joint : skeleton.joints())
        if (skeleton.degree(joint.id) == 1 &&
            (head == kNoJoint || joint.position.y() > skeleton.joint(head).position.y()))
            head = joint.id;
    const JointId neck = limbTop(skeleton, head);
    window->activatePoseTool();
    QTest::qWait(50);
    dragJointBy(id, head, 40.0, -50.0);
    ASSERT_FALSE(document()->part(id).pose.rotations.empty());
    int checked = 0;
    EXPECT_EQ(movedOutside(id, bonesFrom(skeleton, neck), checked), 0);
    EXPECT_GT(checked, static_cast<int>(document()->part(id).part->mesh.vertexCount()) / 2);
    int feet = 0;
    for (const Joint& joint : skeleton.joints())
        if (skeleton.degree(joint.id) == 1 && joint.id != head) {
            ++feet;
            const QVector3D rest = QVector3D(joint.position.x(), joint.position.y(), 0);
            EXPECT_LT((viewport()->jointWorldPosition(id, joint.id) - rest).length(), 1e-6f)
                << "foot " << joint.id;
        }
    EXPECT_EQ(feet, 4);
    EXPECT_GT((viewport()->jointWorldPosition(id, head) -
               QVector3D(skeleton.joint(head).position.x(), skeleton.joint(head).position.y(), 0))
                  .length(),
              0.05f);
    window->grab().save(QStringLiteral(RIGMESH_TEST_OUTPUT "/studio_pose_quadruped.png"));
}

// Issue 14 item 1: the weight views colour the surface on the GPU. The
// selected joint's bone shows hot (red) where it leads and cold (blue) or
// dark (zero) elsewhere; dominant bones show several colours.
TEST_F(Studio, WeightViewsColourTheSurfaceBySkinWeights) {
    const model::PartId biped = addExampleBiped();
    const Skeleton& skeleton = document()->part(biped).part->skeleton;
    const JointId hand = sidewaysHand(skeleton);
    document()->setSelection({biped, hand});
    auto count = [&](auto&& test) {
        const QImage image = viewport()->grabFramebuffer();
        int n = 0;
        for (int y = 0; y < image.height(); y += 2)
            for (int x = 0; x < image.width(); x += 2)
                n += test(QColor(image.pixel(x, y))) ? 1 : 0;
        return n;
    };
    auto red = [](const QColor& c) { return c.red() > 150 && c.green() < 90 && c.blue() < 90; };
    auto blue = [](const QColor& c) { return c.blue() > 120 && c.red() < 60 && c.green() < 90; };
    // Before the view is on, only the grid's red axis is red.
    const int redBefore = count(red);
    const int blueBefore = count(blue);
    viewport()->setWeightView(widgets::WeightView::SelectedBone);
    QTest::qWait(50);
    EXPECT_GT(count(red), redBefore + 50) << "the hand's bone leads its hand";
    EXPECT_GT(count(blue), blueBefore + 50) << "the rest of the body is cold or zero";
    window->grab().save(QStringLiteral(RIGMESH_TEST_OUTPUT "/studio_weights_bone.png"));
    // Hovering the hand lists its vertex's weights in the status bar.
    const Vec3 handAt = skeleton.joint(hand).position;
    const QVector3D p = viewport()->camera().project(
        QVector3D(float(handAt.x()), float(handAt.y()), float(handAt.z())),
        QSizeF(viewport()->size()));
    test::sendMouse(viewport(), QEvent::MouseMove, QPointF(p.x(), p.y()), Qt::NoButton,
                    Qt::NoButton);
    const QString status = window->statusBar()->currentMessage();
    EXPECT_TRUE(status.startsWith(QStringLiteral("Vertex ")) && status.contains("of biped: bone"))
        << status.toStdString();
    viewport()->setWeightView(widgets::WeightView::DominantBone);
    QTest::qWait(50);
    std::set<QRgb> colours;
    const QImage image = viewport()->grabFramebuffer();
    for (int y = 0; y < image.height(); y += 3)
        for (int x = 0; x < image.width(); x += 3)
            colours.insert(image.pixel(x, y) & 0xF0F0F0);
    EXPECT_GT(colours.size(), 20u);
    window->grab().save(QStringLiteral(RIGMESH_TEST_OUTPUT "/studio_weights_dominant.png"));
    viewport()->setWeightView(widgets::WeightView::Off);
}

// Issue 14 item 3: a brush stroke over the hand paints the selected bone's
// weights there only, keeps every sum at 1, is one undo step, and Esc in
// the middle of a stroke puts the weights back.
TEST_F(Studio, PaintingTheHandChangesItsWeightsInOneUndoStep) {
    const model::PartId biped = addExampleBiped();
    const Part& rest = *document()->part(biped).part;
    const JointId hand = sidewaysHand(rest.skeleton);
    // The bone ending at the shoulder: paint it onto the hand.
    JointId shoulder = kNoJoint;
    for (const Bone& bone : rest.skeleton.bones())
        if (bone.tail == hand)
            shoulder = bone.head;
    ASSERT_NE(shoulder, kNoJoint);
    document()->setSelection({biped, shoulder});
    window->activatePaintTool();
    QTest::qWait(50);
    const QByteArray before = model::DocumentFile::toBytes(*document());
    const int steps = document()->undoStack()->count();
    const Vec3 h = rest.skeleton.joint(hand).position;
    const QVector3D p = viewport()->camera().project(QVector3D(float(h.x()), float(h.y()), 0.2f),
                                                     QSizeF(viewport()->size()));
    // From the hand towards the body, on the arm.
    const double inward = h.x() < 0.0 ? 1.0 : -1.0;
    std::vector<QPointF> stroke;
    for (int i = 0; i <= 12; ++i)
        stroke.emplace_back(p.x() + inward * 5 * i, p.y());
    ASSERT_TRUE(viewport()->surfaceAt(stroke.front()).has_value());
    drag(viewport(), stroke);
    EXPECT_EQ(document()->undoStack()->count(), steps + 1)
        << "a stroke is one undo step: " << window->statusBar()->currentMessage().toStdString();
    const Part& painted = *document()->part(biped).part;
    EXPECT_TRUE(painted.validate().empty());
    EXPECT_NE(painted.weights.perVertex, rest.weights.perVertex);
    // Far from the hand (the other side of the body) nothing changed.
    for (int v = 0; v < painted.mesh.vertexCount(); ++v)
        if (painted.mesh.vertices[v].x() * h.x() < 0.0) {
            ASSERT_EQ(painted.weights.perVertex[v], rest.weights.perVertex[v]) << v;
        }
    QTest::qWait(50);
    window->grab().save(QStringLiteral(RIGMESH_TEST_OUTPUT "/studio_paint.png"));
    QTest::keyClick(window.get(), Qt::Key_Z, Qt::ControlModifier);
    EXPECT_EQ(model::DocumentFile::toBytes(*document()), before);
    // Esc in the middle of a stroke puts the weights back.
    viewport()->setFocus(Qt::MouseFocusReason);
    test::sendMouse(viewport(), QEvent::MouseButtonPress, stroke.front(), Qt::LeftButton,
                    Qt::LeftButton);
    for (const QPointF& point : stroke)
        test::sendMouse(viewport(), QEvent::MouseMove, point, Qt::NoButton, Qt::LeftButton);
    QTest::keyClick(viewport(), Qt::Key_Escape);
    test::sendMouse(viewport(), QEvent::MouseButtonRelease, stroke.back(), Qt::LeftButton,
                    Qt::NoButton);
    EXPECT_EQ(model::DocumentFile::toBytes(*document()), before);
    EXPECT_EQ(document()->undoStack()->count(), steps + 1);  // the undone stroke, redoable

    // Tools > Weights > Limit Total keeps at most four bones per vertex.
    QAction* limit = nullptr;
    for (QAction* action : window->findChildren<QAction*>())
        if (action->text() == QStringLiteral("&Limit Total (4 bones)"))
            limit = action;
    ASSERT_NE(limit, nullptr);
    limit->trigger();
    for (const auto& list : document()->part(biped).part->weights.perVertex)
        EXPECT_LE(list.size(), 4u);
    EXPECT_TRUE(document()->part(biped).part->validate().empty());
}

TEST_F(Studio, DraggingAPartMovesItAndCtrlDragTurnsIt) {
    window->activateSketchTool();
    const QPointF centre(viewport()->width() / 2.0, viewport()->height() / 2.0);
    drag(viewport(), ellipseStroke(centre, 220, 60));
    ASSERT_EQ(document()->partCount(), 1);
    const model::PartId id = document()->parts().front().id;
    const model::Placement before = document()->part(id).placement;
    window->activateSelectTool();
    QTest::qWait(50);  // the first paint frames the new part
    // A pixel on the surface but away from every joint.
    QPointF grab;
    bool found = false;
    for (double dy = 10; dy < 200 && !found; dy += 5) {
        grab = QPointF(centre.x() + 30, centre.y() + dy);
        found = viewport()->partAt(grab).has_value() && !viewport()->jointAt(grab).has_value();
    }
    ASSERT_TRUE(found);
    std::vector<QPointF> path;
    for (int i = 0; i <= 10; ++i)
        path.emplace_back(grab.x() + 5.0 * i, grab.y());
    drag(viewport(), path);
    const model::Placement moved = document()->part(id).placement;
    EXPECT_GT((moved.translation - before.translation).norm(), 0.0);
    const int steps = document()->undoStack()->count();
    // Ctrl + drag from a point on the part sweeps around its centre.
    std::vector<QPointF> arc;
    for (int i = 0; i <= 10; ++i) {
        const double a = 0.05 * i;
        arc.emplace_back(grab.x() + 50 + 50 * std::cos(a), grab.y() - 50 * std::sin(a));
    }
    drag(viewport(), arc, Qt::ControlModifier);
    const model::Placement turned = document()->part(id).placement;
    EXPECT_GT(turned.rotation.angularDistance(moved.rotation), 0.1);
    EXPECT_EQ(document()->undoStack()->count(), steps + 1) << "a drag is one undo step";
    // Another plain drag of the same part is another step; undo takes back
    // only that one.
    drag(viewport(), path);
    EXPECT_EQ(document()->undoStack()->count(), steps + 2) << "two drags, two undo steps";
    QTest::keyClick(window.get(), Qt::Key_Z, Qt::ControlModifier);
    EXPECT_EQ(document()->part(id).placement, turned);
    QTest::keyClick(window.get(), Qt::Key_Z, Qt::ControlModifier);
    EXPECT_EQ(document()->part(id).placement, moved);
}

TEST_F(Studio, UnriggedImportedMeshIsDrawnAndCannotBePosed) {
    window->activateSketchTool();
    const QPointF centre(viewport()->width() / 2.0, viewport()->height() / 2.0);
    drag(viewport(), ellipseStroke(centre, 220, 60));
    ASSERT_EQ(document()->partCount(), 1);
    const QString obj = recovery.filePath(QStringLiteral("static.obj"));
    model::exportDocument(*document(), obj.toStdString());
    document()->undoStack()->push(model::ImportPartsCommand::create(*document(), obj).release());
    ASSERT_EQ(document()->partCount(), 2);
    viewport()->frameAll();
    QTest::qWait(50);  // paints both parts; the unrigged one at rest
    const QImage frame = viewport()->grabFramebuffer();
    EXPECT_FALSE(frame.isNull());
    window->activatePoseTool();
    document()->setSelection({document()->parts().back().id, kNoJoint});
    QTest::keyClick(window.get(), Qt::Key_R, Qt::AltModifier);  // reset pose: nothing to do
    EXPECT_EQ(document()->partCount(), 2);
}

TEST_F(Studio, SavedDocumentReopensWithTheSameContent) {
    window->activateSketchTool();
    const QPointF centre(viewport()->width() / 2.0, viewport()->height() / 2.0);
    drag(viewport(), ellipseStroke(centre, 220, 60));
    ASSERT_EQ(document()->partCount(), 1);
    const QString path = recovery.filePath(QStringLiteral("saved.rigmesh"));
    model::DocumentFile::save(*document(), path);
    const QByteArray saved = model::DocumentFile::toBytes(*document());
    EXPECT_FALSE(document()->isModified());
    ASSERT_TRUE(window->closeDocument(window->tabs()->currentIndex()));
    ASSERT_TRUE(window->openFile(path));
    EXPECT_EQ(model::DocumentFile::toBytes(*document()), saved);
}

}  // namespace
}  // namespace rigmesh

namespace rigmesh {
namespace {

// The camel body and a leg overlapping its front (the recipe's placement).
class StudioMerge : public testing::Test {
  protected:
    void SetUp() override {
        ASSERT_TRUE(recovery.isValid());
        window = std::make_unique<widgets::MainWindow>(recovery.path());
        window->resize(1200, 800);
        window->newDocument();
        settle(window.get());
        model::Document& d = *window->currentDocument();
        const std::string dir = RIGMESH_SHARED_SKETCHES;
        d.undoStack()->push(model::CreatePartCommand::create(
                                d, readSketchFile(dir + "/camel_body.json").points, "body")
                                .release());
        model::Placement legPlace;
        legPlace.translation = Vec3(1.7, -0.55, 0.3);
        d.undoStack()->push(
            model::CreatePartCommand::create(d, readSketchFile(dir + "/camel_leg.json").points,
                                             "leg", {}, legPlace)
                .release());
        viewport()->frameAll();
        window->activateMergeTool();
        QTest::qWait(50);
    }
    widgets::Viewport* viewport() const { return window->currentView()->viewport(); }
    model::Document* document() const { return window->currentDocument(); }
    // A pixel on the leg's lower half, far from the body.
    QPointF onTheLeg() const {
        const QVector3D p =
            viewport()->camera().project(QVector3D(1.7f, -2.6f, 0.3f), QSizeF(viewport()->size()));
        return {p.x(), p.y()};
    }
    std::vector<QPointF> shortDrag() const {
        std::vector<QPointF> path;
        for (int i = 0; i <= 6; ++i)
            path.emplace_back(onTheLeg().x() + i, onTheLeg().y() - i);
        return path;
    }

    QTemporaryDir recovery;
    std::unique_ptr<widgets::MainWindow> window;
};

TEST_F(StudioMerge, DraggingALegIntoTheBodyMergesThemInOneUndoStep) {
    ASSERT_EQ(document()->partCount(), 2);
    ASSERT_TRUE(viewport()->partAt(onTheLeg()).has_value());
    const QByteArray before = model::DocumentFile::toBytes(*document());
    const int steps = document()->undoStack()->count();
    drag(viewport(), shortDrag());
    ASSERT_EQ(document()->partCount(), 1) << window->statusBar()->currentMessage().toStdString();
    EXPECT_EQ(document()->undoStack()->count(), steps + 1);
    EXPECT_TRUE(document()->parts()[0].part->validateSolid().empty());
    EXPECT_TRUE(window->statusBar()->currentMessage().contains(QStringLiteral("merged in")))
        << window->statusBar()->currentMessage().toStdString();
    QTest::qWait(50);
    window->grab().save(QStringLiteral(RIGMESH_TEST_OUTPUT "/studio_merged.png"));
    // The paper's Fig. 9a view: where the local re-skin differs from a
    // global one (near the seam, warmer than the untouched blue).
    viewport()->setWeightView(widgets::WeightView::GlobalDifference);
    QTest::qWait(50);
    const QImage difference = viewport()->grabFramebuffer();
    int warm = 0, cold = 0;
    for (int y = 0; y < difference.height(); y += 2)
        for (int x = 0; x < difference.width(); x += 2) {
            const QColor c(difference.pixel(x, y));
            warm += c.green() > 120 && c.blue() < 200 ? 1 : 0;
            cold += c.blue() > 120 && c.green() < 60 && c.red() < 60 ? 1 : 0;
        }
    EXPECT_GT(cold, warm) << "most of the part is as the global computation";
    window->grab().save(QStringLiteral(RIGMESH_TEST_OUTPUT "/studio_weights_difference.png"));
    viewport()->setWeightView(widgets::WeightView::Off);
    QTest::keyClick(window.get(), Qt::Key_Z, Qt::ControlModifier);
    EXPECT_EQ(model::DocumentFile::toBytes(*document()), before);
}

TEST_F(StudioMerge, EscapeDuringTheDragPutsThePartBackAndMergesNothing) {
    const model::PartId leg = document()->parts()[1].id;
    const model::Placement start = document()->part(leg).placement;
    const int steps = document()->undoStack()->count();
    const std::vector<QPointF> path = shortDrag();
    viewport()->setFocus(Qt::MouseFocusReason);
    test::sendMouse(viewport(), QEvent::MouseButtonPress, path.front(), Qt::LeftButton,
                    Qt::LeftButton);
    for (const QPointF& p : path)
        test::sendMouse(viewport(), QEvent::MouseMove, p, Qt::NoButton, Qt::LeftButton);
    EXPECT_FALSE(document()->part(leg).placement == start);  // the live preview
    QTest::qWait(50);
    window->grab().save(QStringLiteral(RIGMESH_TEST_OUTPUT "/studio_merge_drag.png"));
    QTest::keyClick(viewport(), Qt::Key_Escape);
    EXPECT_EQ(document()->part(leg).placement, start);
    test::sendMouse(viewport(), QEvent::MouseButtonRelease, path.back(), Qt::LeftButton,
                    Qt::NoButton);
    EXPECT_EQ(document()->partCount(), 2);
    EXPECT_EQ(document()->undoStack()->count(), steps);
}

// The pixel of a document point.
QPointF pixelOf(const widgets::Viewport& viewport, const Vec3& point) {
    const QVector3D p = viewport.camera().project(
        QVector3D(float(point.x()), float(point.y()), float(point.z())), QSizeF(viewport.size()));
    return {p.x(), p.y()};
}

TEST_F(StudioMerge, ALineAcrossThePartCutsItInTwoInOneUndoStep) {
    window->activateCutTool();
    const QByteArray before = model::DocumentFile::toBytes(*document());
    // Across the body's back half, from above it to below it.
    const QPointF top = pixelOf(*viewport(), Vec3(-1.2, 1.6, 0.0));
    const QPointF bottom = pixelOf(*viewport(), Vec3(-1.1, -1.6, 0.0));
    ASSERT_FALSE(viewport()->partAt(top).has_value());
    ASSERT_FALSE(viewport()->partAt(bottom).has_value());
    drag(viewport(), {top, (top + bottom) / 2, bottom});
    ASSERT_EQ(document()->partCount(), 3) << window->statusBar()->currentMessage().toStdString();
    for (const model::PartNode& node : document()->parts())
        EXPECT_TRUE(node.part->validateSolid().empty());
    QTest::qWait(50);
    window->grab().save(QStringLiteral(RIGMESH_TEST_OUTPUT "/studio_cut.png"));
    QTest::keyClick(window.get(), Qt::Key_Z, Qt::ControlModifier);
    EXPECT_EQ(model::DocumentFile::toBytes(*document()), before);
    // A line that starts on the part cuts nothing and says why.
    drag(viewport(), {pixelOf(*viewport(), Vec3(-1.2, 0.0, 0.0)), bottom});
    EXPECT_EQ(document()->partCount(), 2);
    EXPECT_TRUE(window->statusBar()->currentMessage().contains(QStringLiteral("Nothing cut")));
}

TEST_F(StudioMerge, KSplitsTheBoneUnderTheCursorAndShiftKDeletesIt) {
    const model::PartId leg = document()->parts()[1].id;
    ASSERT_EQ(document()->part(leg).part->skeleton.boneCount(), 1);
    viewport()->setFocus(Qt::MouseFocusReason);
    const QPointF knee = pixelOf(*viewport(), Vec3(1.7, -2.0, 0.3));
    QCursor::setPos(viewport()->mapToGlobal(knee.toPoint()));
    QTest::qWait(20);
    QTest::keyClick(viewport(), Qt::Key_K);
    ASSERT_EQ(document()->part(leg).part->skeleton.boneCount(), 2)
        << window->statusBar()->currentMessage().toStdString();
    EXPECT_TRUE(document()->part(leg).part->validateSolid().empty());
    QCursor::setPos(viewport()->mapToGlobal(pixelOf(*viewport(), Vec3(1.7, -3.0, 0.3)).toPoint()));
    QTest::qWait(20);
    QTest::keyClick(viewport(), Qt::Key_K, Qt::ShiftModifier);
    EXPECT_EQ(document()->part(leg).part->skeleton.boneCount(), 1);
    QTest::keyClick(window.get(), Qt::Key_Z, Qt::ControlModifier);
    EXPECT_EQ(document()->part(leg).part->skeleton.boneCount(), 2);
}

}  // namespace
}  // namespace rigmesh
