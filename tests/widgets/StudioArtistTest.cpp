// The studio as an artist expects it, driven by synthetic mouse and keys:
// a cut stroke across the biped's upper arm takes the arm off (the stroke's
// extension crossing the hip does not matter), a part dropped with its end
// over a blob's edge merges where it was dropped, a Select drag over
// another part shows it in front and says the Merge tool joins parts, the
// numpad looks along the axes, and sketching never moves the camera nor
// the grid's spacing.
#include <gtest/gtest.h>

#include <QMenu>
#include <QStatusBar>
#include <QUndoStack>
#include <QWheelEvent>

#include "StudioFixture.h"
#include "model/DocumentFile.h"
#include "model/commands/KeyPoseCommand.h"
#include "viewport/ViewMath.h"

namespace rigmesh {
namespace {

using test::drag;

class StudioArtist : public test::StudioFixture {
  protected:
    QString status() const { return window->statusBar()->currentMessage(); }
    // A closed ellipse outline in document units.
    static std::vector<Vec2> ellipse(const Vec2& centre, double rx, double ry) {
        std::vector<Vec2> points;
        for (int i = 0; i < 72; ++i) {
            const double t = 2.0 * M_PI * i / 72.0;
            points.emplace_back(centre.x() + rx * std::cos(t), centre.y() + ry * std::sin(t));
        }
        return points;
    }
    model::PartId addPart(const std::vector<Vec2>& outline, const QString& name) {
        document()->undoStack()->push(
            model::CreatePartCommand::create(*document(), outline, name).release());
        return document()->parts().back().id;
    }
    // `count` + 1 points from `from` to `to`.
    static std::vector<QPointF> line(const QPointF& from, const QPointF& to, int count = 10) {
        std::vector<QPointF> points;
        for (int i = 0; i <= count; ++i)
            points.push_back(from + (to - from) * (static_cast<double>(i) / count));
        return points;
    }
    // The joint lowest in y.
    static JointId lowestJoint(const Skeleton& skeleton) {
        JointId lower = skeleton.joints().front().id;
        for (const Joint& joint : skeleton.joints())
            if (joint.position.y() < skeleton.joint(lower).position.y())
                lower = joint.id;
        return lower;
    }
    // Drags a part with the Merge tool from `grab` to `release`: the
    // Snap / Split / Connect menu it opens (null if none).
    QMenu* mergeMenuAfterDrag(const QPointF& grab, const QPointF& release) {
        drag(viewport(), line(grab, release));
        auto* tool = dynamic_cast<widgets::MergeTool*>(viewport()->tool());
        QMenu* menu = tool ? tool->choices() : nullptr;
        return menu && menu->activeAction() ? menu : nullptr;
    }
    static double maxX(const Part& part) {
        double x = -1e300;
        for (const Vec3& v : part.mesh.vertices)
            x = std::max(x, v.x());
        return x;
    }
};

// Paper 3.1 as Blender's knife: only the loop near the drawn stroke cuts.
TEST_F(StudioArtist, AStrokeAcrossTheUpperArmTakesTheArmOffTheBody) {
    const model::PartId biped = addExampleBiped();
    // A key at 0.5 s: the body keeps its clip.
    document()->undoStack()->push(new model::KeyPoseCommand(*document(), biped, 0.5));
    ASSERT_EQ(document()->part(biped).clip.keyCount(), 1);
    document()->setSelection({biped, kNoJoint});
    window->activateTool<widgets::CutTool>();
    QTest::qWait(50);
    // A short diagonal stroke across the right upper arm, from the armpit's
    // gap to above the arm; its line goes on down into the hip.
    const QPointF from = onScreen(Vec3(0.9, 0.65, 0.0));
    const QPointF to = onScreen(Vec3(1.15, 1.55, 0.0));
    ASSERT_FALSE(viewport()->partAt(from).has_value());
    ASSERT_FALSE(viewport()->partAt(to).has_value());
    const QByteArray before = model::DocumentFile::toBytes(*document());
    const double handX = maxX(*document()->part(biped).part);
    drag(viewport(), line(from, to));
    ASSERT_EQ(document()->partCount(), 2) << status().toStdString();
    // The body stays the part: its id, name, place and the selection.
    const model::PartNode& body = document()->parts()[0];
    const model::PartNode& arm = document()->parts()[1];
    EXPECT_EQ(body.id, biped);
    EXPECT_EQ(body.name, QStringLiteral("biped"));
    EXPECT_EQ(arm.name, QStringLiteral("biped cut"));
    EXPECT_EQ(document()->selection().part, biped);
    EXPECT_EQ(body.clip.keyCount(), 1) << "the body keeps its clip";
    EXPECT_LT(maxX(*body.part), 1.2) << "the hand went with the arm";
    EXPECT_NEAR(maxX(*arm.part), handX, 1e-9);
    for (const model::PartNode& node : document()->parts())
        EXPECT_TRUE(node.part->validateSolid().empty());
    QTest::qWait(50);
    window->grab().save(QStringLiteral(RIGMESH_TEST_OUTPUT "/studio_cut_arm.png"));
    QTest::keyClick(window.get(), Qt::Key_Z, Qt::ControlModifier);
    EXPECT_EQ(model::DocumentFile::toBytes(*document()), before);
    EXPECT_TRUE(status().startsWith(QStringLiteral("Undone: Cut biped"))) << status().toStdString();
}

// Paper 3.2: the merge is chosen where the part is dropped. An upright limb
// dropped with its lower end over a wide blob's upper edge splits the blob's
// bone below that end, not at the blob's far end joint.
TEST_F(StudioArtist, ALimbDroppedOverABlobsEdgeMergesWhereItWasDropped) {
    addPart(ellipse(Vec2(0.0, 0.0), 2.0, 1.0), QStringLiteral("blob"));
    const model::PartId limb = addPart(ellipse(Vec2(0.5, 2.3), 0.22, 0.9), QStringLiteral("limb"));
    viewport()->frameAll();
    window->activateTool<widgets::MergeTool>();
    QTest::qWait(50);
    const Skeleton& skeleton = document()->part(limb).part->skeleton;
    const Vec3 end = skeleton.joint(lowestJoint(skeleton)).position;
    // Dragged down until that end is over the blob's upper edge.
    const Vec3 drop(end.x(), 0.92, 0.0);
    const QPointF grab = onScreen(Vec3(0.5, 2.3, 0.0));
    const QPointF release = grab + (onScreen(drop) - onScreen(end));
    const int steps = document()->undoStack()->count();
    QMenu* menu = mergeMenuAfterDrag(grab, release);
    ASSERT_NE(menu, nullptr) << status().toStdString();
    EXPECT_EQ(menu->activeAction()->text(), QStringLiteral("S&plit the bone here"))
        << "no joint of the blob is near the drop: its bone is split there";
    EXPECT_TRUE(status().startsWith(QStringLiteral("Split a bone of blob")))
        << status().toStdString();
    // While the menu waits, the limb shows in front of the blob (it would
    // hide inside it), with a copy where the split puts it.
    const auto inFront = viewport()->tool()->partsInFront(*viewport());
    ASSERT_EQ(inFront.size(), 1u);
    EXPECT_EQ(inFront.front().part, limb);
    EXPECT_TRUE(inFront.front().resultOffset.has_value());
    QTest::qWait(50);
    window->grab().save(QStringLiteral(RIGMESH_TEST_OUTPUT "/studio_merge_drop_menu.png"));
    QTest::keyClick(menu, Qt::Key_Return);
    test::waitForJobs();
    ASSERT_EQ(document()->partCount(), 1) << status().toStdString();
    EXPECT_EQ(document()->undoStack()->count(), steps + 1);
    const Part& merged = *document()->parts().front().part;
    EXPECT_TRUE(merged.validateSolid().empty());
    // The limb's end joint is on the blob's axis right below the drop, and
    // the limb stands above it (it did not jump to the blob's end).
    bool endBelowDrop = false, limbAbove = false;
    for (const Joint& joint : merged.skeleton.joints()) {
        endBelowDrop = endBelowDrop || ((joint.position - Vec3(drop.x(), 0.0, 0.0)).norm() < 0.1);
        limbAbove = limbAbove ||
                    (std::abs(joint.position.x() - drop.x()) < 0.1 && joint.position.y() > 1.2);
    }
    EXPECT_TRUE(endBelowDrop);
    EXPECT_TRUE(limbAbove);
    QTest::qWait(50);
    window->grab().save(QStringLiteral(RIGMESH_TEST_OUTPUT "/studio_merge_at_drop.png"));
}

// In perspective a bone's far half looks shorter, so where it is split is
// found in 3D: the point of the bone nearest the line of sight through the
// dropped joint, not the same fraction of its length as on screen.
TEST_F(StudioArtist, ASplitInPerspectiveIsWhereTheJointShowsOnTheBone) {
    const model::PartId blob = addPart(ellipse(Vec2(0.0, 0.0), 2.0, 1.0), QStringLiteral("blob"));
    const model::PartId limb = addPart(ellipse(Vec2(0.5, 2.3), 0.22, 0.9), QStringLiteral("limb"));
    viewport()->frameAll();
    viewport()->orbitBy(50.0, 15.0);  // the blob's bones now run away from the camera
    ASSERT_FALSE(viewport()->camera().orthographic());
    window->activateTool<widgets::MergeTool>();
    QTest::qWait(50);
    const QSizeF size(viewport()->size());
    auto screen = [&](const Vec3& p) {
        const QVector3D s = viewport()->camera().project(widgets::toQt(p), size);
        return QPointF(s.x(), s.y());
    };
    // The blob's longest bone on screen, and a point at a third of it.
    const Skeleton& blobSkeleton = document()->part(blob).part->skeleton;
    const Bone* longest = nullptr;
    for (const Bone& bone : blobSkeleton.bones())
        if (!longest ||
            QLineF(screen(blobSkeleton.joint(bone.head).position),
                   screen(blobSkeleton.joint(bone.tail).position))
                    .length() > QLineF(screen(blobSkeleton.joint(longest->head).position),
                                       screen(blobSkeleton.joint(longest->tail).position))
                                    .length())
            longest = &bone;
    ASSERT_NE(longest, nullptr);
    const Vec3 head = blobSkeleton.joint(longest->head).position;
    const Vec3 tail = blobSkeleton.joint(longest->tail).position;
    const Skeleton& limbSkeleton = document()->part(limb).part->skeleton;
    const JointId lower = lowestJoint(limbSkeleton);
    const QPointF grab = screen(Vec3(0.5, 2.3, 0.0));
    const QPointF release =
        grab + (screen(head + 0.35 * (tail - head)) - screen(limbSkeleton.joint(lower).position));
    QMenu* menu = mergeMenuAfterDrag(grab, release);
    ASSERT_NE(menu, nullptr) << status().toStdString();
    ASSERT_EQ(menu->activeAction()->text(), QStringLiteral("S&plit the bone here"))
        << status().toStdString();
    // Where the limb's end was dropped, and the line of sight through it.
    const Vec3 dropped = widgets::toEigen(viewport()->jointWorldPosition(limb, lower));
    const Vec3 sight = (dropped - widgets::toEigen(viewport()->camera().eye())).normalized();
    // The bone's point nearest that line, by sampling the bone finely (the
    // tool solves for it), and the point at the same fraction as on screen.
    Vec3 nearest = head;
    double nearestDistance = 1e300;
    for (int i = 0; i <= 100000; ++i) {
        const Vec3 p = head + (i / 100000.0) * (tail - head);
        const double d = (p - dropped).cross(sight).norm();
        if (d < nearestDistance) {
            nearestDistance = d;
            nearest = p;
        }
    }
    const QPointF h = screen(head), ht = screen(tail) - screen(head);
    const double onScreen =
        QPointF::dotProduct(screen(dropped) - h, ht) / QPointF::dotProduct(ht, ht);
    const Vec3 screenFraction = head + onScreen * (tail - head);
    EXPECT_GT((screenFraction - nearest).norm(), 0.05) << "the two differ in this view";
    QTest::keyClick(menu, Qt::Key_Return);
    test::waitForJobs();
    ASSERT_EQ(document()->partCount(), 1) << status().toStdString();
    const model::PartNode& merged = document()->parts().front();
    double closest = 1e300;
    for (const Joint& joint : merged.part->skeleton.joints())
        closest = std::min(closest, (merged.placement.toWorld(joint.position) - nearest).norm());
    EXPECT_LT(closest, 1e-3) << "a joint where the limb's end showed on the bone";
    QTest::qWait(50);
    window->grab().save(QStringLiteral(RIGMESH_TEST_OUTPUT "/studio_merge_perspective_split.png"));
}

// Moving a part into another with the Select tool does not join them: it
// shows in front of the other and the status bar names the Merge tool.
TEST_F(StudioArtist, ASelectDragOverAnotherPartShowsItInFrontAndTheMergeHint) {
    addPart(ellipse(Vec2(0.0, 0.0), 2.0, 1.0), QStringLiteral("blob"));
    const model::PartId limb = addPart(ellipse(Vec2(0.5, 2.3), 0.22, 0.9), QStringLiteral("limb"));
    viewport()->frameAll();
    window->activateTool<widgets::SelectTool>();
    QTest::qWait(50);
    // Grabbed on its surface between two joints (a click on a joint selects
    // the joint and drags nothing).
    const std::vector<QPointF> path =
        line(onScreen(Vec3(0.5, 2.7, 0.0)), onScreen(Vec3(0.5, 1.4, 0.0)));
    ASSERT_FALSE(viewport()->jointAt(path.front()).has_value());
    ASSERT_EQ(viewport()->partAt(path.front()), std::optional<model::PartId>(limb));
    viewport()->setFocus(Qt::MouseFocusReason);
    test::sendMouse(viewport(), QEvent::MouseButtonPress, path.front(), Qt::LeftButton,
                    Qt::LeftButton);
    for (const QPointF& p : path)
        test::sendMouse(viewport(), QEvent::MouseMove, p, Qt::NoButton, Qt::LeftButton);
    EXPECT_TRUE(status().contains(QStringLiteral("Merge tool (M)"))) << status().toStdString();
    const auto inFront = viewport()->tool()->partsInFront(*viewport());
    ASSERT_EQ(inFront.size(), 1u);
    EXPECT_EQ(inFront.front().part, limb);
    QTest::qWait(50);
    window->grab().save(QStringLiteral(RIGMESH_TEST_OUTPUT "/studio_select_overlap.png"));
    test::sendMouse(viewport(), QEvent::MouseButtonRelease, path.back(), Qt::LeftButton,
                    Qt::NoButton);
    EXPECT_EQ(document()->partCount(), 2) << "moving never merges";
    EXPECT_TRUE(viewport()->tool()->partsInFront(*viewport()).empty());
}

void expectLooking(const widgets::OrbitCamera& camera, const QVector3D& forward) {
    EXPECT_LT((camera.forward() - forward).length(), 1e-6f)
        << camera.forward().x() << " " << camera.forward().y() << " " << camera.forward().z();
}

// Blender's numpad: 1 front, 3 right, 7 top, Ctrl the opposite side, 5
// orthographic / perspective; with Num Lock off too.
TEST_F(StudioArtist, NumpadKeysLookAlongTheAxesAndFiveSwitchesTheProjection) {
    addExampleBiped();
    viewport()->setFocus(Qt::OtherFocusReason);
    const widgets::OrbitCamera& camera = viewport()->camera();
    EXPECT_FALSE(camera.orthographic());
    QTest::keyClick(viewport(), Qt::Key_7, Qt::KeypadModifier);
    expectLooking(camera, QVector3D(0, -1, 0));
    EXPECT_LT((camera.up() - QVector3D(0, 0, -1)).length(), 1e-6f) << "the back at the top";
    EXPECT_TRUE(camera.orthographic()) << "an axis view is orthographic";
    QTest::keyClick(viewport(), Qt::Key_7, Qt::KeypadModifier | Qt::ControlModifier);
    expectLooking(camera, QVector3D(0, 1, 0));
    QTest::keyClick(viewport(), Qt::Key_3, Qt::KeypadModifier);
    expectLooking(camera, QVector3D(-1, 0, 0));
    QTest::keyClick(viewport(), Qt::Key_3, Qt::KeypadModifier | Qt::ControlModifier);
    expectLooking(camera, QVector3D(1, 0, 0));
    QTest::keyClick(viewport(), Qt::Key_1, Qt::KeypadModifier | Qt::ControlModifier);
    expectLooking(camera, QVector3D(0, 0, 1));
    QTest::keyClick(viewport(), Qt::Key_1, Qt::KeypadModifier);
    expectLooking(camera, QVector3D(0, 0, -1));
    QTest::qWait(50);
    window->grab().save(QStringLiteral(RIGMESH_TEST_OUTPUT "/studio_front_orthographic.png"));
    // 5 switches the projection; the view stays.
    QTest::keyClick(viewport(), Qt::Key_5, Qt::KeypadModifier);
    EXPECT_FALSE(camera.orthographic());
    QTest::keyClick(viewport(), Qt::Key_5, Qt::KeypadModifier);
    EXPECT_TRUE(camera.orthographic());
    // Without Num Lock the numpad's 7 is Home: the top view, not Frame All.
    QTest::keyClick(viewport(), Qt::Key_Home, Qt::KeypadModifier);
    expectLooking(camera, QVector3D(0, -1, 0));
    // Orbiting out of an axis view the camera made orthographic by itself
    // brings perspective back (Blender's Auto Perspective).
    QTest::keyClick(viewport(), Qt::Key_5, Qt::KeypadModifier);  // perspective by choice
    QTest::keyClick(viewport(), Qt::Key_3, Qt::KeypadModifier);
    EXPECT_TRUE(camera.orthographic());
    const QPointF centre(viewport()->width() / 2.0, viewport()->height() / 2.0);
    test::buttonDrag(viewport(), Qt::MiddleButton, centre, centre + QPointF(40, 10));
    EXPECT_FALSE(camera.orthographic());
    // The View > Viewpoint menu does the same and shows the keys.
    QAction* front = nullptr;
    for (QAction* action : window->findChildren<QAction*>())
        if (action->text() == QStringLiteral("&Front"))
            front = action;
    ASSERT_NE(front, nullptr);
    EXPECT_EQ(front->shortcut(), QKeySequence(QKeyCombination(Qt::KeypadModifier, Qt::Key_1)));
    front->trigger();
    expectLooking(camera, QVector3D(0, 0, -1));
}

// No automatic re-framing: the first sketch stays where it was drawn, as
// does the camera; the grid keeps its spacing as parts come; Home frames.
TEST_F(StudioArtist, SketchingNeverMovesTheCameraAndTheGridKeepsItsSpacing) {
    const widgets::OrbitCamera& camera = viewport()->camera();
    const QVector3D target = camera.target();
    const double distance = camera.distance();
    const double spacing = viewport()->gridSpacing();
    QTest::qWait(50);  // shown: the empty scene's floor is placed
    const double floor = viewport()->floorHeight();
    window->activateTool<widgets::SketchTool>();
    const QPointF centre(viewport()->width() / 2.0, viewport()->height() / 2.0);
    drag(viewport(), test::ellipseStroke(centre + QPointF(-150, 0), 90, 60));
    ASSERT_EQ(document()->partCount(), 1) << status().toStdString();
    QTest::qWait(50);  // a paint: where the first sketch used to re-frame
    EXPECT_EQ(camera.target(), target);
    EXPECT_EQ(camera.distance(), distance);
    EXPECT_EQ(viewport()->gridSpacing(), spacing);
    // A tall part whose lower end reaches below the floor on screen.
    const QVector3D floorOnScreen = camera.project(
        QVector3D(camera.target().x(), float(floor), 0.0f), QSizeF(viewport()->size()));
    const double bottom = std::min<double>(floorOnScreen.y() + 40.0, viewport()->height() - 10.0);
    drag(viewport(),
         test::ellipseStroke(QPointF(centre.x() + 200, 0.5 * (bottom + centre.y() - 100)), 30,
                             0.5 * (bottom - centre.y() + 100)));
    ASSERT_EQ(document()->partCount(), 2) << status().toStdString();
    QTest::qWait(50);
    EXPECT_EQ(camera.target(), target);
    EXPECT_EQ(viewport()->gridSpacing(), spacing);
    // The second part reaches below the floor: the floor stays where it was.
    const Eigen::AlignedBox3d second = model::worldBounds(document()->parts()[1]);
    EXPECT_LT(second.min().y(), floor);
    EXPECT_EQ(viewport()->floorHeight(), floor);
    viewport()->setFocus(Qt::OtherFocusReason);
    QTest::keyClick(viewport(), Qt::Key_Home);
    EXPECT_NE(camera.distance(), distance) << "Home frames the parts";
    // Home puts the floor under the parts, and it stays as the view zooms.
    const double framedFloor = viewport()->floorHeight();
    EXPECT_LE(framedFloor, second.min().y() + 1e-9);
    QWheelEvent wheel(QPointF(100, 100), viewport()->mapToGlobal(QPointF(100, 100)), QPoint(),
                      QPoint(0, 120), Qt::NoButton, Qt::NoModifier, Qt::NoScrollPhase, false);
    QCoreApplication::sendEvent(viewport(), &wheel);
    EXPECT_NE(camera.distance(), distance);
    EXPECT_EQ(viewport()->floorHeight(), framedFloor);
}

}  // namespace
}  // namespace rigmesh
