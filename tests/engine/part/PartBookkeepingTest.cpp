// The per-vertex bookkeeping a Part carries for later local updates: origins,
// mirror, closest bones known from construction (paper 2.4), bone segments.
#include <gtest/gtest.h>

#include <algorithm>
#include <iostream>
#include <limits>
#include <string>
#include <vector>

#include "PartTestSupport.h"

namespace rigmesh {
namespace {

// A construction-known closest bone counts as right when it is among the
// closest visible bones or at most this much (relatively) farther than them.
constexpr double kKnownBoneSlack = 0.05;

class PartBookkeeping : public ::testing::TestWithParam<std::string> {
  protected:
    const SketchToPartResult& result() const { return parttest::sharedPart(GetParam()); }
};

TEST_P(PartBookkeeping, PerVertexListsMatchTheVertexCount) {
    const Part& part = result().part;
    const std::size_t count = part.mesh.vertices.size();
    EXPECT_EQ(part.knownClosestBones.size(), count);
    EXPECT_EQ(part.origins.size(), count);
    EXPECT_EQ(part.mirror.size(), count);
    EXPECT_EQ(part.weights.perVertex.size(), count);
}

// The paper's shortcut (2.4): cylindrical vertices know their closest bone
// from construction. Near a joint where a neighbouring bone is closer the
// engine leaves the vertex to the visibility test instead; that must stay
// the exception.
TEST_P(PartBookkeeping, CylindricalVerticesKnowTheirClosestBones) {
    constexpr double kMinimumKnownFraction = 0.8;
    const Part& part = result().part;
    const auto& cylinderBones = result().skeleton.cylinderBones;
    ASSERT_EQ(part.knownClosestBones.size(), part.origins.size());
    int missing = 0, cylindrical = 0;
    for (std::size_t v = 0; v < part.origins.size(); ++v) {
        const VertexOrigin& origin = part.origins[v];
        if (origin.kind != RegionKind::Cylindrical)
            continue;
        ASSERT_GE(origin.region, 0);
        ASSERT_LT(origin.region, static_cast<int>(cylinderBones.size()));
        if (cylinderBones[origin.region].empty())
            continue;
        ++cylindrical;
        if (part.knownClosestBones[v].empty())
            ++missing;
        for (const auto& [bone, distance] : part.knownClosestBones[v]) {
            EXPECT_TRUE(part.skeleton.hasBone(bone)) << bone;
            EXPECT_GE(distance, 0.0);
        }
    }
    const double known = 1.0 - static_cast<double>(missing) / std::max(cylindrical, 1);
    RecordProperty("knownFraction", std::to_string(known));
    EXPECT_GE(known, kMinimumKnownFraction)
        << missing << " of " << cylindrical << " cylindrical vertices left to the visibility test";
}

TEST_P(PartBookkeeping, BoneSegmentsFollowTheSkeletonBones) {
    const Part& part = result().part;
    const auto segments = part.boneSegments();
    ASSERT_EQ(static_cast<int>(segments.size()), part.skeleton.boneCount());
    for (std::size_t i = 0; i < segments.size(); ++i) {
        const Bone& bone = part.skeleton.bones()[i];
        EXPECT_EQ(part.skeleton.indexOfBone(bone.id), static_cast<int>(i));
        EXPECT_EQ(segments[i].head, part.skeleton.joint(bone.head).position);
        EXPECT_EQ(segments[i].tail, part.skeleton.joint(bone.tail).position);
    }
}

// Paper 2.4: the closest visible bones of cylinder vertices are known from
// construction; they must agree with the ones visibility testing finds.
TEST_P(PartBookkeeping, KnownClosestBonesAreTheClosestVisibleBones) {
    const Part& part = result().part;
    const std::vector<BoneSegment> bones = part.boneSegments();
    const ClosestBones& visible = parttest::sharedClosestVisibleBones(GetParam());
    ASSERT_EQ(visible.size(), part.knownClosestBones.size());
    int known = 0;
    int wrong = 0;
    int firstWrong = -1;
    for (std::size_t v = 0; v < visible.size(); ++v) {
        if (part.knownClosestBones[v].empty())
            continue;
        ++known;
        double nearest = std::numeric_limits<double>::infinity();
        for (const auto& [bone, distance] : visible[v])
            nearest = std::min(nearest, distance);
        bool right = false;
        for (const auto& [bone, distance] : part.knownClosestBones[v])
            right = right || pointSegmentDistance(part.mesh.vertices[v],
                                                  bones[part.skeleton.indexOfBone(bone)]) <=
                                 nearest * (1.0 + kKnownBoneSlack);
        if (!right) {
            ++wrong;
            if (firstWrong < 0)
                firstWrong = static_cast<int>(v);
        }
    }
    std::cout << "[ measured ] " << GetParam() << " known closest bones farther than the closest "
              << "visible one: " << wrong << "/" << known << " (first: vertex " << firstWrong
              << ")\n";
    EXPECT_EQ(wrong, 0) << "first wrong vertex " << firstWrong;
}

// The construction shortcut gives the bones the visibility test
// gives, ties included: a section's bone stops at the planes through its end
// joints, and neighbours within the tie tolerance share the vertex. Measured:
// every known list equals the tested one on every sketch but biped (7 of
// 1554 differ) and open_gap (21 of 2391), where the test picks another bone
// no more than 5% closer (the check above).
TEST_P(PartBookkeeping, KnownClosestBonesListTheSameBonesAsTheVisibilityTest) {
    const Part& part = result().part;
    // With the solver's own tie tolerance, which the construction uses too.
    const ClosestBones& visible =
        parttest::sharedClosestVisibleBones(GetParam(), BoneHeatOptions{}.tieTolerance);
    // The visibility test names bones by position; the part keeps ids.
    const ClosestBones knownByPosition = closestByIndex(part.skeleton, part.knownClosestBones);
    int known = 0;
    int different = 0;
    for (std::size_t v = 0; v < visible.size(); ++v) {
        if (knownByPosition[v].empty())
            continue;
        ++known;
        auto bonesOf = [](const std::vector<std::pair<int, double>>& list) {
            std::vector<int> bones;
            for (const auto& entry : list)
                bones.push_back(entry.first);
            std::sort(bones.begin(), bones.end());
            return bones;
        };
        if (bonesOf(knownByPosition[v]) != bonesOf(visible[v]))
            ++different;
    }
    std::cout << "[ measured ] " << GetParam()
              << " known closest bones unlike the tested ones: " << different << "/" << known
              << "\n";
    ASSERT_GT(known, 0);
    EXPECT_LE(different, known / 100) << "more than 1% of the known lists differ";
}

INSTANTIATE_TEST_SUITE_P(SharedSketches, PartBookkeeping,
                         ::testing::ValuesIn(parttest::goodSketches()),
                         testsupport::sketchTestName);

}  // namespace
}  // namespace rigmesh
