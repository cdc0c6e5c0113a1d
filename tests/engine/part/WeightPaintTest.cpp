// Weight painting: a dab changes weights only inside its
// radius, keeps every sum at 1, leaves locked bones alone, skips vertices
// it cannot change, and with X-mirror keeps the part mirror symmetric.
#include <gtest/gtest.h>

#include "PartWeightOf.h"
#include "SharedSketchPart.h"
#include "base/Error.h"
#include "part/WeightCleanup.h"
#include "part/WeightPaint.h"

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

TEST(WeightPaint, XMirrorKeepsTheWeightsSymmetric) {
    Painted p = addDab(BrushMode::Subtract);
    p.dab.mirror = true;
    paintWeights(p.part, p.dab);
    EXPECT_TRUE(p.part.validate().empty());
    for (int v = 0; v < p.part.mesh.vertexCount(); ++v)
        ASSERT_NEAR(weightOf(p.part, v, p.dab.bone), weightOf(p.part, p.part.mirror[v], p.dab.bone),
                    1e-12)
            << v;
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
