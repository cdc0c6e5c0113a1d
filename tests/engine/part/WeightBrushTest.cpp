// The brush's falloff and "front faces only", the locks every clean-up
// keeps, Smooth All, Recompute Weights and Check Rig.
#include <gtest/gtest.h>

#include <cmath>
#include <stdexcept>

#include "PartWeightOf.h"
#include "SharedSketchPart.h"
#include "base/Error.h"
#include "mesh/MeshAdjacency.h"
#include "mesh/VertexNormals.h"
#include "part/RigCheck.h"
#include "part/WeightCleanup.h"
#include "part/WeightPaint.h"
#include "rig/LocalBoneHeat.h"

namespace rigmesh {
namespace {

using testsupport::weightOf;

double sumOf(const Part& part, int v) {
    double sum = 0.0;
    for (const auto& entry : part.weights.perVertex[v])
        sum += entry.second;
    return sum;
}

// The biped's vertex farthest towards +z (in front of the sketch plane).
int frontmostVertex(const Part& part) {
    int at = 0;
    for (int v = 0; v < part.mesh.vertexCount(); ++v)
        if (part.mesh.vertices[v].z() > part.mesh.vertices[at].z())
            at = v;
    return at;
}

// A Replace dab of constant falloff on the first bone, at full strength,
// centred on the biped's frontmost vertex.
WeightDab constantReplaceInFront(const Part& part, double value, double radius) {
    WeightDab dab;
    dab.bone = part.skeleton.bones().front().id;
    dab.mode = BrushMode::Replace;
    dab.falloff = BrushFalloff::Constant;
    dab.value = value;
    dab.strength = 1.0;
    dab.centre = part.mesh.vertices[frontmostVertex(part)];
    dab.radius = radius;
    return dab;
}

TEST(BrushFalloff, ProfilesStartAtOneAndEndAtZeroExceptConstant) {
    for (BrushFalloff f : {BrushFalloff::Smooth, BrushFalloff::Linear, BrushFalloff::Sharp}) {
        EXPECT_DOUBLE_EQ(brushFalloff(f, 0.0), 1.0);
        EXPECT_DOUBLE_EQ(brushFalloff(f, 1.0), 0.0);
        for (double d = 0.0; d < 1.0; d += 0.05)
            EXPECT_GE(brushFalloff(f, d), brushFalloff(f, d + 0.05)) << "falls off monotonically";
    }
    EXPECT_DOUBLE_EQ(brushFalloff(BrushFalloff::Constant, 0.99), 1.0);
    EXPECT_LT(brushFalloff(BrushFalloff::Sharp, 0.5), brushFalloff(BrushFalloff::Linear, 0.5));
}

TEST(WeightPaint, ConstantFalloffReplacesEveryVertexInsideTheRadiusFully) {
    Part part = testsupport::sharedSketchPart("biped");
    const WeightDab dab = constantReplaceInFront(part, 0.25, 0.3);
    paintWeights(part, dab);
    EXPECT_TRUE(part.validate().empty());
    int inside = 0;
    for (int v = 0; v < part.mesh.vertexCount(); ++v)
        if ((part.mesh.vertices[v] - dab.centre).norm() < dab.radius) {
            ++inside;
            EXPECT_NEAR(weightOf(part, v, dab.bone), 0.25, 1e-9) << v;
        }
    EXPECT_GT(inside, 5);
}

TEST(WeightPaint, FrontFacesOnlyLeavesTheFarSideOfTheLimb) {
    const Part& before = testsupport::sharedSketchPart("biped");
    Part through = before;
    Part front = before;
    WeightDab dab;
    dab.bone = before.skeleton.bones().back().id;
    dab.mode = BrushMode::Add;
    dab.strength = 1.0;
    // A brush on the sketch plane as big as the part: "through" paints both
    // sides, "front faces only" (viewer at +z) only the side facing +z.
    dab.centre = Vec3::Zero();
    dab.radius = 100.0;
    paintWeights(through, dab);
    dab.towardsViewer = Vec3(0.0, 0.0, 1.0);
    paintWeights(front, dab);
    const std::vector<Vec3> normals = vertexNormals(before.mesh);
    int back = 0, facing = 0;
    for (int v = 0; v < before.mesh.vertexCount(); ++v) {
        if (normals[v].z() <= 0.0) {
            ++back;
            EXPECT_EQ(front.weights.perVertex[v], before.weights.perVertex[v]) << v;
        } else if (through.weights.perVertex[v] != before.weights.perVertex[v]) {
            ++facing;
            EXPECT_EQ(front.weights.perVertex[v], through.weights.perVertex[v]) << v;
        }
    }
    EXPECT_GT(back, before.mesh.vertexCount() / 4);
    EXPECT_GT(facing, before.mesh.vertexCount() / 4);
    EXPECT_TRUE(front.validate().empty());
}

TEST(WeightPainter, ManyDabsEqualOneOffDabsBitForBit) {
    Part cached = testsupport::sharedSketchPart("star");
    Part oneOff = cached;
    WeightPainter painter(cached.mesh);
    WeightDab dab;
    dab.bone = cached.skeleton.bones()[1].id;
    dab.radius = 0.2;
    dab.strength = 0.6;
    for (int i = 0; i < 12; ++i) {
        dab.mode = i % 3 == 2 ? BrushMode::Smooth : BrushMode::Add;
        dab.centre = cached.mesh.vertices[(i * 97) % cached.mesh.vertexCount()];
        painter.paint(cached, dab);
        paintWeights(oneOff, dab);
    }
    EXPECT_EQ(cached.weights.perVertex, oneOff.weights.perVertex);
    Part other = testsupport::sharedSketchPart("biped");
    EXPECT_THROW(painter.paint(other, dab), std::logic_error) << "a painter serves one mesh";
}

// Every clean-up keeps a locked bone's weights bit for bit and sums at 1.
TEST(WeightCleanup, LockedBonesKeepTheirWeightsThroughEveryCleanup) {
    const Part& before = testsupport::sharedSketchPart("biped");
    const BoneId lockedBone = before.skeleton.bones()[2].id;
    const std::set<BoneId> locked{lockedBone};
    std::vector<Part> cleaned(4, before);
    EXPECT_GT(cleanWeights(cleaned[0], 0.3, locked), 0);
    EXPECT_GT(limitWeightInfluences(cleaned[1], 1, locked), 0);
    EXPECT_GT(smoothAllWeights(cleaned[2], {0.8, 3}, locked), 0);
    // Normalize: first put the sums off by scaling the unlocked weights.
    for (auto& list : cleaned[3].weights.perVertex)
        for (auto& [b, w] : list)
            if (b != lockedBone)
                w *= 0.5;
    EXPECT_GT(normalizeAllWeights(cleaned[3], locked), 0);
    for (const Part& part : cleaned) {
        EXPECT_TRUE(part.validate().empty()) << part.validate().front();
        for (int v = 0; v < part.mesh.vertexCount(); ++v) {
            ASSERT_EQ(weightOf(part, v, lockedBone), weightOf(before, v, lockedBone)) << v;
            ASSERT_NEAR(sumOf(part, v), 1.0, 1e-9);
        }
    }
    // Limit Total keeps the locked bone and the largest unlocked one.
    for (int v = 0; v < before.mesh.vertexCount(); ++v)
        EXPECT_LE(cleaned[1].weights.perVertex[v].size(),
                  weightOf(before, v, lockedBone) > 0.0 ? 2u : 1u);
}

// The largest per-edge jump of any bone's weight, summed over edges: how
// rough the weights are.
double roughness(const Part& part) {
    const auto neighbours = vertexNeighbours(part.mesh);
    double total = 0.0;
    for (int v = 0; v < part.mesh.vertexCount(); ++v)
        for (int n : neighbours[v]) {
            double jump = 0.0;
            for (const Bone& bone : part.skeleton.bones())
                jump = std::max(jump,
                                std::abs(weightOf(part, v, bone.id) - weightOf(part, n, bone.id)));
            total += jump;
        }
    return total;
}

TEST(WeightCleanup, SmoothAllMakesWeightsSmootherAndKeepsSums) {
    // Rough weights first: a constant-falloff Replace leaves a step.
    Part part = testsupport::sharedSketchPart("biped");
    paintWeights(part, constantReplaceInFront(part, 1.0, 0.4));
    // Each pass makes the weights smoother; many passes much smoother.
    double previous = roughness(part);
    const double start = previous;
    for (int pass = 0; pass < 3; ++pass) {
        EXPECT_GT(smoothAllWeights(part, {0.5, 1}), 0);
        EXPECT_TRUE(part.validate().empty());
        const double now = roughness(part);
        EXPECT_LT(now, previous) << "pass " << pass;
        previous = now;
    }
    // Each pass spreads one ring of neighbours; the biped's limbs are meshed
    // at 0.25 of their radius, so many passes means 60.
    smoothAllWeights(part, {0.5, 60});
    EXPECT_LT(roughness(part), 0.8 * start);
    EXPECT_THROW(smoothAllWeights(part, {1.5, 1}), Error);
    EXPECT_THROW(smoothAllWeights(part, {0.5, 0}), Error);
}

TEST(RigCheck, AFreshPartIsCleanAndEachProblemIsFound) {
    Part part = testsupport::sharedSketchPart("biped");
    RigCheckOptions options;
    options.maxInfluences = 64;
    EXPECT_TRUE(checkRig(part, options).clean());
    // Paint one bone out of every vertex it leads: it leads none.
    const BoneId gone = part.skeleton.bones().back().id;
    const BoneId other = part.skeleton.bones().front().id;
    for (auto& list : part.weights.perVertex) {
        std::erase_if(list, [&](const auto& e) { return e.first == gone; });
        if (list.empty())
            list.emplace_back(other, 1.0);
        double sum = 0.0;
        for (const auto& e : list)
            sum += e.second;
        for (auto& e : list)
            e.second /= sum;
    }
    part.weights.perVertex[3].clear();           // unweighted
    part.weights.perVertex[5][0].second += 0.5;  // sum off 1
    const RigCheckReport report = checkRig(part, options);
    EXPECT_EQ(report.unweightedVertices, std::vector<int>{3});
    EXPECT_EQ(report.verticesWithSumsOff, std::vector<int>{5});
    EXPECT_EQ(report.bonesLeadingNoVertex, std::vector<BoneId>{gone});
    options.maxInfluences = 1;
    const RigCheckReport tight = checkRig(part, options);
    for (int v : tight.verticesOverInfluences)
        EXPECT_GT(part.weights.perVertex[v].size(), 1u);
    EXPECT_FALSE(tight.verticesOverInfluences.empty());
    options.maxInfluences = 0;
    EXPECT_THROW(checkRig(part, options), Error);
}

// Recompute Weights: painted weights go back to the whole-part bone heat
// (paper 2.4); a locked bone keeps its weights bit for bit and every vertex
// still sums to 1.
TEST(RecomputeWeights, PaintedWeightsGoBackToBoneHeatAndLockedBonesKeepTheirs) {
    const Part& fresh = testsupport::sharedSketchPart("y_branch");
    const WeightsById heat = recomputeWeightsGlobally(fresh.mesh, fresh.skeleton);
    Part painted = fresh;
    WeightDab dab;
    const Bone& bone = painted.skeleton.bones().front();
    dab.bone = bone.id;
    dab.mode = BrushMode::Replace;
    dab.value = 0.5;
    dab.centre = 0.5 * (painted.skeleton.joint(bone.head).position +
                        painted.skeleton.joint(bone.tail).position);
    dab.radius =
        (painted.skeleton.joint(bone.head).position - painted.skeleton.joint(bone.tail).position)
            .norm();
    dab.strength = 1.0;
    ASSERT_GT(paintWeights(painted, dab).changed.size(), 10u);

    Part unlocked = painted;
    EXPECT_GT(recomputeWeights(unlocked, {}), 10);
    ASSERT_TRUE(unlocked.validate().empty()) << unlocked.validate().front();
    for (int v = 0; v < unlocked.mesh.vertexCount(); ++v) {
        ASSERT_EQ(unlocked.weights.perVertex[v].size(), heat[v].size()) << v;
        for (std::size_t k = 0; k < heat[v].size(); ++k) {
            EXPECT_EQ(unlocked.weights.perVertex[v][k].first, heat[v][k].first);
            EXPECT_NEAR(unlocked.weights.perVertex[v][k].second, heat[v][k].second, 1e-12);
        }
    }

    Part locked = painted;
    const std::set<BoneId> lock{dab.bone};
    recomputeWeights(locked, lock);
    ASSERT_TRUE(locked.validate().empty()) << locked.validate().front();
    for (int v = 0; v < locked.mesh.vertexCount(); ++v) {
        ASSERT_EQ(weightOf(locked, v, dab.bone), weightOf(painted, v, dab.bone)) << v;
        ASSERT_NEAR(sumOf(locked, v), 1.0, 1e-9);
    }
    EXPECT_THROW(recomputeWeights(locked = Part(), {}), Error) << "no skeleton";
}

}  // namespace
}  // namespace rigmesh
