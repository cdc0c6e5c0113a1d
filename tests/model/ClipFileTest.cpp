// Clips in the native file: exact round trips (times, key poses, frame rate,
// modes, keys closer than half a frame after a frame rate change),
// deterministic bytes, files without clips, and rejection of corrupt clips.
#include <cmath>
#include <limits>
#include <nlohmann/json.hpp>

#include "ModelTestSupport.h"
#include "PoseTestSupport.h"
#include "model/commands/KeyPoseCommand.h"
#include "model/commands/SetClipSettingsCommand.h"
#include "model/commands/SetPoseCommand.h"

namespace rigmesh::model::test {
namespace {

using nlohmann::json;

// Part 0 with three keys at awkward times, smooth and looping; part 1 with
// keys 0.01 s apart, then a frame rate at which they are within half a frame.
std::unique_ptr<Document> animatedDocument() {
    auto document = std::make_unique<Document>();
    const PartId a = addPart(*document, sharedStroke("biped"), QStringLiteral("Y"));
    const PartId b = addPart(*document, testStrokes()[0], QStringLiteral("Body"));
    QUndoStack& stack = *document->undoStack();
    const std::vector<JointId> ends = endJoints(document->part(a).part->skeleton);
    stack.push(new KeyPoseCommand(*document, a, 0.0));
    stack.push(new SetPoseCommand(
        *document, a, dragged(document->part(a), ends[0], Vec3(0.1, 0.12, -0.07)), ends[0]));
    stack.push(new KeyPoseCommand(*document, a, 1.0 / 3.0));
    stack.push(new SetPoseCommand(
        *document, a, dragged(document->part(a), ends[1], Vec3(-0.1, 0.05, 0.02)), ends[1]));
    stack.push(new KeyPoseCommand(*document, a, 0.7 + 1e-13));
    stack.push(
        new SetClipSettingsCommand(*document, a, 29.97, Interpolation::Smooth, PlaybackMode::Loop));
    stack.push(
        new SetClipSettingsCommand(*document, b, 100.0, Interpolation::Linear, PlaybackMode::Hold));
    stack.push(new KeyPoseCommand(*document, b, 0.0));
    stack.push(new KeyPoseCommand(*document, b, 0.01));
    stack.push(
        new SetClipSettingsCommand(*document, b, 10.0, Interpolation::Linear, PlaybackMode::Hold));
    return document;
}

TEST(ClipFile, ClipsRoundTripExactly) {
    const auto document = animatedDocument();
    ASSERT_EQ(document->parts()[0].clip.keyCount(), 3);
    ASSERT_EQ(document->parts()[1].clip.keyCount(), 2);
    const QByteArray bytes = bytesOf(*document);
    const DocumentContents loaded = DocumentFile::fromBytes(bytes);
    ASSERT_EQ(loaded.parts.size(), 2u);
    for (std::size_t i = 0; i < 2; ++i)
        EXPECT_TRUE(identicalClips(loaded.parts[i].clip, document->parts()[i].clip)) << i;
    EXPECT_EQ(loaded.parts[0].clip.framesPerSecond(), 29.97);
    EXPECT_EQ(loaded.parts[0].clip.keyTimes()[2], 0.7 + 1e-13);
    EXPECT_EQ(loaded.parts[1].clip.keyTimes(), (std::vector<double>{0.0, 0.01}));
    EXPECT_EQ(DocumentFile::toBytes(loaded), bytes);
    EXPECT_EQ(bytesOf(*animatedDocument()), bytes);  // deterministic
}

TEST(ClipFile, ClipIsStoredAsTimesAndPosesWithItsSettings) {
    const json root = documentJson(bytesOf(*animatedDocument()));
    const json& clip = root["parts"][0]["clip"];
    EXPECT_EQ(clip["framesPerSecond"], 29.97);
    EXPECT_EQ(clip["interpolation"], "smooth");
    EXPECT_EQ(clip["playback"], "loop");
    ASSERT_EQ(clip["keys"].size(), 3u);
    EXPECT_EQ(clip["keys"][1]["time"], 1.0 / 3.0);
    EXPECT_TRUE(clip["keys"][1]["pose"].contains("rotations"));
    EXPECT_TRUE(clip["keys"][1]["pose"].contains("rootTranslation"));
    EXPECT_EQ(root["parts"][1]["clip"]["interpolation"], "linear");
    EXPECT_EQ(root["parts"][1]["clip"]["playback"], "hold");
}

TEST(ClipFile, FileWithoutClipsLoadsWithEmptyClips) {
    json root = documentJson(bytesOf(*animatedDocument()));
    for (json& part : root["parts"])
        part.erase("clip");
    const DocumentContents loaded = DocumentFile::fromBytes(documentBytes(root));
    for (const PartNode& node : loaded.parts)
        EXPECT_TRUE(identicalClips(node.clip, rigmesh::Clip()));
}

TEST(ClipFile, CorruptClipsAreRejectedWithAClearMessage) {
    const json good = documentJson(bytesOf(*animatedDocument()));
    json bad = good;
    bad["parts"][0]["clip"]["interpolation"] = "cubic";
    expectRejected(documentBytes(bad), "unknown clip interpolation \"cubic\"");
    bad = good;
    bad["parts"][0]["clip"]["playback"] = "bounce";
    expectRejected(documentBytes(bad), "unknown clip playback \"bounce\"");
    bad = good;
    bad["parts"][0]["clip"]["framesPerSecond"] = 0.0;
    expectRejected(documentBytes(bad), "clip frame rate of part 1 (\"Y\") is not positive");
    bad = good;
    bad["parts"][0]["clip"]["keys"][1]["time"] = std::numeric_limits<double>::infinity();
    expectRejected(documentBytes(bad), "key time of part 1 (\"Y\") is not finite");
    bad = good;
    bad["parts"][0]["clip"]["keys"][1]["time"] = 0.0;
    expectRejected(documentBytes(bad), "two keys at one time");
    bad = good;
    bad["parts"][0]["clip"]["keys"][0]["pose"]["rotations"][0][0] = 424242;
    expectRejected(documentBytes(bad), "pose joint 424242 of part 1 (\"Y\") is not a joint");
    bad = good;
    bad["parts"][0]["clip"]["keys"][0]["pose"]["rotations"][0][1] =
        std::numeric_limits<double>::quiet_NaN();
    expectRejected(documentBytes(bad), "is not finite or is zero");
    bad = good;
    bad["parts"][0]["clip"]["keys"][0].erase("pose");
    expectRejected(documentBytes(bad), "missing \"pose\"");
    bad = good;
    bad["parts"][0]["clip"].erase("keys");
    expectRejected(documentBytes(bad), "missing \"keys\"");
}

}  // namespace
}  // namespace rigmesh::model::test
