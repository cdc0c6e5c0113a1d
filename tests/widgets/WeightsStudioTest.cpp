// The studio's weight inspection and editing: the Weights panel
// lists bones and locks them (a locked bone is not painted), a click pins a
// vertex's weights, Check Rig lists and selects what it finds, and a
// rebuild asks before it discards painted weights.
#include <QAction>
#include <QCheckBox>
#include <QComboBox>
#include <QDockWidget>
#include <QLabel>
#include <QPushButton>
#include <QSpinBox>
#include <QStatusBar>
#include <QTabWidget>
#include <QTableWidget>
#include <QTreeWidget>
#include <iostream>
#include <optional>

#include "MirrorPaintSymmetry.h"
#include "PartWeightOf.h"
#include "StudioPoseFixture.h"
#include "jobs/JobRunner.h"
#include "model/BoneDisplayName.h"
#include "model/DocumentFile.h"
#include "model/recipe/RecipeRunner.h"
#include "panels/PropertiesPanel.h"
#include "panels/WeightsPanel.h"

namespace rigmesh {
namespace {

using test::drag;

class WeightsStudio : public test::StudioPose {
  protected:
    // The example biped with one paint stroke along its arm.
    void paintTheArmOfTheExample() {
        const model::PartId biped = addExampleBiped();
        document()->setSelection({biped, shoulder()});
        window->activateTool<widgets::PaintTool>();
        QTest::qWait(20);
        drag(viewport(), armStroke());
    }
    // The leaf joint farthest sideways (a hand) and the bone ending there.
    JointId hand() const { return sidewaysHand(part().skeleton); }
    // The joint the hand's bone starts at: the bone ending there (the upper
    // arm) is painted onto the forearm, where it has room to grow.
    JointId shoulder() const {
        for (const Bone& bone : part().skeleton.bones())
            if (bone.tail == hand())
                return bone.head;
        return kNoJoint;
    }
    const Part& part() const { return *document()->parts().front().part; }
    // A stroke from the hand inwards along the arm, in front of the sketch plane.
    std::vector<QPointF> armStroke(int points = 13, double spacing = 5.0) const {
        const Vec3 h = part().skeleton.joint(hand()).position;
        const QPointF p = onScreen(Vec3(h.x(), h.y(), 0.2));
        const double inward = h.x() < 0.0 ? 1.0 : -1.0;
        std::vector<QPointF> stroke;
        for (int i = 0; i < points; ++i)
            stroke.emplace_back(p.x() + inward * spacing * i, p.y());
        return stroke;
    }
    widgets::WeightsPanel* panel() const { return window->weightsPanel(); }
    QString status() const { return window->statusBar()->currentMessage(); }
};

TEST_F(WeightsStudio, LockingABoneInTheWeightsPanelStopsItsPaintUntilUnlocked) {
    const model::PartId biped = addExampleBiped();
    document()->setSelection({biped, shoulder()});
    QTest::qWait(20);
    QTableWidget* bones = panel()->bonesTable();
    ASSERT_EQ(bones->rowCount(), part().skeleton.boneCount());
    const BoneId bone = *boneForJoint(part().skeleton, shoulder());
    int row = -1;
    for (int r = 0; r < bones->rowCount(); ++r)
        if (bones->item(r, 0)->data(Qt::UserRole).toUInt() == bone)
            row = r;
    ASSERT_GE(row, 0);
    EXPECT_TRUE(bones->item(row, 0)->isSelected()) << "the selected joint's bone is current";
    // Tick its lock box: one undo step.
    const int steps = document()->undoStack()->count();
    bones->item(row, 2)->setCheckState(Qt::Checked);
    EXPECT_EQ(document()->undoStack()->count(), steps + 1);
    EXPECT_TRUE(part().lockedBones.contains(bone));
    // Painting it now changes nothing and says why.
    const QByteArray before = model::DocumentFile::toBytes(*document());
    window->activateTool<widgets::PaintTool>();
    QTest::qWait(20);
    drag(viewport(), armStroke());
    EXPECT_EQ(model::DocumentFile::toBytes(*document()), before);
    EXPECT_TRUE(status().contains(QStringLiteral("locked"))) << status().toStdString();
    // Undo unlocks it (the box follows); the stroke then paints.
    document()->undoStack()->undo();
    QTest::qWait(20);
    EXPECT_FALSE(part().lockedBones.contains(bone));
    EXPECT_EQ(panel()->bonesTable()->item(row, 2)->checkState(), Qt::Unchecked);
    drag(viewport(), armStroke());
    EXPECT_EQ(document()->undoStack()->count(), steps + 1) << status().toStdString();
    EXPECT_TRUE(part().weightsPainted);
    // Clicking another bone's row selects its joint (the painted bone).
    const int other = row == 0 ? 1 : 0;
    panel()->bonesTable()->cellClicked(other, 0);
    EXPECT_EQ(document()->selection().joint,
              part()
                  .skeleton.bone(panel()->bonesTable()->item(other, 0)->data(Qt::UserRole).toUInt())
                  .tail);
    // For the docs: a vertex pinned (the paint tool's Ctrl + click), the panel shown.
    drag(viewport(), {armStroke()[4]}, Qt::ControlModifier);
    for (auto* dock : window->findChildren<QDockWidget*>())
        if (dock->objectName() == QStringLiteral("weightsDock"))
            dock->raise();
    QTest::qWait(50);
    window->grab().save(QStringLiteral(RIGMESH_TEST_OUTPUT "/studio_weights_panel.png"));
}

// The notes the heat solver left with the weights (a bone that fell back to
// nearest-bone weights) are shown above the bone list, and go with them.
TEST_F(WeightsStudio, WeightsPanelShowsTheNotesTheWeightsCarry) {
    const model::PartId biped = addExampleBiped();
    document()->setSelection({biped, shoulder()});
    QTest::qWait(20);
    auto* notes = panel()->findChild<QLabel*>(QStringLiteral("weightNotes"));
    ASSERT_NE(notes, nullptr);
    EXPECT_TRUE(notes->isHidden()) << notes->text().toStdString();
    auto noted = std::make_shared<Part>(part());
    const Message fellBack{MessageId::WeightsBoneUnsolved, {"2"}};
    noted->weights.warnings = {fellBack};
    document()->replaceSkinning(biped, noted);
    QTest::qWait(20);
    EXPECT_FALSE(notes->isHidden());
    EXPECT_EQ(notes->text().toStdString(), englishText(fellBack));
    for (auto* dock : window->findChildren<QDockWidget*>())
        if (dock->objectName() == QStringLiteral("weightsDock"))
            dock->raise();
    QTest::qWait(50);
    window->grab().save(QStringLiteral(RIGMESH_TEST_OUTPUT "/studio_weight_notes.png"));
    // Saved as an id and its arguments, and read back the same.
    const QByteArray bytes = model::DocumentFile::toBytes(*document());
    EXPECT_TRUE(bytes.contains("boneUnsolved")) << "documents keep ids, not English";
    EXPECT_FALSE(bytes.contains("could not be solved"));
    const model::DocumentContents read = model::DocumentFile::fromBytes(bytes);
    EXPECT_EQ(read.parts.front().part->weights.warnings, std::vector<Message>{fellBack});
    // A bone the weights list as fallen back is named as the bone list names it.
    auto failed = std::make_shared<Part>(part());
    const BoneId second = part().skeleton.bones()[1].id;
    failed->weights.failedBones = {second};
    document()->replaceSkinning(biped, failed);
    QTest::qWait(20);
    EXPECT_TRUE(notes->text().contains(model::boneDisplayName(part(), second)))
        << notes->text().toStdString();
    document()->undoStack()->clear();
    auto clean = std::make_shared<Part>(part());
    clean->weights.warnings.clear();
    clean->weights.failedBones.clear();
    document()->replaceSkinning(biped, clean);
    QTest::qWait(20);
    EXPECT_TRUE(notes->isHidden());
}

// A stroke with X-mirror on paints the other arm too (the head's bone,
// across the middle, is its own mirror image), leaves a locked bone's
// weights bit for bit (the other bones take up the change) and undoes
// exactly.
TEST_F(WeightsStudio, MirroredStrokePaintsBothArmsAndLeavesLockedBonesAlone) {
    const model::PartId biped = addSymmetricExampleBiped();
    const Part rest = part();
    // Lock the upper arm's bone and paint the head's bone (the topmost
    // joint's) onto the arm: the forearm's bone gives way, the locked one
    // stays where the stroke meets it.
    const BoneId locked = *boneForJoint(rest.skeleton, shoulder());
    JointId top = rest.skeleton.root();
    for (const Joint& joint : rest.skeleton.joints())
        if (joint.position.y() > rest.skeleton.joint(top).position.y())
            top = joint.id;
    const BoneId painted = *boneForJoint(rest.skeleton, top);
    document()->setSelection({biped, top});
    QTest::qWait(20);
    QTableWidget* bones = panel()->bonesTable();
    for (int r = 0; r < bones->rowCount(); ++r)
        if (bones->item(r, 0)->data(Qt::UserRole).toUInt() == locked)
            bones->item(r, 2)->setCheckState(Qt::Checked);
    ASSERT_TRUE(part().lockedBones.contains(locked));
    window->activateTool<widgets::PaintTool>();
    // Replace with a constant brush at full strength: the painted bone gets
    // 0.6 wherever the brush reaches and a lock leaves room.
    auto* paint = window->tools()->find<widgets::PaintTool>();
    paint->mode = BrushMode::Replace;
    paint->falloff = BrushFalloff::Constant;
    paint->strength = 1.0;
    paint->value = 0.6;
    window->findChild<QCheckBox*>(QStringLiteral("paintMirror"))->setChecked(true);
    QTest::qWait(20);
    const QByteArray before = model::DocumentFile::toBytes(*document());
    const int steps = document()->undoStack()->count();
    drag(viewport(), armStroke(30, 6.0));  // from the hand to the upper arm
    ASSERT_EQ(document()->undoStack()->count(), steps + 1) << status().toStdString();
    const Part& after = part();
    EXPECT_TRUE(after.validate().empty());
    EXPECT_NE(after.weights.perVertex, rest.weights.perVertex);
    int lockedInStroke = 0;  // painted vertices where the locked bone has weight
    double gainedLeft = 0.0, gainedRight = 0.0;  // the painted bone's weight
    for (int v = 0; v < after.mesh.vertexCount(); ++v) {
        if (after.weights.perVertex[v] != rest.weights.perVertex[v] &&
            testsupport::weightOf(rest, v, locked) > 0.0)
            ++lockedInStroke;
        (after.mesh.vertices[v].x() > 0.0 ? gainedRight : gainedLeft) +=
            testsupport::weightOf(after, v, painted) - testsupport::weightOf(rest, v, painted);
        ASSERT_EQ(testsupport::weightOf(after, v, locked), testsupport::weightOf(rest, v, locked))
            << v;
    }
    EXPECT_GT(lockedInStroke, 0) << "the stroke reached the locked bone's vertices";
    EXPECT_GT(std::min(gainedLeft, gainedRight), 1.0) << "both arms painted";
    // Left and right alike, vertex by vertex, wherever the lock does not
    // hold the weight on one side only (the locked bone's image is not
    // locked).
    const std::optional<PartSymmetry> symmetry = findPartSymmetry(after);
    ASSERT_TRUE(symmetry.has_value());
    const BoneId lockedImage = symmetry->imageOf(locked);
    const double edge = testsupport::meanEdgeLength(after.mesh);
    const testsupport::MirrorMismatch mismatch = testsupport::mirrorMismatch(
        rest, after, painted, symmetry->imageOf(painted), symmetry->plane, 0.05 * edge,
        [&](int v, int pair) {
            return testsupport::weightOf(rest, v, locked) == 0.0 &&
                   testsupport::weightOf(rest, v, lockedImage) == 0.0 &&
                   testsupport::weightOf(rest, pair, locked) == 0.0 &&
                   testsupport::weightOf(rest, pair, lockedImage) == 0.0;
        });
    std::cout << "mirror mismatch over " << mismatch.compared << " vertices: " << mismatch.unequal
              << " unequal, largest " << mismatch.largest << std::endl;
    EXPECT_GT(mismatch.compared, 10);
    // Every pair equal to 1e-9: X-mirror copies each changed vertex's
    // change to its partner (rig/VertexMirror), so a brush's edge or the
    // front-faces test falling between the two sides' samplings (which
    // differ by up to 5% of an edge there) cannot leave one side unpainted.
    EXPECT_EQ(mismatch.unequal, 0);
    document()->undoStack()->undo();
    EXPECT_EQ(model::DocumentFile::toBytes(*document()), before);
}

TEST_F(WeightsStudio, ClickingAVertexWithAWeightViewOnPinsItsWeightsInThePanel) {
    const model::PartId biped = addExampleBiped();
    window->activateTool<widgets::SelectTool>();
    viewport()->setWeightView(widgets::WeightView::DominantBone);
    QTest::qWait(20);
    // The middle of the forearm, in front: far from any joint marker.
    const Skeleton& skeleton = part().skeleton;
    const Vec3 forearm =
        0.5 * (skeleton.joint(hand()).position + skeleton.joint(shoulder()).position);
    const QPointF at = onScreen(Vec3(forearm.x(), forearm.y(), 0.2));
    ASSERT_FALSE(viewport()->jointAt(at).has_value());
    const auto hit = viewport()->surfaceAt(at);
    ASSERT_TRUE(hit.has_value());
    drag(viewport(), {at});
    ASSERT_TRUE(viewport()->inspectedVertex().has_value());
    EXPECT_EQ(viewport()->inspectedVertex()->part, biped);
    EXPECT_EQ(viewport()->inspectedVertex()->vertex, hit->vertex);
    QTableWidget* table = panel()->vertexTable();
    const auto& weights = part().weights.perVertex[hit->vertex];
    ASSERT_EQ(table->rowCount(), static_cast<int>(weights.size()));
    double sum = 0.0;
    double previous = 2.0;
    for (int r = 0; r < table->rowCount(); ++r) {
        const double w = table->item(r, 1)->text().toDouble();
        EXPECT_LE(w, previous) << "largest first";
        previous = w;
        sum += w;
    }
    EXPECT_NEAR(sum, 1.0, 1e-3);
    // The paint tool's Ctrl + click samples: pinned, and the Replace weight is
    // the selected bone's weight there.
    document()->setSelection({biped, hand()});
    window->activateTool<widgets::PaintTool>();
    QTest::qWait(20);
    const QPointF other = armStroke()[0];
    drag(viewport(), {other}, Qt::ControlModifier);
    const auto sampled = viewport()->surfaceAt(other);
    ASSERT_TRUE(sampled.has_value());
    EXPECT_EQ(viewport()->inspectedVertex()->vertex, sampled->vertex);
    EXPECT_TRUE(status().startsWith(QStringLiteral("Sampled"))) << status().toStdString();
}

TEST_F(WeightsStudio, CheckRigListsABoneLeadingNoVertexAndSelectsIt) {
    const model::PartId biped = addExampleBiped();
    const BoneId bone = *boneForJoint(part().skeleton, shoulder());
    // Paint one bone to 1 everywhere (a constant brush as big as the part,
    // through it): every other bone leads no vertex any more.
    const Vec3 centre = part().skeleton.joint(hand()).position;
    model::RecipeRunner(*document())
        .apply({{"command", "paint_weights"},
                {"part", 0},
                {"bone", bone},
                {"mode", "add"},
                {"strength", 1.0},
                {"falloff", "constant"},
                {"center", {centre.x(), centre.y(), centre.z()}},
                {"radius", 100.0}},
               1);
    document()->setSelection({biped, kNoJoint});
    QAction* check = nullptr;
    for (QAction* action : window->findChildren<QAction*>())
        if (action->text() == QStringLiteral("Check &Rig"))
            check = action;
    ASSERT_NE(check, nullptr);
    check->trigger();
    QTreeWidget* results = panel()->checkResults();
    ASSERT_EQ(results->topLevelItemCount(), 4);
    QTreeWidgetItem* bones = results->topLevelItem(1);
    const int others = part().skeleton.boneCount() - 1;
    EXPECT_TRUE(bones->text(0).endsWith(QStringLiteral(": %1").arg(others)))
        << bones->text(0).toStdString();
    ASSERT_EQ(bones->childCount(), others);
    const BoneId listed = bones->child(0)->data(0, Qt::UserRole).toUInt();
    EXPECT_NE(listed, bone);
    results->itemClicked(bones->child(0), 0);
    EXPECT_EQ(document()->selection().joint, part().skeleton.bone(listed).tail);
    // Vertices over one influence (before the paint): all marked when the
    // group is clicked.
    document()->undoStack()->undo();
    panel()->findChild<QSpinBox*>()->setValue(1);
    panel()->checkRig();
    QTreeWidgetItem* over = panel()->checkResults()->topLevelItem(2);
    ASSERT_GT(over->childCount(), 0);
    panel()->checkResults()->itemClicked(over, 0);
    EXPECT_EQ(viewport()->markedPart(), biped);
    EXPECT_GT(viewport()->markedVertices().size(), 10u);
    for (int v : viewport()->markedVertices())
        EXPECT_GT(part().weights.perVertex[v].size(), 1u);
    QTest::qWait(20);
    window->grab().save(QStringLiteral(RIGMESH_TEST_OUTPUT "/studio_check_rig.png"));
}

TEST_F(WeightsStudio, RebuildAsksBeforeDiscardingPaintedWeights) {
    paintTheArmOfTheExample();
    ASSERT_TRUE(part().weightsPainted) << status().toStdString();
    const int steps = document()->undoStack()->count();
    widgets::PropertiesPanel* properties = window->propertiesPanel();
    QString asked;
    properties->confirmDiscard = [&](const QString& question) {
        asked = question;
        return false;
    };
    QPushButton* rebuild = nullptr;
    for (QPushButton* button : properties->findChildren<QPushButton*>())
        if (button->text() == QStringLiteral("Rebuild"))
            rebuild = button;
    ASSERT_NE(rebuild, nullptr);
    rebuild->click();
    test::waitForJobs();
    EXPECT_TRUE(asked.contains(QStringLiteral("painted"))) << asked.toStdString();
    EXPECT_EQ(document()->undoStack()->count(), steps) << "cancelled: nothing happens";
    EXPECT_TRUE(part().weightsPainted);
    properties->confirmDiscard = [](const QString&) { return true; };
    rebuild->click();
    test::waitForJobs();
    EXPECT_EQ(document()->undoStack()->count(), steps + 1);
    EXPECT_FALSE(part().weightsPainted) << "fresh weights from the sketch";
    document()->undoStack()->undo();
    EXPECT_TRUE(part().weightsPainted) << "undo brings the painting back";
}

// Tools > Weights > Recompute Weights: asks before replacing painted
// weights (no: nothing happens), then runs bone heat over the whole part as
// a background job, one undo step; undo brings the painting back.
TEST_F(WeightsStudio, RecomputeWeightsAsksThenRunsInTheBackgroundAsOneStep) {
    paintTheArmOfTheExample();
    ASSERT_TRUE(part().weightsPainted) << status().toStdString();
    const int steps = document()->undoStack()->count();
    auto* recompute = window->findChild<QAction*>(QStringLiteral("recomputeWeights"));
    ASSERT_NE(recompute, nullptr);
    QString asked;
    window->weightsController()->confirmDiscard = [&](const QString& question) {
        asked = question;
        return false;
    };
    recompute->trigger();
    EXPECT_TRUE(asked.contains(QStringLiteral("painted"))) << asked.toStdString();
    EXPECT_FALSE(window->jobs()->busy());
    EXPECT_EQ(document()->undoStack()->count(), steps) << "declined: nothing happens";
    window->weightsController()->confirmDiscard = [](const QString&) { return true; };
    recompute->trigger();
    EXPECT_TRUE(window->jobs()->busy()) << "bone heat runs in the background";
    EXPECT_EQ(document()->undoStack()->count(), steps) << "nothing changes before it is done";
    test::waitForJobs();
    EXPECT_EQ(document()->undoStack()->count(), steps + 1) << status().toStdString();
    EXPECT_FALSE(part().weightsPainted) << "automatic weights again";
    EXPECT_TRUE(part().validate().empty());
    EXPECT_TRUE(status().contains(QStringLiteral("Recompute Weights of")))
        << status().toStdString();
    document()->undoStack()->undo();
    EXPECT_TRUE(part().weightsPainted) << "undo brings the painting back";
}

// The weight view is chosen per document, from the View
// menu or the toolbar's list, which follow the current document.
TEST_F(WeightsStudio, EachDocumentKeepsItsOwnWeightView) {
    auto* box = window->findChild<QComboBox*>(QStringLiteral("weightViewBox"));
    ASSERT_NE(box, nullptr);
    widgets::Viewport* first = viewport();
    box->setCurrentIndex(box->findData(static_cast<int>(widgets::WeightView::DominantBone)));
    box->activated(box->currentIndex());
    EXPECT_EQ(first->weightView(), widgets::WeightView::DominantBone);
    window->newDocument();
    QTest::qWait(20);
    EXPECT_NE(viewport(), first);
    EXPECT_EQ(viewport()->weightView(), widgets::WeightView::Off) << "a new document starts plain";
    EXPECT_EQ(box->currentData().toInt(), static_cast<int>(widgets::WeightView::Off));
    window->tabs()->setCurrentIndex(0);
    QTest::qWait(20);
    EXPECT_EQ(box->currentData().toInt(), static_cast<int>(widgets::WeightView::DominantBone));
    // The paint tool turns the bone view on, and the list follows.
    window->activateTool<widgets::PaintTool>();
    EXPECT_EQ(box->currentData().toInt(), static_cast<int>(widgets::WeightView::SelectedBone));
}

}  // namespace
}  // namespace rigmesh
