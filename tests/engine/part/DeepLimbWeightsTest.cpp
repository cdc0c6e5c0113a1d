// Deep along a limb, far from any joint, a vertex belongs to its bone alone:
// heat from the other bones has died out there (paper 2.4).
#include <gtest/gtest.h>

#include <iostream>
#include <limits>
#include <string>
#include <vector>

#include "PartTestSupport.h"

namespace rigmesh {
namespace {

// The middle of a bone: projection parameters in this range.
constexpr double kMiddleStart = 0.35;
constexpr double kMiddleEnd = 0.65;
constexpr double kOwnWeight = 0.95;
constexpr double kMinimumFraction = 0.9;

// A limb bone: it ends in a leaf, or neither joint branches.
bool isLimbBone(const Skeleton& skeleton, const Bone& bone) {
    return skeleton.childrenOf(bone.tail).empty() ||
           (skeleton.degree(bone.head) <= 2 && skeleton.degree(bone.tail) <= 2);
}

class DeepLimbWeights : public ::testing::TestWithParam<std::string> {};

TEST_P(DeepLimbWeights, MiddleOfALimbBoneBelongsToThatBone) {
    const Part& part = parttest::sharedPart(GetParam()).part;
    const std::vector<BoneSegment> segments = part.boneSegments();
    const SkinWeights weights = parttest::weightsByPosition(part);
    int considered = 0;
    int owned = 0;
    for (std::size_t v = 0; v < part.mesh.vertices.size(); ++v) {
        const Vec3& position = part.mesh.vertices[v];
        int closest = -1;
        double nearest = std::numeric_limits<double>::infinity();
        for (std::size_t b = 0; b < segments.size(); ++b) {
            const double d = pointSegmentDistance(position, segments[b]);
            if (d < nearest) {
                nearest = d;
                closest = static_cast<int>(b);
            }
        }
        if (closest < 0 || !isLimbBone(part.skeleton, part.skeleton.bones()[closest]))
            continue;
        const double t = closestSegmentParameter(position, segments[closest]);
        if (t < kMiddleStart || t > kMiddleEnd)
            continue;
        ++considered;
        const std::vector<double> dense =
            parttest::denseWeights(weights.perVertex[v], part.skeleton.boneCount());
        if (dense[closest] >= kOwnWeight)
            ++owned;
    }
    ASSERT_GT(considered, 0) << "no vertex in the middle of a limb bone";
    const double fraction = static_cast<double>(owned) / considered;
    RecordProperty("deepLimbFraction", std::to_string(fraction));
    std::cout << "[ measured ] " << GetParam()
              << " deep-limb vertices owned by their bone: " << owned << "/" << considered << " = "
              << fraction << "\n";
    EXPECT_GE(fraction, kMinimumFraction);
}

INSTANTIATE_TEST_SUITE_P(LimbSketches, DeepLimbWeights,
                         ::testing::Values("tube", "y_branch", "star"),
                         testsupport::sketchTestName);

}  // namespace
}  // namespace rigmesh
