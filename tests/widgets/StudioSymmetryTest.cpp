// Weight paint and posing as in Blender, by mouse and keys on the example
// biped: Subtract where one bone leads hands the weight to the parent bone,
// a stroke may start beside the part, X-mirror paints the other arm's bone
// on the other side, a pinned shoulder holds under Alt + drag of the other
// hand, and Edit > Mirror Pose (Ctrl+Shift+V) flips a pose left to right.
#include <gtest/gtest.h>

#include <QCheckBox>
#include <QStatusBar>
#include <QUndoStack>
#include <iostream>

#include "MirrorPaintSymmetry.h"
#include "PartWeightOf.h"
#include "StudioPoseFixture.h"
#include "model/DocumentFile.h"
#include "pose/ForwardKinematics.h"
#include "rig/MirrorSymmetry.h"
#include "viewport/ViewMath.h"

namespace rigmesh {
namespace {

using test::drag;
using testsupport::weightOf;

class StudioSymmetry : public test::StudioPose {
  protected:
    const Part& part() const { return *document()->parts().front().part; }
    QString status() const { return window->statusBar()->currentMessage(); }
    // The leaf joint farthest to the right (+x) or left (-x).
    JointId handOn(double side) const {
        JointId hand = kNoJoint;
        for (const Joint& joint : part().skeleton.joints())
            if (part().skeleton.degree(joint.id) == 1 &&
                (hand == kNoJoint ||
                 side * joint.position.x() > side * part().skeleton.joint(hand).position.x()))
                hand = joint.id;
        return hand;
    }
    widgets::PaintTool* paintTool() const { return window->tools()->find<widgets::PaintTool>(); }
    // A stroke along x at the height of `at`, in front of the sketch plane.
    std::vector<QPointF> strokeAlong(const Vec3& at, double fromX, double toX) const {
        std::vector<QPointF> stroke;
        for (int i = 0; i <= 12; ++i) {
            const double x = fromX + (toX - fromX) * i / 12.0;
            stroke.push_back(onScreen(Vec3(x, at.y(), 0.15)));
        }
        return stroke;
    }
};

// Blender's auto-normalise: Subtract on the hand, which its bone alone
// leads, gives the weight to the forearm's bone; a stroke started beside the
// part paints once it reaches it.
TEST_F(StudioSymmetry, SubtractOnAOneBoneRegionMovesTheWeightToTheParentBone) {
    const model::PartId biped = addExampleBiped();
    const JointId hand = handOn(1.0);
    const BoneId bone = *boneForJoint(part().skeleton, hand);
    const BoneId parent = *part().skeleton.parentBone(bone);
    // The hand's vertices its bone alone leads.
    std::vector<int> alone;
    for (int v = 0; v < part().mesh.vertexCount(); ++v)
        if (part().weights.perVertex[v].size() == 1 &&
            part().weights.perVertex[v].front().first == bone)
            alone.push_back(v);
    ASSERT_FALSE(alone.empty());
    document()->setSelection({biped, hand});
    window->activateTool<widgets::PaintTool>();
    paintTool()->mode = BrushMode::Subtract;
    QTest::qWait(20);
    const Part before = part();
    const int steps = document()->undoStack()->count();
    // From beside the hand (off the part) across its tip.
    const Vec3 tip = part().skeleton.joint(hand).position;
    const std::vector<QPointF> stroke = strokeAlong(tip, tip.x() + 0.6, tip.x() - 0.25);
    ASSERT_FALSE(viewport()->partAt(stroke.front()).has_value()) << "the stroke starts beside it";
    drag(viewport(), stroke);
    ASSERT_EQ(document()->undoStack()->count(), steps + 1) << status().toStdString();
    EXPECT_FALSE(status().contains(QStringLiteral("locked"))) << status().toStdString();
    EXPECT_TRUE(part().validate().empty());
    int moved = 0;
    for (int v : alone) {
        const double given = weightOf(before, v, bone) - weightOf(part(), v, bone);
        if (given <= 0.0)
            continue;
        ++moved;
        EXPECT_NEAR(weightOf(part(), v, parent), given, 1e-9) << v;
    }
    EXPECT_GT(moved, 0);
}

// X-mirror is left and right: a stroke on the right forearm with X-mirror
// on paints the left forearm's bone on the left as much, and undoes exactly.
TEST_F(StudioSymmetry, XMirrorPaintsTheOtherArmsBoneOnTheOtherSide) {
    const model::PartId biped = addSymmetricExampleBiped();
    const JointId hand = handOn(1.0);
    const BoneId bone = *boneForJoint(part().skeleton, hand);
    const std::optional<PartSymmetry> symmetry = findPartSymmetry(part());
    ASSERT_TRUE(symmetry.has_value());
    const BoneId image = symmetry->imageOf(bone);
    ASSERT_NE(image, bone) << "the left hand's bone mirrors the right's";
    document()->setSelection({biped, hand});
    window->activateTool<widgets::PaintTool>();
    // Replace with a constant brush at full strength: every vertex it
    // reaches gets the weight 0.25, whatever it had.
    paintTool()->mode = BrushMode::Replace;
    paintTool()->falloff = BrushFalloff::Constant;
    paintTool()->strength = 1.0;
    paintTool()->value = 0.25;
    window->findChild<QCheckBox*>(QStringLiteral("paintMirror"))->setChecked(true);
    QTest::qWait(20);
    const Part before = part();
    const QByteArray bytes = model::DocumentFile::toBytes(*document());
    const Vec3 tip = part().skeleton.joint(hand).position;
    drag(viewport(), strokeAlong(tip, tip.x() - 0.1, tip.x() - 0.6));
    ASSERT_TRUE(part().validate().empty()) << status().toStdString();
    double right = 0.0;
    for (int v = 0; v < part().mesh.vertexCount(); ++v)
        right += weightOf(before, v, bone) - weightOf(part(), v, bone);
    EXPECT_GT(right, 1.0) << "the stroke painted the right hand";
    // Each vertex the stroke changed on the right has the hand bone's
    // weight that the vertex mirroring it on the left has of its image.
    const double edge = testsupport::meanEdgeLength(part().mesh);
    const testsupport::MirrorMismatch mismatch =
        testsupport::mirrorMismatch(before, part(), bone, image, symmetry->plane, 0.05 * edge);
    std::cout << "mirror mismatch over " << mismatch.compared << " vertices: " << mismatch.unequal
              << " unequal, largest " << mismatch.largest << std::endl;
    EXPECT_GT(mismatch.compared, 10);
    // Every pair equal to 1e-9: X-mirror copies each changed vertex's
    // change to its partner (rig/VertexMirror), so a brush's edge or the
    // front-faces test falling between the two sides' samplings (which
    // differ by up to 5% of an edge there) cannot leave one side unpainted.
    EXPECT_EQ(mismatch.unequal, 0);
    QTest::qWait(50);
    window->grab().save(QStringLiteral(RIGMESH_TEST_OUTPUT "/studio_mirror_paint.png"));
    document()->undoStack()->undo();
    EXPECT_EQ(model::DocumentFile::toBytes(*document()), bytes);
}

// Pins hold in world space at any reach: Alt + drag of the left hand runs
// the chain to the root, and the pinned right shoulder stays put.
TEST_F(StudioSymmetry, APinnedShoulderHoldsWhileAltDragMovesTheOtherHand) {
    const model::PartId biped = addExampleBiped();
    window->activateTool<widgets::PoseTool>();
    QTest::qWait(20);
    const JointId shoulder = limbTop(part().skeleton, handOn(1.0));
    const JointId other = handOn(-1.0);
    // Shift + click pins the shoulder.
    const QVector3D at = viewport()->camera().project(
        viewport()->jointWorldPosition(biped, shoulder), QSizeF(viewport()->size()));
    drag(viewport(), {QPointF(at.x(), at.y())}, Qt::ShiftModifier);
    ASSERT_TRUE(document()->part(biped).pinnedJoints.contains(shoulder));
    const QVector3D pinned = viewport()->jointWorldPosition(biped, shoulder);
    const QVector3D hand = viewport()->jointWorldPosition(biped, other);
    dragJointBy(biped, other, 60.0, -80.0, Qt::AltModifier);
    EXPECT_GT((viewport()->jointWorldPosition(biped, other) - hand).length(), 0.1f)
        << "the hand followed";
    const Vec3 now = widgets::toEigen(viewport()->jointWorldPosition(biped, shoulder));
    EXPECT_LT((now - widgets::toEigen(pinned)).norm(), 1e-6);
}

// Edit > Mirror Pose (Ctrl+Shift+V): the right arm raised becomes the left
// arm raised; every posed joint is the reflection of its image's.
TEST_F(StudioSymmetry, MirrorPoseFlipsThePoseLeftToRight) {
    const model::PartId biped = addExampleBiped();
    window->activateTool<widgets::PoseTool>();
    QTest::qWait(20);
    dragJointBy(biped, handOn(1.0), 30.0, -90.0);
    const Pose posed = document()->part(biped).pose;
    ASSERT_FALSE(posed.rotations.empty());
    const std::optional<PartSymmetry> symmetry = findPartSymmetry(part());
    ASSERT_TRUE(symmetry.has_value());
    const int steps = document()->undoStack()->count();
    document()->setSelection({biped, kNoJoint});
    QTest::keyClick(window.get(), Qt::Key_V, Qt::ControlModifier | Qt::ShiftModifier);
    ASSERT_EQ(document()->undoStack()->count(), steps + 1) << status().toStdString();
    const Skeleton& skeleton = part().skeleton;
    const PosedSkeleton before = forwardKinematics(skeleton, posed);
    const PosedSkeleton after = forwardKinematics(skeleton, document()->part(biped).pose);
    Eigen::AlignedBox3d box;
    for (const Vec3& v : part().mesh.vertices)
        box.extend(v);
    for (const Joint& joint : skeleton.joints()) {
        const auto image = symmetry->joints.find(joint.id);
        ASSERT_NE(image, symmetry->joints.end()) << "joint " << joint.id << " has an image";
        const Vec3 expected =
            symmetry->plane.reflect(before.jointPositions[skeleton.indexOfJoint(joint.id)]);
        const Vec3 got = after.jointPositions[skeleton.indexOfJoint(image->second)];
        EXPECT_LT((got - expected).norm(), 0.01 * box.diagonal().norm()) << "joint " << joint.id;
    }
    EXPECT_TRUE(status().contains(QStringLiteral("Mirrored"))) << status().toStdString();
    QTest::qWait(50);
    window->grab().save(QStringLiteral(RIGMESH_TEST_OUTPUT "/studio_mirror_pose.png"));
}

}  // namespace
}  // namespace rigmesh
