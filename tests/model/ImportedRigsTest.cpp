// Rigs made elsewhere in the document: a Half-Life model and a
// DirectX character from Debian's assimp-testmodels come in rigged, with
// disconnected bones and every animation a named clip; they pose, key, save
// and load exactly; a cut refuses them naming the bone, Connect Bone
// connects it in one undo step, and the history replays.
#include "ModelTestSupport.h"
#include "RecipeTestSupport.h"
#include "model/PartClips.h"
#include "model/recipe/RecipeFromHistory.h"
#include "part/BoneConnection.h"

namespace rigmesh::model::test {
namespace {

const std::string kMan = "/usr/share/assimp/models/MDL/MDL (HL1)/man.mdl";
const std::string kWuson = "/usr/share/assimp/models/X/Testwuson.X";

TEST(ImportedRigs, EveryAnimationIsANamedClipAndTheDocumentKeepsThemExactly) {
    Document document;
    runSteps(document, {{{"command", "import"}, {"file", kWuson}}});
    ASSERT_EQ(document.partCount(), 1);
    const PartNode& node = document.parts().front();
    ASSERT_GT(node.part->skeleton.boneCount(), 30);
    std::vector<std::string> names;
    for (const Clip* clip : clipsOf(node))
        names.push_back(clipName(*clip));
    EXPECT_EQ(names, (std::vector<std::string>{"Wuson_Bind", "Wuson_Run", "Wuson_Walk"}));
    EXPECT_EQ(clipName(node.clip), "Wuson_Run");  // the file's first
    const QByteArray saved = bytesOf(document);
    EXPECT_EQ(DocumentFile::toBytes(DocumentFile::fromBytes(saved)), saved);
}

// Wuson_Walk's last key is at 3.6 s, past the default timeline's 2 s: the
// import extends the timeline to the frame that shows it, in its own undo
// step; a file whose keys fit leaves the timeline as it was.
TEST(ImportedRigs, ATimelineShorterThanTheFilesAnimationsIsExtendedToTheirLastKey) {
    Document document;
    const TimelineSettings before = document.timeline();
    ASSERT_EQ(before.endFrame, 48);
    runSteps(document, {{{"command", "import"}, {"file", kWuson}}});
    ASSERT_EQ(document.partCount(), 1);
    double last = 0.0;
    for (const Clip* clip : clipsOf(document.parts().front()))
        last = std::max(last, clip->keyTimes().back());
    EXPECT_NEAR(last, 3.6, 1e-9);
    EXPECT_EQ(document.timeline().endFrame, 87);  // 3.6 s at 24 fps is frame 86.4
    EXPECT_EQ(document.timeline().startFrame, before.startFrame);
    EXPECT_EQ(document.timeline().framesPerSecond, before.framesPerSecond);
    document.undoStack()->undo();
    EXPECT_EQ(document.partCount(), 0);
    EXPECT_EQ(document.timeline(), before);
    document.undoStack()->redo();
    EXPECT_EQ(document.timeline().endFrame, 87);

    // Keys within the range: nothing to extend (man.mdl's clips end by 1 s).
    Document fits;
    runSteps(fits, {{{"command", "import"}, {"file", kMan}}});
    EXPECT_EQ(fits.timeline(), before);
}

TEST(ImportedRigs, ADisconnectedRigPosesKeysAndLoadsExactly) {
    Document document;
    runSteps(document, {{{"command", "import"}, {"file", kMan}}});
    ASSERT_EQ(document.partCount(), 1);
    const Part& part = *document.parts().front().part;
    ASSERT_FALSE(part.skeleton.isConnectedTree());
    EXPECT_EQ(clipsOf(document.parts().front()).size(), 6u);
    // Drag the right arm's end (its bone hangs from the spine, disconnected)
    // with whole-body reach, and key it.
    JointId hand = kNoJoint;
    for (const Bone& bone : part.skeleton.bones())
        if (part.boneNames.at(bone.id) == "RightArm")
            hand = bone.tail;
    ASSERT_NE(hand, kNoJoint);
    const Vec3 at = part.skeleton.joint(hand).position;
    runSteps(document, {{{"command", "pose"},
                         {"part", 0},
                         {"joint", hand},
                         {"target", {at.x() + 2.0, at.y() + 3.0, at.z() + 1.0}},
                         {"reach", "body"}},
                        {{"command", "key"}, {"part", 0}, {"time", 2.0}}});
    const PartNode& posed = document.parts().front();
    EXPECT_FALSE(posed.pose.rotations.empty());
    EXPECT_EQ(posed.clip.keyTimes().back(), 2.0);
    const QByteArray saved = bytesOf(document);
    EXPECT_EQ(DocumentFile::toBytes(DocumentFile::fromBytes(saved)), saved);
    Document replay;
    RecipeRunner(replay).run(parseRecipe(recipeFromHistory(document).dump(), "history"));
    EXPECT_EQ(bytesOf(replay), saved);
}

TEST(ImportedRigs, ACutRefusesUntilTheBonesAreConnected) {
    Document document;
    runSteps(document, {{{"command", "import"}, {"file", kMan}}});
    const QByteArray imported = bytesOf(document);
    const nlohmann::json cut = {
        {"command", "cut"},
        {"part", 0},
        {"plane", {{"point", {0.0, 6.0, 0.0}}, {"normal", {0.0, 1.0, 0.0}}}}};
    const std::string refusal = stepError(document, {cut});
    EXPECT_NE(
        refusal.find("is not connected to its parent; connect it first (Edit > Connect Bone)"),
        std::string::npos)
        << refusal;
    EXPECT_EQ(bytesOf(document), imported);

    // Connect every disconnected bone, one undo step each.
    int steps = 0;
    while (const std::optional<BoneId> bone =
               firstDisconnectedBone(document.parts().front().part->skeleton)) {
        const QByteArray before = bytesOf(document);
        runSteps(document, {{{"command", "connect_bone"}, {"part", 0}, {"bone", *bone}}});
        EXPECT_TRUE(document.parts().front().part->validate().empty());
        ++steps;
        document.undoStack()->undo();
        EXPECT_EQ(bytesOf(document), before);
        document.undoStack()->redo();
        ASSERT_LT(steps, 20);
    }
    EXPECT_GT(steps, 0);
    EXPECT_TRUE(document.parts().front().part->skeleton.isConnectedTree());
    // The cut no longer names a bone (the model's open surface may still
    // stop it).
    EXPECT_EQ(stepError(document, {cut}).find("not connected to its parent"), std::string::npos);
    const QByteArray connected = bytesOf(document);
    Document replay;
    RecipeRunner(replay).run(parseRecipe(recipeFromHistory(document).dump(), "history"));
    EXPECT_EQ(bytesOf(replay), connected);
}

}  // namespace
}  // namespace rigmesh::model::test
