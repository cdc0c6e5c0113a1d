// The RigMesh edits (paper 3.1-3.3) on a rig made elsewhere: Debian's
// assimp-testmodels X/Testwuson.X, an open surface whose skeleton has bones
// hanging disconnected from the pelvis and the spine and a further root
// chain. Splitting and deleting a bone work on it and keep the rest of the
// rig (names, disconnected chains, clips, the surface as it came); a merge
// refuses it naming the bone to connect first; every refusal leaves the
// document unchanged.
#include <optional>
#include <utility>

#include "ModelTestSupport.h"
#include "RecipeTestSupport.h"
#include "model/PartClips.h"
#include "part/BoneConnection.h"
#include "rig/BoneSegment.h"

namespace rigmesh::model::test {
namespace {

const std::string kWuson = "/usr/share/assimp/models/X/Testwuson.X";

struct Imported {
    Document document;
    QByteArray bytes;
};

void importWuson(Imported& imported) {
    runSteps(imported.document, {{{"command", "import"}, {"file", kWuson}}});
    ASSERT_EQ(imported.document.partCount(), 1);
    imported.bytes = bytesOf(imported.document);
}

const Part& partOf(const Document& document) {
    return *document.parts().front().part;
}

std::vector<std::string> clipNamesOf(const PartNode& node) {
    std::vector<std::string> names;
    for (const Clip* clip : clipsOf(node))
        names.push_back(clipName(*clip));
    return names;
}

// The bone `chainRoot`'s chain hangs from (its head's attachment).
BoneId hangsFrom(const Skeleton& skeleton, BoneId chainRoot) {
    return skeleton.attachments().at(skeleton.bone(chainRoot).head);
}

// The first bone hanging disconnected from another bone (not a further
// root chain's, which hangs from no bone).
std::optional<BoneId> firstBoneHangingFromABone(const Skeleton& skeleton) {
    for (const auto& [joint, parent] : skeleton.attachments())
        if (parent != kNoBone && !skeleton.childrenOf(joint).empty())
            return skeleton.childrenOf(joint).front();
    return std::nullopt;
}

// The imported rig before an edit (a copy: the edit replaces the part), the
// first bone hanging disconnected from another bone, and that bone.
struct HangingChain {
    Skeleton skeleton;
    BoneId chainRoot = kNoBone;
    BoneId parent = kNoBone;
};

HangingChain hangingChainOf(const Document& document) {
    HangingChain chain{partOf(document).skeleton};
    if (const std::optional<BoneId> root = firstBoneHangingFromABone(chain.skeleton)) {
        chain.chainRoot = *root;
        chain.parent = hangsFrom(chain.skeleton, *root);
    }
    return chain;
}

// What an edit of one bone must keep of an imported rig: a valid part, the
// surface as it came (still marked as a file's), every other bone's name,
// every clip, and the chains that hung disconnected still disconnected.
void expectRigKept(const Document& before, const Document& after, BoneId edited) {
    const Part& was = partOf(before);
    const Part& is = partOf(after);
    const std::vector<Message> problems = is.validate();
    EXPECT_TRUE(problems.empty()) << problems.front();
    EXPECT_TRUE(is.surfaceFromFile);
    EXPECT_EQ(is.mesh.vertices, was.mesh.vertices);
    EXPECT_EQ(is.mesh.faces, was.mesh.faces);
    for (const auto& [bone, name] : was.boneNames)
        if (bone != edited && is.skeleton.hasBone(bone)) {
            ASSERT_TRUE(is.boneNames.contains(bone)) << name;
            EXPECT_EQ(is.boneNames.at(bone), name);
        }
    EXPECT_EQ(clipNamesOf(after.parts().front()), clipNamesOf(before.parts().front()));
    for (const auto& [joint, parent] : was.skeleton.attachments())
        for (BoneId bone : was.skeleton.childrenOf(joint))
            if (bone != edited && is.skeleton.hasBone(bone)) {
                EXPECT_FALSE(is.skeleton.isConnected(bone))
                    << was.boneNames.at(bone) << " got connected by the edit";
            }
}

TEST(ImportedRigEdits, SplittingTheBoneAChainHangsFromKeepsTheRigAndTheChainOnTheNearerHalf) {
    Imported imported;
    importWuson(imported);
    const auto [skeleton, chainRoot, parent] = hangingChainOf(imported.document);
    ASSERT_NE(chainRoot, kNoBone);
    const JointId parentTail = skeleton.bone(parent).tail;

    runSteps(imported.document, {{{"command", "split_bone"}, {"part", 0}, {"bone", parent}}});
    const Part& split = partOf(imported.document);
    EXPECT_EQ(split.skeleton.boneCount(), skeleton.boneCount() + 1);
    // Skeleton::splitBone hangs the chain from the half nearer its head.
    const JointId middle = split.skeleton.bone(parent).tail;
    BoneId tailHalf = kNoBone;
    for (BoneId id : split.skeleton.childrenOf(middle))
        if (split.skeleton.bone(id).tail == parentTail)
            tailHalf = id;
    ASSERT_NE(tailHalf, kNoBone);
    auto distanceTo = [&](BoneId half) {
        const Bone& b = split.skeleton.bone(half);
        return pointSegmentDistance(
            split.skeleton.joint(split.skeleton.bone(chainRoot).head).position,
            {split.skeleton.joint(b.head).position, split.skeleton.joint(b.tail).position});
    };
    const BoneId nearer = distanceTo(tailHalf) < distanceTo(parent) ? tailHalf : parent;
    EXPECT_EQ(hangsFrom(split.skeleton, chainRoot), nearer);
    EXPECT_FALSE(split.skeleton.isConnected(chainRoot));

    Imported reference;
    importWuson(reference);
    expectRigKept(reference.document, imported.document, parent);
    imported.document.undoStack()->undo();
    EXPECT_EQ(bytesOf(imported.document), imported.bytes);
}

TEST(ImportedRigEdits, DeletingTheBoneAChainHangsFromHangsItFromTheBoneAbove) {
    Imported imported;
    importWuson(imported);
    const auto [skeleton, chainRoot, parent] = hangingChainOf(imported.document);
    ASSERT_NE(chainRoot, kNoBone);
    const BoneId above = skeleton.parentBone(parent).value_or(kNoBone);

    Imported reference;
    importWuson(reference);
    runSteps(imported.document, {{{"command", "delete_bone"}, {"part", 0}, {"bone", parent}}});
    const Part& deleted = partOf(imported.document);
    EXPECT_FALSE(deleted.skeleton.hasBone(parent));
    EXPECT_EQ(deleted.skeleton.boneCount(), partOf(reference.document).skeleton.boneCount() - 1);
    EXPECT_EQ(hangsFrom(deleted.skeleton, chainRoot), above);
    expectRigKept(reference.document, imported.document, parent);
    imported.document.undoStack()->undo();
    EXPECT_EQ(bytesOf(imported.document), imported.bytes);
}

TEST(ImportedRigEdits, DeletingADisconnectedBoneKeepsTheRig) {
    Imported imported;
    importWuson(imported);
    const std::optional<BoneId> disconnected =
        firstDisconnectedBone(partOf(imported.document).skeleton);
    ASSERT_TRUE(disconnected.has_value());
    const BoneId chainRoot = *disconnected;

    Imported reference;
    importWuson(reference);
    runSteps(imported.document, {{{"command", "delete_bone"}, {"part", 0}, {"bone", chainRoot}}});
    EXPECT_FALSE(partOf(imported.document).skeleton.hasBone(chainRoot));
    expectRigKept(reference.document, imported.document, chainRoot);
    imported.document.undoStack()->undo();
    EXPECT_EQ(bytesOf(imported.document), imported.bytes);
}

TEST(ImportedRigEdits, AMergeEitherWayRefusesNamingTheBoneAndChangesNothing) {
    Imported imported;
    importWuson(imported);
    addPart(imported.document, ellipseStroke(1.0, 0.4), "blob");
    const QByteArray before = bytesOf(imported.document);
    const std::string wuson = imported.document.parts().front().name.toStdString();
    for (const auto& [dragged, target] :
         {std::pair<std::string, std::string>{"blob", wuson}, {wuson, "blob"}}) {
        const std::string refusal = stepError(imported.document, {{{"command", "merge"},
                                                                   {"part", dragged},
                                                                   {"into", target},
                                                                   {"joint", 0},
                                                                   {"target", 0}}});
        EXPECT_NE(refusal.find("is not connected to its parent; connect it first "
                               "(Edit > Connect Bone)"),
                  std::string::npos)
            << dragged << " into " << target << ": " << refusal;
        EXPECT_EQ(bytesOf(imported.document), before);
    }
}

}  // namespace
}  // namespace rigmesh::model::test
