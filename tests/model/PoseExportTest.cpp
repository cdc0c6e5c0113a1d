// File > Export with "Current pose": every format carries the pose. The
// rigged formats make it the file's rest shape (skinned vertices, joints at
// their posed places), so the file opens posed; read back, it matches our
// own skinning.
#include <gtest/gtest.h>

#include <QTemporaryDir>

#include "ModelTestSupport.h"
#include "PoseTestSupport.h"
#include "model/DocumentExport.h"
#include "model/ImportReader.h"
#include "model/commands/SetPoseCommand.h"
#include "pose/ForwardKinematics.h"
#include "pose/Skinning.h"

namespace rigmesh::model {
namespace {

using test::addPart;
using test::dragged;
using test::endJoints;
using test::sharedStroke;

// Largest distance from a point of `expected` to the nearest of `actual`.
double largestGap(const std::vector<Vec3>& expected, const std::vector<Vec3>& actual) {
    double largest = 0.0;
    for (const Vec3& p : expected) {
        double nearest = std::numeric_limits<double>::infinity();
        for (const Vec3& q : actual)
            nearest = std::min(nearest, (p - q).squaredNorm());
        largest = std::max(largest, std::sqrt(nearest));
    }
    return largest;
}

// A y_branch part with one end dragged well away: its rest and posed meshes.
class PoseExport : public testing::TestWithParam<const char*> {
  protected:
    void SetUp() override {
        ASSERT_TRUE(folder.isValid());
        id = addPart(document, sharedStroke("y_branch"));
        const PartNode& node = document.part(id);
        const JointId end = endJoints(node.part->skeleton).front();
        Eigen::AlignedBox3d restBox;
        for (const Vec3& p : node.part->mesh.vertices)
            restBox.extend(p);
        const Vec3 offset = Vec3(0.1, 0.15, 0.08) * restBox.diagonal().norm();
        document.undoStack()->push(
            new SetPoseCommand(document, id, dragged(node, end, offset), end));
        ASSERT_FALSE(node.pose.rotations.empty());
        posed = posePart(*node.part, node.pose).mesh.vertices;
        rest = node.part->mesh.vertices;
        Eigen::AlignedBox3d box;
        for (const Vec3& p : posed)
            box.extend(p);
        size = box.diagonal().norm();
        ASSERT_GT(largestGap(posed, rest), 0.05 * size) << "the pose must move the mesh";
    }
    QTemporaryDir folder;
    Document document;
    PartId id = kNoPart;
    std::vector<Vec3> posed, rest;
    double size = 0;
};

TEST_P(PoseExport, CurrentPoseBecomesTheRestShapeAndMatchesOurSkinning) {
    const PartNode& node = document.part(id);
    const PosedSkeleton joints = forwardKinematics(node.part->skeleton, node.pose);

    const QString path = folder.filePath(QStringLiteral("posed.") + QLatin1String(GetParam()));
    ExportOptions options;
    options.restPose = false;
    exportDocument(document, path.toStdString(), options);
    const std::vector<PartNode> imported = readImportedParts(path);
    ASSERT_EQ(imported.size(), 1u);
    const Part& back = *imported.front().part;
    // The file's rest mesh is the posed mesh (float32 in the files).
    EXPECT_LT(largestGap(posed, back.mesh.vertices), 1e-5 * size);
    EXPECT_LT(largestGap(back.mesh.vertices, posed), 1e-5 * size);
    // Its skeleton stands in the pose.
    std::vector<Vec3> backJoints;
    for (const Joint& joint : back.skeleton.joints())
        backJoints.push_back(joint.position);
    EXPECT_LT(largestGap(joints.jointPositions, backJoints), 1e-5 * size);
}

TEST_P(PoseExport, CurrentPoseAsOneKeyKeepsTheRestShapeAndSkinsToThePose) {
    const QString path = folder.filePath(QStringLiteral("key.") + QLatin1String(GetParam()));
    ExportOptions options;
    options.restPose = false;
    options.poseAsKey = true;
    options.animation = false;  // the key is written anyway: it is the pose
    exportDocument(document, path.toStdString(), options);
    const std::vector<PartNode> imported = readImportedParts(path);
    ASSERT_EQ(imported.size(), 1u);
    const PartNode& back = imported.front();
    // The rest shape stays; the one key skins it to the pose.
    EXPECT_LT(largestGap(rest, back.part->mesh.vertices), 1e-5 * size);
    ASSERT_EQ(back.clip.keyCount(), 1);
    const std::vector<Vec3> keyed = posePart(*back.part, back.clip.evaluate(0.0)).mesh.vertices;
    EXPECT_LT(largestGap(posed, keyed), 1e-4 * size);
}

INSTANTIATE_TEST_SUITE_P(RiggedFormats, PoseExport, testing::Values("glb", "fbx", "dae"));

}  // namespace
}  // namespace rigmesh::model
