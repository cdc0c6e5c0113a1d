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

// Weight paint on a rig made elsewhere (disconnected bones, an open
// surface): a stroke on the vertices a bone leads is one undo step, every
// vertex keeps non-negative weights summing to 1, the part stays valid, and
// undo gives back the document byte for byte.
TEST(ImportedRigs, PaintingAnImportedRigIsOneUndoStepKeepingWeightsNormalised) {
    Document document;
    runSteps(document, {{{"command", "import"}, {"file", kWuson}}});
    ASSERT_EQ(document.partCount(), 1);
    const PartNode& node = document.parts().front();
    const Part& part = *node.part;
    ASSERT_FALSE(part.skeleton.isConnectedTree());
    // The bone with the most weight on one vertex, and that vertex's place.
    BoneId bone = 0;
    int at = -1;
    double best = 0.0;
    for (int v = 0; v < part.mesh.vertexCount(); ++v)
        for (const auto& [id, w] : part.weights.perVertex[v])
            if (w < 0.9 && w > best) {
                best = w;
                bone = id;
                at = v;
            }
    ASSERT_GE(at, 0);
    const Vec3 centre = node.placement.toWorld(part.mesh.vertices[at]);
    Eigen::AlignedBox3d box;
    for (const Vec3& p : part.mesh.vertices)
        box.extend(p);
    const QByteArray before = bytesOf(document);
    const int steps = document.undoStack()->count();
    runSteps(document, {{{"command", "paint_weights"},
                         {"part", 0},
                         {"bone", bone},
                         {"mode", "add"},
                         {"center", {centre.x(), centre.y(), centre.z()}},
                         {"radius", 0.05 * box.diagonal().norm()},
                         {"strength", 0.8}}});
    EXPECT_EQ(document.undoStack()->count(), steps + 1);
    const Part& painted = *document.parts().front().part;
    EXPECT_TRUE(painted.validate().empty());
    double weight = 0.0;
    for (const auto& [id, w] : painted.weights.perVertex[at])
        if (id == bone)
            weight = w;
    EXPECT_GT(weight, best) << "the stroke adds weight of the bone where it was painted";
    for (const auto& influences : painted.weights.perVertex) {
        double sum = 0.0;
        for (const auto& [id, w] : influences) {
            EXPECT_GE(w, 0.0);
            sum += w;
        }
        EXPECT_NEAR(sum, 1.0, 1e-9);
    }
    document.undoStack()->undo();
    EXPECT_EQ(bytesOf(document), before);
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
