// Poses and pins in the native file: exact round trips, deterministic bytes,
// files without pose fields, and clear rejection of corrupt pose data.
#include <nlohmann/json.hpp>

#include "ModelTestSupport.h"
#include "PoseTestSupport.h"
#include "model/commands/SetJointPinnedCommand.h"
#include "model/commands/SetPoseCommand.h"

namespace rigmesh::model::test {
namespace {

using nlohmann::json;

// Two parts: one IK-posed with a pin, one with an awkward hand-made pose.
std::unique_ptr<Document> posedDocument() {
    auto document = std::make_unique<Document>();
    const PartId a = addPart(*document, sharedStroke("biped"), QStringLiteral("Y"));
    const PartId b = addPart(*document, testStrokes()[0], QStringLiteral("Body"));
    QUndoStack& stack = *document->undoStack();
    const std::vector<JointId> ends = endJoints(document->part(a).part->skeleton);
    stack.push(new SetJointPinnedCommand(*document, a, ends[2], true));
    stack.push(new SetPoseCommand(
        *document, a, dragged(document->part(a), ends[1], Vec3(0.1, 0.12, -0.07)), ends[1]));
    EXPECT_EQ(stack.count(), 4);  // the drag moved something

    rigmesh::Pose odd = document->part(b).pose;
    const JointId root = document->part(b).part->skeleton.root();
    odd.setRotation(root,
                    Eigen::Quaterniond(Eigen::AngleAxisd(1.0 / 3.0, Vec3(1, 2, 3).normalized())));
    odd.rotations.begin()->second.coeffs().x() = -0.0;
    odd.rootTranslation = Vec3(1.0 / 3.0, -2.0e-17, 7.25);
    stack.push(new SetPoseCommand(*document, b, odd));
    return document;
}

TEST(PoseFile, PoseAndPinsRoundTripExactly) {
    const auto document = posedDocument();
    const QByteArray bytes = bytesOf(*document);
    const DocumentContents loaded = DocumentFile::fromBytes(bytes);
    ASSERT_EQ(loaded.parts.size(), 2u);
    for (std::size_t i = 0; i < 2; ++i) {
        const PartNode& saved = document->parts()[i];
        EXPECT_TRUE(identicalPoses(loaded.parts[i].pose, saved.pose));
        EXPECT_EQ(loaded.parts[i].pinnedJoints, saved.pinnedJoints);
    }
    EXPECT_TRUE(std::signbit(loaded.parts[1].pose.rotations.begin()->second.x()));
    EXPECT_EQ(DocumentFile::toBytes(loaded), bytes);
    EXPECT_EQ(bytesOf(*posedDocument()), bytes);  // deterministic
}

TEST(PoseFile, FileWithoutPoseFieldsLoadsInTheRestPose) {
    json root = documentJson(bytesOf(*posedDocument()));
    for (json& part : root["parts"]) {
        part.erase("pose");
        part.erase("pinned");
    }
    const DocumentContents loaded = DocumentFile::fromBytes(documentBytes(root));
    for (const PartNode& node : loaded.parts) {
        EXPECT_TRUE(identicalPoses(node.pose, restPose(node.part->skeleton)));
        EXPECT_TRUE(node.pinnedJoints.empty());
    }
}

TEST(PoseFile, CorruptPoseDataIsRejectedWithAClearMessage) {
    const json good = documentJson(bytesOf(*posedDocument()));
    const JointId joint = good["parts"][0]["pose"]["rotations"][0][0].get<JointId>();

    json bad = good;
    bad["parts"][0]["pose"]["rotations"][0][1] = std::numeric_limits<double>::quiet_NaN();
    expectRejected(documentBytes(bad), "the pose rotation of joint " + std::to_string(joint) +
                                           " of part 1 (\"Y\") is not finite or is zero");
    bad = good;
    for (int k = 1; k <= 4; ++k)
        bad["parts"][0]["pose"]["rotations"][0][k] = 0.0;
    expectRejected(documentBytes(bad), "is not finite or is zero");
    bad = good;
    bad["parts"][0]["pose"]["rotations"][0][0] = 424242;
    expectRejected(documentBytes(bad),
                   "pose joint 424242 of part 1 (\"Y\") is not a joint of its skeleton");
    bad = good;
    bad["parts"][0]["pinned"][0] = 424242;
    expectRejected(documentBytes(bad), "pinned joint 424242 of part 1 (\"Y\") is not a joint");
    bad = good;
    bad["parts"][0]["pose"]["rotations"][0] = json::array({joint, 1.0, 0.0});
    expectRejected(documentBytes(bad), "is not [joint, w, x, y, z]");
    bad = good;
    bad["parts"][0]["pose"]["rootTranslation"][1] = std::numeric_limits<double>::infinity();
    expectRejected(documentBytes(bad), "root translation of part 1 (\"Y\") is not finite");
    bad = good;
    bad["parts"][0]["pose"].erase("rotations");
    expectRejected(documentBytes(bad), "missing \"rotations\"");
}

}  // namespace
}  // namespace rigmesh::model::test
