// Characters other tools made (Debian's assimp-testmodels, installed by
// scripts/setup.sh, and meshes made in Blender, tests/data/autorig): many
// pieces, open borders, crossing faces, faces that repeat a corner. Each is
// rigged, not refused: all its meshes as one figure, on a wrapped proxy
// where it needs one, keeping every original vertex with weights summing
// to 1. The expected leaf count is the limbs a person counts on the
// character (written beside each).
#include <gtest/gtest.h>

#include <functional>

#include <Eigen/Geometry>
#include <map>
#include <string>

#include "AutoRigTestSupport.h"
#include "autorig/AxisChain.h"
#include "autorig/SurfaceProbe.h"

namespace rigmesh {
namespace {

const std::string kModels = "/usr/share/assimp/models/";
const std::string kBlenderMeshes = RIGMESH_TEST_DATA "/autorig/";

struct Character {
    std::string file;  // under kModels, or a full path
    int leaves;        // limbs a person counts
    // Why the auto-rig does not find them yet, for a character it is known to
    // miss (docs/ARCHITECTURE.md, the auto-rig's baseline renders): its leaf
    // count is reported, not asserted, until it comes right.
    std::string knownDefect = {};
};

void PrintTo(const Character& character, std::ostream* out) {
    *out << character.file;
}

struct RiggedCharacter {
    Part imported;  // every mesh of the file, in world space, one after another
    AutoRigResult rigged;
};

// Rigged with the wrap aiming at `wrapVertices` (ProxyWrapOptions), the
// default unless given.
const RiggedCharacter& rigged(const std::string& file,
                              int wrapVertices = ProxyWrapOptions{}.targetVertices) {
    static std::map<std::pair<std::string, int>, RiggedCharacter> cache;
    auto found = cache.find({file, wrapVertices});
    if (found == cache.end()) {
        RiggedCharacter character;
        character.imported.name = "figure";
        const std::string path = file.starts_with('/') ? file : kModels + file;
        for (const ImportedPart& part : importScene(path).parts) {
            const int offset = character.imported.mesh.vertexCount();
            for (const Vec3& v : part.part.mesh.vertices)
                character.imported.mesh.vertices.push_back(v);
            for (const auto& [a, b, c] : part.part.mesh.faces)
                character.imported.mesh.faces.push_back({a + offset, b + offset, c + offset});
        }
        AutoRigOptions options;
        options.surface.wrap.targetVertices = wrapVertices;
        character.rigged = autoRigPart(character.imported, options);
        found = cache.emplace(std::pair{file, wrapVertices}, std::move(character)).first;
    }
    return found->second;
}

Eigen::AlignedBox3d boundsOf(const TriMesh& mesh) {
    Eigen::AlignedBox3d box;
    for (const Vec3& v : mesh.vertices)
        box.extend(v);
    return box;
}

double diagonalOf(const TriMesh& mesh) {
    return boundsOf(mesh).diagonal().norm();
}

class AutoRigCharacter : public ::testing::TestWithParam<Character> {};

TEST_P(AutoRigCharacter, IsRiggedKeepingEveryVertexAndSaysWhatItWorkedAround) {
    const RiggedCharacter& character = rigged(GetParam().file);
    EXPECT_EQ(character.rigged.part.mesh.vertices, character.imported.mesh.vertices);
    EXPECT_EQ(character.rigged.part.mesh.faces, character.imported.mesh.faces);
    EXPECT_TRUE(character.rigged.part.validate().empty());
    EXPECT_FALSE(character.rigged.repairs.empty());
}

TEST_P(AutoRigCharacter, SkeletonIsATreeInsideTheProxy) {
    const AutoRigResult& result = rigged(GetParam().file).rigged;
    const Skeleton& skeleton = result.part.skeleton;
    EXPECT_TRUE(skeleton.validate().empty());
    EXPECT_TRUE(skeleton.isOrientedFromRoot());
    int outside = 0;
    for (const BoneSegment& bone : result.part.boneSegments())
        for (int i = 0; i <= 8; ++i)
            outside += parttest::windingNumber(
                           result.rigSurface, bone.head + (bone.tail - bone.head) * (i / 8.0)) < 0.5
                           ? 1
                           : 0;
    EXPECT_EQ(outside, 0);
}

// A skeleton computed on a proxy lies inside the proxy, which is fatter
// than the mesh; every joint (so every bone tail Blender shows, end bones'
// too) lies inside the mesh itself as ray-cast parity counts it (an eye
// inside a head is outside), the test a rigger's eye and
// tests/external/check_tails_inside_in_blender.py apply.
TEST_P(AutoRigCharacter, EveryJointLiesInsideTheMeshByRayParity) {
    const RiggedCharacter& character = rigged(GetParam().file);
    const TriMesh& mesh = character.rigged.part.mesh;
    const double size = diagonalOf(mesh);
    std::string outside;
    for (const Joint& joint : character.rigged.part.skeleton.joints())
        if (!parttest::insideByRayParity(mesh, joint.position, size))
            outside += " " + std::to_string(joint.id);
    EXPECT_TRUE(outside.empty()) << "joints outside:" << outside;
}

TEST_P(AutoRigCharacter, EveryVertexIsWithin15PercentOfTheDiagonalFromABone) {
    const RiggedCharacter& character = rigged(GetParam().file);
    const double diagonal = diagonalOf(character.imported.mesh);
    EXPECT_LE(farthestFromBones(character.imported.mesh, character.rigged.part.skeleton),
              0.15 * diagonal);
}

TEST_P(AutoRigCharacter, LeafCountIsTheLimbsAPersonCounts) {
    const int leaves = autorigtest::leafCount(rigged(GetParam().file).rigged.part.skeleton);
    if (!GetParam().knownDefect.empty()) {
        // A known defect that is gone must leave the list.
        EXPECT_NE(leaves, GetParam().leaves) << "fixed: remove the known defect";
        GTEST_SKIP() << "known defect: " << leaves << " leaves, a person counts "
                     << GetParam().leaves << ": " << GetParam().knownDefect;
    }
    EXPECT_EQ(leaves, GetParam().leaves);
}

// The root sits where the limbs branch (the torso), not partway along a
// limb: a pose moves the figure from there, as a person's rig does.
TEST_P(AutoRigCharacter, RootIsABranchingJoint) {
    const Skeleton& skeleton = rigged(GetParam().file).rigged.part.skeleton;
    EXPECT_GE(skeleton.degree(skeleton.root()), 3);
}

TEST_P(AutoRigCharacter, EveryOriginalVertexHasPositiveWeightsSummingToOne) {
    const RiggedCharacter& character = rigged(GetParam().file);
    autorigtest::expectPositiveWeightsSummingToOne(character.rigged.part.weights.perVertex,
                                                   character.imported.mesh.vertexCount());
}

// The leaves below `share` of the figure's height (y up).
std::vector<Vec3> leavesBelow(const AutoRigResult& result, double share) {
    const Eigen::AlignedBox3d box = boundsOf(result.part.mesh);
    const double level = box.min().y() + share * box.sizes().y();
    std::vector<Vec3> leaves;
    for (const Joint& joint : result.part.skeleton.joints())
        if (result.part.skeleton.degree(joint.id) == 1 && joint.position.y() < level)
            leaves.push_back(joint.position);
    return leaves;
}

// Sydney's shins touch from the knees down: the proxy joins them, and her
// right thigh's chain ended at the knee while one chain ran down both
// shins. Each foot ends a leg of its own now (autorig/FusedLimbs): two
// leaves in the lowest tenth of her height (y up), one per foot.
TEST(AutoRigSydney, EachShinEndsALegOfItsOwn) {
    const AutoRigResult& result = rigged("MD2/sydney.md2").rigged;
    const Eigen::AlignedBox3d box = boundsOf(result.part.mesh);
    const std::vector<Vec3> feet = leavesBelow(result, 0.1);
    ASSERT_EQ(feet.size(), 2u);
    // Each in its own foot: farther apart than a twentieth of her height.
    EXPECT_GT((feet[0] - feet[1]).norm(), 0.05 * box.sizes().y());
}

// On a coarser wrap her thighs are one on the proxy too, and the tree cut
// the loop thigh, shins, thigh high in one thigh: that stub's chain has both
// thighs' outlines around it, one of them the other chain's. It is not
// split into two limbs (which left a leaf at a knee): a limb that has a
// chain of its own gets no second one (autorig/FusedLimbs).
TEST(AutoRigSydney, OnACoarserWrapNoLegEndsAtTheKnee) {
    const AutoRigResult& result = rigged("MD2/sydney.md2", 1600).rigged;
    EXPECT_EQ(autorigtest::leafCount(result.part.skeleton), 5);
    // Her hips at about 45% of her height (y up): every leaf below them a foot.
    EXPECT_EQ(leavesBelow(result, 0.45).size(), 2u);
    EXPECT_EQ(leavesBelow(result, 0.1).size(), 2u);
}

// Mr. Fixit's legs are 1.4% of the diagonal apart: the proxy fuses them
// from the crotch down, and the chain from the chest parts low on them.
// Both legs leave the parting joint (autorig/FusedLimbs): two leaves in the
// lowest tenth of his height (y up), one per foot, either side of him.
TEST(AutoRigMrFixit, EachLegEndsInAFootOfItsOwn) {
    const AutoRigResult& result = rigged("IQM/mrfixit.iqm").rigged;
    const Eigen::AlignedBox3d box = boundsOf(result.part.mesh);
    const std::vector<Vec3> feet = leavesBelow(result, 0.1);
    ASSERT_EQ(feet.size(), 2u);
    EXPECT_GT((feet[0] - feet[1]).norm(), 0.05 * box.sizes().y());
    // He faces x and is mirrored across z = 0: a foot on each side.
    EXPECT_LT(feet[0].z() * feet[1].z(), 0.0);
}

// The dwarf holds a long axe in its left hand: measured along the bones the
// hand is the skeleton's middle, but the root belongs in the chest, the
// deepest place of the figure (rig/ShortBones keeps the auto-rig's root,
// the thickest junction, when it collapses a short bone).
TEST(AutoRigDwarf, RootIsInTheChestNotTheHandHoldingTheAxe) {
    const AutoRigResult& result = rigged("COB/dwarf.cob").rigged;
    const Skeleton& skeleton = result.part.skeleton;
    const SurfaceProbe probe(result.rigSurface);
    const double rootDepth = probe.distance(skeleton.joint(skeleton.root()).position);
    for (const Joint& joint : skeleton.joints()) {
        if (skeleton.degree(joint.id) >= 3) {
            EXPECT_GE(rootDepth, probe.distance(joint.position)) << "joint " << joint.id;
        }
    }
}

// The leaves beyond `level` along the x axis, on the side `side` (+1, -1).
int leavesBeyond(const Skeleton& skeleton, double level, double side) {
    int leaves = 0;
    for (const Joint& joint : skeleton.joints())
        leaves += skeleton.degree(joint.id) == 1 && side * (joint.position.x() - level) > 0 ? 1 : 0;
    return leaves;
}

// The axe runs through the dwarf's left fist (x about -20, z up): the
// handle's end below the fist and the blade's two corners were leaves, the
// hand none. The arm's chain now runs on from the hand along the axe to
// the blade (autorig/HeldProps): one leaf on that side, no other limb
// there.
TEST(AutoRigHeldProps, TheDwarfsArmAndAxeEndInOneLeaf) {
    EXPECT_EQ(leavesBeyond(rigged("COB/dwarf.cob").rigged.part.skeleton, -15.0, -1.0), 1);
}

// The Blender figure holds a spear upright in its right fist (x about
// 1.06, y up), low on the shaft: the shaft's end below the fist was a
// leaf beside the spear's top; only the top is one now.
TEST(AutoRigHeldProps, TheSpearEndsInOneLeafAtItsTop) {
    const Skeleton& skeleton = rigged(kBlenderMeshes + "armed.obj").rigged.part.skeleton;
    EXPECT_EQ(leavesBeyond(skeleton, 0.9, 1.0), 1);
    for (const Joint& joint : skeleton.joints())
        if (skeleton.degree(joint.id) == 1 && joint.position.x() > 0.9) {
            EXPECT_GT(joint.position.y(), 2.5);
        }
}

// The user is told what became of a held prop, once per prop; a figure
// without one is not.
TEST(AutoRigHeldProps, TheResultSaysWhichPropsAreHeld) {
    const auto heldProps = [](const AutoRigResult& result) {
        int notes = 0;
        for (const Message& note : result.repairs)
            if (note.id == MessageId::AutoRigHeldProps) {
                ++notes;
                EXPECT_EQ(note.args, std::vector<std::string>{"1"});
            }
        return notes;
    };
    EXPECT_EQ(heldProps(rigged("COB/dwarf.cob").rigged), 1);
    EXPECT_EQ(heldProps(rigged(kBlenderMeshes + "armed.obj").rigged), 1);
    EXPECT_EQ(heldProps(rigged("MD2/sydney.md2").rigged), 0);
}

// The positions of the leaves (not the root) that `where` holds.
std::vector<Vec3> leavesWhere(const Skeleton& skeleton,
                              const std::function<bool(const Vec3&)>& where) {
    std::vector<Vec3> leaves;
    for (const Joint& joint : skeleton.joints())
        if (joint.id != skeleton.root() && skeleton.degree(joint.id) == 1 && where(joint.position))
            leaves.push_back(joint.position);
    return leaves;
}

// The dwarf's helmet wears two horns (pieces of their own, z up): the flow
// forked in the middle of the head into a leaf in each horn, and the head
// had none. The head now ends in one leaf in its middle, below the horns,
// which ride on its bone (autorig/WornPieces), and the result says so.
TEST(AutoRigWornPieces, TheDwarfsHeadEndsInOneLeafAndItsHornsRideOnIt) {
    const AutoRigResult& result = rigged("COB/dwarf.cob").rigged;
    const Skeleton& skeleton = result.part.skeleton;
    const std::vector<Vec3> aboveShoulders =
        leavesWhere(skeleton, [](const Vec3& p) { return p.z() > 55.0; });
    ASSERT_EQ(aboveShoulders.size(), 1u);
    // The horns leave the helmet at |x| 2 to 12 and reach z = 70.
    EXPECT_LT(std::abs(aboveShoulders.front().x()), 2.0);
    EXPECT_LT(aboveShoulders.front().z(), 64.5);
    std::vector<std::vector<std::string>> notes;
    for (const Message& note : result.repairs)
        if (note.id == MessageId::AutoRigWornPieces)
            notes.push_back(note.args);
    EXPECT_EQ(notes, (std::vector<std::vector<std::string>>{{"2"}}));
}

// The same rule on a figure made in Blender (the primitives' figure, y up
// in the OBJ, its head a sphere of radius 0.32 about y = 2.1 wearing two
// cones that point up and out to x = +-0.45, y = 2.57): one leaf in the
// head, none in a horn.
TEST(AutoRigWornPieces, TheHornsOfAFigureMadeInBlenderRideOnItsHead) {
    const AutoRigResult& result = rigged(kBlenderMeshes + "horned.obj").rigged;
    const Skeleton& skeleton = result.part.skeleton;
    const std::vector<Vec3> inHead =
        leavesWhere(skeleton, [](const Vec3& p) { return p.y() > 1.8; });
    ASSERT_EQ(inHead.size(), 1u);
    EXPECT_LT((inHead.front() - Vec3(0, 2.1, 0)).norm(), 0.32);
}

INSTANTIATE_TEST_SUITE_P(AssimpTestModels, AutoRigCharacter,
                         ::testing::Values(
                             // arms, legs, head and four wings
                             Character{"MD2/faerie.md2", 9},
                             // arms, legs, head
                             Character{"MD2/sydney.md2", 5},
                             // a bull: four legs, tail, head
                             Character{"OBJ/WusonOBJ.obj", 6},
                             // arms, legs, head; the axe goes with the hand, the
                             // helmet's horns with the head
                             Character{"COB/dwarf.cob", 5},
                             // arms, legs, head
                             Character{"BLEND/HUMAN.blend", 5},
                             // eight legs, the head's and the abdomen's ends
                             Character{"OBJ/spider.obj", 10},
                             // arms, legs, head (legs 1.4% of the diagonal
                             // apart, fused on the proxy: autorig/FusedLimbs)
                             Character{"IQM/mrfixit.iqm", 5},
                             // arms, legs, head (15.6k vertices, 5 pieces)
                             Character{"Collada/human.zae", 5},
                             // a dinosaur: four legs, tail, neck and head
                             Character{"X/fromtruespace_bin32.x", 6},
                             // a figure of 26 boxes: arms, legs, head
                             Character{"ASE/MotionCaptureROM.ase", 5}));

INSTANTIATE_TEST_SUITE_P(MadeInBlender, AutoRigCharacter,
                         ::testing::Values(
                             // a head alone: two ears and the neck
                             Character{kBlenderMeshes + "suzanne.obj", 3},
                             // arms, legs, head
                             Character{kBlenderMeshes + "primitives.obj", 5},
                             // arms, legs, head; the horns go with the head
                             Character{kBlenderMeshes + "horned.obj", 5},
                             // arms, head and the trunk down to the open base
                             Character{kBlenderMeshes + "statue.obj", 4},
                             // arms, legs, head; the spear and the sword go
                             // with the hands that hold them
                             Character{kBlenderMeshes + "armed.obj", 5}));

// The wrap's fineness is the auto-rig's choice (a vertex budget, so a
// time budget: ProxyWrap.h), not the character's: the same characters on
// wraps aiming at 1600 and 3600 vertices (alpha about 1.22 and 0.82 times
// the default's) keep a tree inside the proxy, every joint inside the mesh
// and every vertex within 15% of the diagonal from a bone. Their leaf
// counts are not asserted here: they vary with the wrap (docs/ARCHITECTURE.md,
// the auto-rig's known limits). Before, the faerie's coarser wrap left a
// wing 32% of the diagonal from any bone (a tip moved to the middle of the
// wing's cross-section, autorig/BonesInside), and the spider's kept 1-3
// bone points outside the proxy after six rounds of splits.
struct WrapFineness {
    std::string file;
    int wrapVertices;
};

void PrintTo(const WrapFineness& wrap, std::ostream* out) {
    *out << wrap.file << " at " << wrap.wrapVertices;
}

class AutoRigWrapFineness : public ::testing::TestWithParam<WrapFineness> {};

TEST_P(AutoRigWrapFineness, RootIsABranchingJoint) {
    const Skeleton& skeleton =
        rigged(GetParam().file, GetParam().wrapVertices).rigged.part.skeleton;
    EXPECT_GE(skeleton.degree(skeleton.root()), 3);
}

TEST_P(AutoRigWrapFineness, KeepsATreeInsideThatCoversTheBody) {
    const RiggedCharacter& character = rigged(GetParam().file, GetParam().wrapVertices);
    const AutoRigResult& result = character.rigged;
    EXPECT_TRUE(result.part.validate().empty());
    EXPECT_TRUE(result.part.skeleton.isOrientedFromRoot());
    int outsideProxy = 0;
    for (const BoneSegment& bone : result.part.boneSegments())
        for (int i = 0; i <= 8; ++i)
            outsideProxy +=
                parttest::windingNumber(result.rigSurface,
                                        bone.head + (bone.tail - bone.head) * (i / 8.0)) < 0.5
                    ? 1
                    : 0;
    EXPECT_EQ(outsideProxy, 0);
    const double diagonal = diagonalOf(character.imported.mesh);
    int outsideMesh = 0;
    for (const Joint& joint : result.part.skeleton.joints())
        outsideMesh +=
            parttest::insideByRayParity(result.part.mesh, joint.position, diagonal) ? 0 : 1;
    EXPECT_EQ(outsideMesh, 0);
    EXPECT_LE(farthestFromBones(character.imported.mesh, result.part.skeleton), 0.15 * diagonal);
    autorigtest::expectPositiveWeightsSummingToOne(result.part.weights.perVertex,
                                                   character.imported.mesh.vertexCount());
}

std::vector<WrapFineness> coarserAndFinerWraps() {
    std::vector<WrapFineness> wraps;
    for (const std::string& file : std::vector<std::string>{
             "MD2/faerie.md2", "MD2/sydney.md2", "OBJ/WusonOBJ.obj", "COB/dwarf.cob",
             "BLEND/HUMAN.blend", "OBJ/spider.obj", "IQM/mrfixit.iqm", "Collada/human.zae",
             "X/fromtruespace_bin32.x", "ASE/MotionCaptureROM.ase", kBlenderMeshes + "suzanne.obj",
             kBlenderMeshes + "primitives.obj", kBlenderMeshes + "horned.obj",
             kBlenderMeshes + "statue.obj", kBlenderMeshes + "armed.obj"})
        for (int vertices : {1600, 3600})
            wraps.push_back({file, vertices});
    return wraps;
}

INSTANTIATE_TEST_SUITE_P(CoarserAndFiner, AutoRigWrapFineness,
                         ::testing::ValuesIn(coarserAndFinerWraps()));

// A limb's end the flow split in two where one half is a twig and the
// other a longer branch of the same junction, their tips' balls
// overlapping: one end, one leaf (autorig/SkeletonFromCurve pruneTwigs).
// Before, only two twigs were taken for such halves: sydney's raised hand
// on a wrap of 3000 vertices ended in two leaves (6), and one of the
// faerie's arms on a wrap of 2000 (10).
TEST(AutoRigSplitEnd, AHalfBesideALongerBranchIsPrunedOnOtherWraps) {
    EXPECT_EQ(autorigtest::leafCount(rigged("MD2/sydney.md2", 3000).rigged.part.skeleton), 5);
    EXPECT_EQ(autorigtest::leafCount(rigged("MD2/faerie.md2", 2000).rigged.part.skeleton), 9);
}

// A region far from every bone on a thick body (the Wuson's hump) gets a
// bend of the nearest bone towards it, not a branch that would end in a
// leaf: where the middle of the region's cross-section lies too deep to
// cover it, the bend goes towards the far point itself
// (autorig/BoneCoverage). Before, on wraps of 1600 and 2000 vertices, the
// hump grew a branch and the bull had 7 leaves.
TEST(AutoRigCoverage, AHumpOnAThickBodyBendsABoneInsteadOfGrowingALeaf) {
    for (int wrapVertices : {1600, 2000})
        EXPECT_EQ(
            autorigtest::leafCount(rigged("OBJ/WusonOBJ.obj", wrapVertices).rigged.part.skeleton),
            6)
            << "wrap of " << wrapVertices;
}

// Blobs of assimp-testmodels, no limbs at all, that the auto-rig refused
// ("too small for a bone") before: a sphere the flow contracts to a stub
// 8.7e-5 long, and meshes so coarse (a tetrahedron, an octahedron, boxes,
// a 6-vertex sphere with a hole) that their only bone came out shorter than
// half their mean edge. Each is rigged now: a chain along its main axis
// where the flow gives a stub, on a proxy where the mesh is coarse, with
// weights summing to 1 on every vertex and, where the mesh is one closed
// piece, every bone inside it.
TEST(AutoRigBlobs, EveryBlobIsRiggedWithBonesInsideNotRefused) {
    struct Blob {
        std::string file;
        bool closed;  // one closed piece: bones are checked inside it
    };
    for (const Blob& blob :
         {Blob{"AC/SphereWithLight.ac", true}, Blob{"AMF/test1.amf", true},
          Blob{"NFF/NFF/octahedron.nff", true}, Blob{"BLEND/4Cubes4Mats_248.blend", false},
          Blob{"STL/sphereWithHole.stl", false}}) {
        const RiggedCharacter& character = rigged(blob.file);
        const Part& part = character.rigged.part;
        ASSERT_GE(part.skeleton.boneCount(), 1) << blob.file;
        EXPECT_TRUE(part.skeleton.validate().empty()) << blob.file;
        EXPECT_TRUE(part.validate().empty()) << blob.file;
        if (blob.closed) {
            EXPECT_EQ(autorigtest::bonePointsOutside(part), 0) << blob.file;
        }
        autorigtest::expectPositiveWeightsSummingToOne(part.weights.perVertex,
                                                       character.imported.mesh.vertexCount());
    }
}

}  // namespace
}  // namespace rigmesh
