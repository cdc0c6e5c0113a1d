// Posing in the studio: a joint drag is one undo step, typed
// rotations, FK by bone and by the rotation ring, a limb drag moving no
// vertex outside its limb unless Alt is held, the quadruped's head moving
// no leg.
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
#include "StudioPoseFixture.h"
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
using Studio = test::StudioPose;

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
    window->activateTool<widgets::PoseTool>();
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
    window->activateTool<widgets::PoseTool>();  // first: the tool's options may resize the viewport
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

// FK by bone at a junction: turning the biped's upper arm
// (the bone leaving the chest) moves its arm only, never the head, the
// other arm or the body.
TEST_F(Studio, TurningABoneLeavingAJunctionMovesNoSibling) {
    const model::PartId id = addExampleBiped();
    const Skeleton& skeleton = document()->part(id).part->skeleton;
    const JointId shoulder = limbTop(skeleton, sidewaysHand(skeleton));
    const JointId chest = widgets::poseParent(skeleton, shoulder);
    ASSERT_GE(skeleton.degree(chest), 3) << "the upper arm leaves a junction";
    window->activateTool<widgets::PoseTool>();
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
    window->activateTool<widgets::PoseTool>();
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
    window->activateTool<widgets::SketchTool>();
    EXPECT_FALSE(wholeBody->isVisibleTo(window.get())) << "other tools show their own options";
}

TEST_F(Studio, DraggingTheRingOfTheSelectedJointTurnsIt) {
    const model::PartId id = sketchEllipse();
    ASSERT_NE(id, model::kNoPart);
    const Skeleton& skeleton = document()->part(id).part->skeleton;
    const JointId joint = skeleton.root();
    window->activateTool<widgets::PoseTool>();
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

// A plain drag of a hand turns its arm's bones up to
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
    const std::set<BoneId> arm = bonesFrom(skeleton, shoulder);
    window->activateTool<widgets::PoseTool>();
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

// The quadruped's head pulled with the pose tool moves
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
    window->activateTool<widgets::PoseTool>();
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

// The weight views colour the surface on the GPU. The
// selected joint's bone shows hot (red) where it leads and cold (blue) or
// dark (zero) elsewhere; dominant bones show several colours.

}  // namespace
}  // namespace rigmesh
