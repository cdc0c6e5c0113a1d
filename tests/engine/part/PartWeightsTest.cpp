// Bone heat skin weights of every shared sketch (paper 2.4): a partition of
// unity on every vertex, no failed bone, and weights that follow the closest
// visible bone.
#include <gtest/gtest.h>

#include <algorithm>
#include <iostream>
#include <limits>
#include <string>
#include <vector>

#include "PartTestSupport.h"

namespace rigmesh {
namespace {

constexpr double kSumTolerance = 1e-9;
// The dominant bone also counts as right when it is this much farther
// (relatively) than the closest visible bone: at a joint two bones are
// nearly equally close and heat blends them.
constexpr double kDominantDistanceSlack = 0.05;
constexpr double kMinimumDominantFraction = 0.95;

class PartWeights : public ::testing::TestWithParam<std::string> {
  protected:
    const Part& part() const { return parttest::sharedPart(GetParam()).part; }
};

TEST_P(PartWeights, EveryVertexHasNonNegativeWeightsSummingToOne) {
    const Part& p = part();
    ASSERT_EQ(p.weights.perVertex.size(), p.mesh.vertices.size());
    int unweighted = 0;
    for (const auto& weights : p.weights.perVertex) {
        if (weights.empty()) {
            ++unweighted;
            continue;
        }
        double sum = 0.0;
        for (const auto& [bone, weight] : weights) {
            EXPECT_TRUE(p.skeleton.hasBone(bone)) << bone;
            EXPECT_GE(weight, 0.0);
            sum += weight;
        }
        EXPECT_NEAR(sum, 1.0, kSumTolerance);
    }
    EXPECT_EQ(unweighted, 0) << "vertices without any weight";
}

TEST_P(PartWeights, NoBoneFellBack) {
    EXPECT_TRUE(part().weights.failedBones.empty()) << englishText(part().weights.warnings);
    EXPECT_TRUE(part().weights.warnings.empty()) << englishText(part().weights.warnings);
}

TEST_P(PartWeights, DominantBoneIsAClosestVisibleBone) {
    const Part& p = part();
    const std::vector<BoneSegment> bones = p.boneSegments();
    const ClosestBones& closest = parttest::sharedClosestVisibleBones(GetParam());
    ASSERT_EQ(closest.size(), p.mesh.vertices.size());

    const SkinWeights weights = parttest::weightsByPosition(p);
    int inList = 0;
    int withinSlack = 0;
    for (std::size_t v = 0; v < closest.size(); ++v) {
        const int dominant = parttest::dominantBone(weights.perVertex[v]);
        double nearest = std::numeric_limits<double>::infinity();
        bool listed = false;
        for (const auto& [bone, distance] : closest[v]) {
            nearest = std::min(nearest, distance);
            listed = listed || bone == dominant;
        }
        if (listed) {
            ++inList;
            ++withinSlack;
        } else if (dominant >= 0 && pointSegmentDistance(p.mesh.vertices[v], bones[dominant]) <=
                                        nearest * (1.0 + kDominantDistanceSlack)) {
            ++withinSlack;
        }
    }
    const double count = static_cast<double>(closest.size());
    const double strictFraction = inList / count;
    const double fraction = withinSlack / count;
    RecordProperty("dominantAmongClosestVisible", std::to_string(strictFraction));
    RecordProperty("dominantWithinSlack", std::to_string(fraction));
    std::cout << "[ measured ] " << GetParam()
              << " dominant bone among closest visible: " << strictFraction << ", within "
              << kDominantDistanceSlack << ": " << fraction << "\n";
    EXPECT_GE(fraction, kMinimumDominantFraction);
}

INSTANTIATE_TEST_SUITE_P(SharedSketches, PartWeights, ::testing::ValuesIn(parttest::goodSketches()),
                         testsupport::sketchTestName);

}  // namespace
}  // namespace rigmesh
