// Weight painting: a dab changes weights only inside its
// radius, keeps every sum at 1, leaves locked bones alone, skips vertices
// it cannot change (saying why), hands what Subtract takes from a region
// one bone leads to the parent bone (Blender's auto-normalise), and with
// X-mirror paints the bone's mirror image on the other side.
#include <gtest/gtest.h>

#include "PartWeightOf.h"
#include "SharedSketchPart.h"
#include "base/Error.h"
#include "part/WeightCleanup.h"
#include "part/WeightPaint.h"
#include "rig/VertexMirror.h"

namespace rigmesh {
namespace {

using testsupport::weightOf;

struct Painted {
    Part part;
    WeightDab dab;
};

// An Add dab of the biped's first bone at a vertex off the sketch plane.
Painted addDab(BrushMode mode = BrushMode::Add) {
    Painted p{testsupport::sharedSketchPart("biped"), {}};
    int at = 0;
    for (int v = 0; v < p.part.mesh.vertexCount(); ++v)
        if (p.part.mesh.vertices[v].z() > p.part.mesh.vertices[at].z())
            at = v;
    p.dab.bone = p.part.skeleton.bones().front().id;
    p.dab.mode = mode;
    p.dab.centre = p.part.mesh.vertices[at];
    p.dab.radius = 0.4;
    p.dab.strength = 0.8;
    return p;
}

TEST(WeightPaint, AddChangesOnlyInsideTheRadiusAndKeepsSumsAtOne) {
    const Part& before = testsupport::sharedSketchPart("biped");
    Painted p = addDab();
    const DabResult result = paintWeights(p.part, p.dab);
    ASSERT_FALSE(result.changed.empty());
    EXPECT_TRUE(p.part.validate().empty());
    for (int v = 0; v < before.mesh.vertexCount(); ++v) {
        const bool inside = (before.mesh.vertices[v] - p.dab.centre).norm() < p.dab.radius;
        if (!inside) {
            EXPECT_EQ(p.part.weights.perVertex[v], before.weights.perVertex[v]) << v;
        } else {
            EXPECT_GE(weightOf(p.part, v, p.dab.bone), weightOf(before, v, p.dab.bone) - 1e-12);
        }
    }
}

TEST(WeightPaint, LockedBonesStayAndVerticesWithOnlyLockedBonesAreSkipped) {
    const Part& before = testsupport::sharedSketchPart("biped");
    Painted p = addDab();
    for (const Bone& bone : before.skeleton.bones())
        if (bone.id != p.dab.bone)
            p.dab.locked.insert(bone.id);
    const DabResult result = paintWeights(p.part, p.dab);
    EXPECT_GT(result.skippedLocked, 0);
    for (int v = 0; v < before.mesh.vertexCount(); ++v)
        for (const Bone& bone : before.skeleton.bones()) {
            if (bone.id != p.dab.bone) {
                EXPECT_EQ(weightOf(p.part, v, bone.id), weightOf(before, v, bone.id));
            }
        }
    WeightDab locked = p.dab;
    locked.locked.insert(p.dab.bone);
    EXPECT_THROW(paintWeights(p.part, locked), Error);
}

// Blender's X-mirror: a dab on the biped's right hand with X-mirror on
// paints the left hand's bone on the left as much, vertex by vertex: every
// vertex changed is within the brush or the partner of one that is
// (rig/VertexMirror), and each partner has the image bone's weight the
// vertex has of the hand's bone. The hand-drawn outline's surface is not
// symmetric: a vertex without a partner is painted on its side only.
TEST(WeightPaint, XMirrorPaintsTheMirrorBoneOnTheOtherSide) {
    Part part = testsupport::sharedSketchPart("biped");
    const Part before = part;
    const std::optional<PartSymmetry> symmetry = findPartSymmetry(part);
    ASSERT_TRUE(symmetry.has_value());
    EXPECT_GT(std::abs(symmetry->plane.normal.x()), 0.99) << "left and right of the sketch";
    // The right hand's joint and bone, and the image bone.
    JointId hand = part.skeleton.joints().front().id;
    for (const Joint& joint : part.skeleton.joints())
        if (joint.position.x() > part.skeleton.joint(hand).position.x())
            hand = joint.id;
    WeightDab dab;
    dab.bone = *boneForJoint(part.skeleton, hand);
    const BoneId image = symmetry->imageOf(dab.bone);
    ASSERT_NE(image, dab.bone);
    dab.mode = BrushMode::Subtract;
    dab.centre = part.skeleton.joint(hand).position;
    dab.radius = 0.5;
    dab.strength = 0.6;
    dab.mirror = true;
    const DabResult result = paintWeights(part, dab);
    EXPECT_TRUE(part.validate().empty());
    const std::vector<int> partner =
        mirrorVertices(part.mesh, symmetry->plane, vertexMirrorTolerance(part.mesh));
    auto inBrush = [&](int v) { return (part.mesh.vertices[v] - dab.centre).norm() < dab.radius; };
    double right = 0.0, left = 0.0;
    int unpaired = 0;
    for (int v : result.changed) {
        const int p = partner[v];
        EXPECT_TRUE(inBrush(v) || (p != kNoMirrorVertex && inBrush(p))) << v;
        if (inBrush(v)) {
            right += weightOf(before, v, dab.bone) - weightOf(part, v, dab.bone);
            if (p == kNoMirrorVertex) {
                ++unpaired;
                continue;
            }
            left += weightOf(before, p, image) - weightOf(part, p, image);
        }
    }
    EXPECT_EQ(unpaired, result.unpaired);
    EXPECT_GT(right, 1.0);
    // Each pair lost the same weight where both had the same before: the
    // sums differ only by what the sides' weights differed before.
    EXPECT_NEAR(left / right, 1.0, 0.25);
}

// Subtract where one bone alone leads (the weight is 1) gives the weight to
// the parent bone, as Blender's auto-normalise does, and says nothing was
// locked; a part of one bone is left as it is and says so.
TEST(WeightPaint, SubtractOnAOneBoneRegionHandsTheWeightToTheParentBone) {
    Part part = testsupport::sharedSketchPart("biped");
    // A vertex the hand's bone alone leads: at its tip.
    int tip = -1;
    for (int v = 0; v < part.mesh.vertexCount(); ++v)
        if (part.weights.perVertex[v].size() == 1 &&
            (tip < 0 || part.mesh.vertices[v].x() > part.mesh.vertices[tip].x()))
            tip = v;
    ASSERT_GE(tip, 0);
    WeightDab dab;
    dab.bone = part.weights.perVertex[tip].front().first;
    const std::optional<BoneId> parent = part.skeleton.parentBone(dab.bone);
    ASSERT_TRUE(parent.has_value());
    dab.mode = BrushMode::Subtract;
    dab.centre = part.mesh.vertices[tip];
    dab.radius = 0.2;
    dab.strength = 0.5;
    const DabResult result = paintWeights(part, dab);
    EXPECT_EQ(result.skippedLocked, 0);
    EXPECT_EQ(result.skippedOnlyBone, 0);
    EXPECT_TRUE(part.validate().empty());
    EXPECT_NEAR(weightOf(part, tip, dab.bone), 0.5, 1e-12);
    EXPECT_NEAR(weightOf(part, tip, *parent), 0.5, 1e-12);

    Part tube = testsupport::sharedSketchPart("tube");
    ASSERT_EQ(tube.skeleton.boneCount(), 1);
    dab.bone = tube.skeleton.bones().front().id;
    dab.centre = tube.mesh.vertices.front();
    const DabResult one = paintWeights(tube, dab);
    EXPECT_TRUE(one.changed.empty());
    EXPECT_GT(one.skippedOnlyBone, 0);
    EXPECT_EQ(one.skippedLocked, 0);
}

TEST(WeightPaint, SmoothEvensOutABoneAndReplaceMovesTowardsTheValue) {
    Painted p = addDab(BrushMode::Replace);
    p.dab.value = 0.5;
    p.dab.strength = 1.0;
    paintWeights(p.part, p.dab);
    // At the centre the weight is the value.
    int centre = 0;
    for (int v = 0; v < p.part.mesh.vertexCount(); ++v)
        if ((p.part.mesh.vertices[v] - p.dab.centre).norm() <
            (p.part.mesh.vertices[centre] - p.dab.centre).norm())
            centre = v;
    EXPECT_NEAR(weightOf(p.part, centre, p.dab.bone), 0.5, 0.05);
    p.dab.mode = BrushMode::Smooth;
    const Part before = p.part;
    paintWeights(p.part, p.dab);
    EXPECT_TRUE(p.part.validate().empty());
    EXPECT_NE(p.part.weights.perVertex, before.weights.perVertex);
}

}  // namespace
}  // namespace rigmesh

namespace rigmesh {
namespace {

// Blender's Normalize All, Clean and Limit Total: sums 1, no weight below
// the threshold but the largest, at most N influences; untouched vertices
// bit for bit.
TEST(WeightCleanup, CleanLimitAndNormalizeKeepValidWeights) {
    Part part = testsupport::sharedSketchPart("biped");
    EXPECT_EQ(normalizeAllWeights(part), 0) << "already normalised: nothing changes";
    const int cleaned = cleanWeights(part, 0.2);
    EXPECT_GT(cleaned, 0);
    EXPECT_TRUE(part.validate().empty());
    for (const auto& list : part.weights.perVertex)
        for (const auto& [bone, w] : list)
            if (list.size() > 1) {
                EXPECT_GE(w, 0.2 * 0.999);
            }
    Part limited = testsupport::sharedSketchPart("biped");
    limitWeightInfluences(limited, 1);
    EXPECT_TRUE(limited.validate().empty());
    for (const auto& list : limited.weights.perVertex)
        EXPECT_EQ(list.size(), 1u);
    EXPECT_THROW(limitWeightInfluences(limited, 0), Error);
    EXPECT_THROW(cleanWeights(limited, 1.0), Error);
}

}  // namespace
}  // namespace rigmesh
