// Tools > Auto-Rig Part in the studio: a mesh imported without a
// rig is offered a rig at once; rigging runs as a background job whose bar
// fills, Cancel leaves the mesh as it was, and the rig is one undo step.
#include <QMessageBox>
#include <QPushButton>
#include <QStatusBar>
#include <QTimer>
#include <cmath>
#include <limits>
#include <optional>

#include "StudioFixture.h"
#include "jobs/BusyBar.h"
#include "jobs/JobRunner.h"
#include "jobs/JobStatus.h"
#include "model/DocumentExport.h"
#include "model/DocumentFile.h"
#include "rig/MirrorSymmetry.h"

namespace rigmesh {
namespace {

class StudioAutoRig : public test::StudioFixture {
  protected:
    // The example biped's surface as a plain OBJ, as another tool writes
    // one; `subdivisions` Loop rounds make it larger (slower to rig).
    QString bipedObj(int subdivisions) {
        model::Document source;
        const Sketch sketch = parseSketchJson(resources::exampleSketchJson(), "example.json");
        source.undoStack()->push(
            model::CreatePartCommand::create(source, sketch.points, "biped").release());
        ExportOptions options;
        options.subdivisionLevels = subdivisions;
        const QString path = recovery.filePath(QStringLiteral("biped%1.obj").arg(subdivisions));
        model::exportDocument(source, path.toStdString(), options);
        return path;
    }
    // Imports `path`, answering the offer to rig with `answer` ("Rig Now"
    // or "Not Now"); returns whether the offer came.
    bool importAnswering(const QString& path, const QString& answer) {
        bool offered = false;
        QTimer answerer;
        answerer.setInterval(10);
        QObject::connect(&answerer, &QTimer::timeout, [&] {
            for (QWidget* widget : QApplication::topLevelWidgets()) {
                auto* box = qobject_cast<QMessageBox*>(widget);
                if (!box || box->objectName() != QStringLiteral("offerToRig") || !box->isVisible())
                    continue;
                for (QAbstractButton* button : box->buttons())
                    if (button->text() == answer) {
                        offered = true;
                        button->click();
                    }
            }
        });
        answerer.start();
        window->exchange()->importPath(path);
        test::waitForJobs();  // the import, then the offer
        test::waitWhile([&] { return !offered; }, 10000);
        answerer.stop();
        return offered;
    }
    const Part& onlyPart() const { return *document()->parts().front().part; }
    // A five-pointed star, exactly symmetric about x = 0, as a plain OBJ.
    QString starObj() {
        std::vector<Vec2> corners;
        for (int k = 0; k < 10; ++k) {
            const double angle = M_PI / 2.0 + k * M_PI / 5.0;
            const double radius = k % 2 == 0 ? 1.0 : 0.45;
            corners.emplace_back(radius * std::cos(angle), radius * std::sin(angle));
        }
        std::vector<Vec2> outline;
        for (int k = 0; k < 10; ++k)
            for (int i = 0; i < 8; ++i)
                outline.push_back(corners[k] + (i / 8.0) * (corners[(k + 1) % 10] - corners[k]));
        model::Document source;
        source.undoStack()->push(
            model::CreatePartCommand::create(source, outline, "star").release());
        const QString path = recovery.filePath(QStringLiteral("star.obj"));
        model::exportDocument(source, path.toStdString(), ExportOptions{});
        return path;
    }
};

// Auto-rig finds a symmetric mesh's mirror plane and gives mirrored limbs
// mirrored bones: every joint of the star's rig has its mirror image among
// the joints, within 1% of the star's size.
TEST_F(StudioAutoRig, ASymmetricMeshGetsAMirroredRig) {
    ASSERT_TRUE(importAnswering(starObj(), QStringLiteral("Rig Now")));
    test::waitForJobs();
    ASSERT_EQ(document()->partCount(), 1);
    const Part& part = onlyPart();
    ASSERT_GE(part.skeleton.boneCount(), 5) << "a bone for each point at least";
    const std::optional<PartSymmetry> symmetry = findPartSymmetry(part);
    ASSERT_TRUE(symmetry.has_value());
    Eigen::AlignedBox3d box;
    for (const Vec3& v : part.mesh.vertices)
        box.extend(v);
    const double size = box.diagonal().norm();
    for (const Joint& joint : part.skeleton.joints()) {
        const Vec3 image = symmetry->plane.reflect(joint.position);
        double nearest = std::numeric_limits<double>::infinity();
        for (const Joint& other : part.skeleton.joints())
            nearest = std::min(nearest, (other.position - image).norm());
        EXPECT_LT(nearest, 0.01 * size) << "joint " << joint.id;
    }
    // Each point's limb has as many bones as its mirror image's.
    for (const auto& [bone, image] : symmetry->bones)
        EXPECT_EQ(part.skeleton.degree(part.skeleton.bone(bone).tail),
                  part.skeleton.degree(part.skeleton.bone(image).tail));
    EXPECT_EQ(symmetry->joints.size(), static_cast<size_t>(part.skeleton.jointCount()))
        << "every joint has its mirror image";
    viewport()->frameAll();
    QTest::qWait(50);
    window->grab().save(QStringLiteral(RIGMESH_TEST_OUTPUT "/studio_autorigged_star.png"));
}

TEST_F(StudioAutoRig, AMeshImportedWithoutARigIsRiggedByRigNowAsOneUndoStep) {
    ASSERT_TRUE(importAnswering(bipedObj(0), QStringLiteral("Rig Now")));
    test::waitForJobs();
    ASSERT_EQ(document()->partCount(), 1);
    EXPECT_GE(onlyPart().skeleton.boneCount(), 5);
    EXPECT_TRUE(onlyPart().validateSolid().empty());
    EXPECT_TRUE(window->statusBar()->currentMessage().contains(QStringLiteral("rigged with")))
        << window->statusBar()->currentMessage().toStdString();
    ASSERT_EQ(document()->undoStack()->count(), 2);  // the import and the rig
    // Posed like a sketched part: every limb's last bone turned 35 degrees.
    const model::PartId id = document()->parts().front().id;
    const Skeleton& skeleton = onlyPart().skeleton;
    Pose pose;
    for (const Bone& bone : skeleton.bones())
        if (skeleton.degree(bone.tail) == 1)
            pose.setRotation(bone.tail, Eigen::Quaterniond(Eigen::AngleAxisd(0.6, Vec3::UnitZ())));
    ASSERT_FALSE(pose.rotations.empty());
    document()->setPose(id, pose);
    viewport()->frameAll();
    QTest::qWait(50);
    window->grab().save(QStringLiteral(RIGMESH_TEST_OUTPUT "/studio_autorigged_posed.png"));
    document()->setPose(id, restPose(onlyPart().skeleton));
    document()->undoStack()->undo();
    EXPECT_EQ(onlyPart().skeleton.jointCount(), 0);
    document()->undoStack()->redo();
    EXPECT_GE(onlyPart().skeleton.boneCount(), 5);
}

TEST_F(StudioAutoRig, TheBarFillsAndCancelLeavesTheMeshUnrigged) {
    ASSERT_TRUE(importAnswering(bipedObj(2), QStringLiteral("Not Now")));
    ASSERT_EQ(onlyPart().skeleton.jointCount(), 0);
    document()->setSelection({document()->parts().front().id, kNoJoint});
    const QByteArray before = model::DocumentFile::toBytes(*document());
    auto* rig = window->findChild<QAction*>(QStringLiteral("autoRigPart"));
    ASSERT_NE(rig, nullptr);
    rig->trigger();
    ASSERT_TRUE(window->jobs()->busy());
    auto* bar = window->findChild<widgets::BusyBar*>(QStringLiteral("jobBusyBar"));
    ASSERT_NE(bar, nullptr);
    // The flow reports as it contracts: the bar fills instead of sliding.
    test::waitWhile([&] { return window->jobs()->busy() && !(bar->fraction() > 0.05); }, 60000);
    ASSERT_TRUE(window->jobs()->busy()) << "the rig finished before its bar could be seen";
    EXPECT_TRUE(bar->isVisible());
    EXPECT_GT(bar->fraction(), 0.05);
    window->grab().save(QStringLiteral(RIGMESH_TEST_OUTPUT "/studio_autorig_progress.png"));
    window->jobStatus()->cancelButton()->click();
    EXPECT_FALSE(window->jobs()->busy());
    QTest::qWait(1500);  // the worker stops at its next step; its result is dropped
    EXPECT_EQ(model::DocumentFile::toBytes(*document()), before);
    EXPECT_TRUE(window->statusBar()->currentMessage().contains(QStringLiteral("cancelled")));
}

TEST_F(StudioAutoRig, ASketchedPartIsNotRiggedAgain) {
    const model::PartId biped = addExampleBiped();
    document()->setSelection({biped, kNoJoint});
    const QByteArray before = model::DocumentFile::toBytes(*document());
    window->findChild<QAction*>(QStringLiteral("autoRigPart"))->trigger();
    EXPECT_FALSE(window->jobs()->busy());
    EXPECT_TRUE(
        window->statusBar()->currentMessage().contains(QStringLiteral("already has a skeleton")));
    EXPECT_EQ(model::DocumentFile::toBytes(*document()), before);
}

}  // namespace
}  // namespace rigmesh
