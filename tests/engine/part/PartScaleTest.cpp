// Scale independence of the rig: a scaled stroke gives the same skeleton,
// scaled, and the same skin weights (bone heat is scale invariant, and the
// DP/CDP threshold is relative to the cylinder's radius).
#include <gtest/gtest.h>

#include <algorithm>
#include <string>
#include <vector>

#include "PartTestSupport.h"

namespace rigmesh {
namespace {

constexpr double kPositionTolerance = 1e-6;  // relative to the bounding-box diagonal
constexpr double kWeightTolerance = 1e-6;    // absolute, per vertex and bone

struct ScaleCase {
    std::string sketch;
    double scale;
};

std::vector<ScaleCase> scaleCases() {
    std::vector<ScaleCase> cases;
    for (const std::string& sketch : parttest::goodSketches())
        for (double scale : {1e-3, 1e3})
            cases.push_back({sketch, scale});
    return cases;
}

std::string scaleCaseName(const ::testing::TestParamInfo<ScaleCase>& info) {
    return info.param.sketch + (info.param.scale < 1.0 ? "_small" : "_large");
}

class PartScale : public ::testing::TestWithParam<ScaleCase> {};

TEST_P(PartScale, ScaledStrokeGivesTheSameSkeletonScaled) {
    const auto& [sketch, scale] = GetParam();
    const Part& reference = parttest::sharedPart(sketch).part;
    const Part& scaled = parttest::sharedPart(sketch, scale).part;
    ASSERT_EQ(scaled.skeleton.jointCount(), reference.skeleton.jointCount());
    ASSERT_EQ(scaled.skeleton.boneCount(), reference.skeleton.boneCount());
    const double tolerance = kPositionTolerance * parttest::boundingBoxDiagonal(reference.mesh);
    double worst = 0.0;
    for (int j = 0; j < reference.skeleton.jointCount(); ++j) {
        const Vec3& a = reference.skeleton.joints()[j].position;
        const Vec3& b = scaled.skeleton.joints()[j].position;
        worst = std::max(worst, (b / scale - a).norm());
    }
    EXPECT_LE(worst, tolerance);
    for (int b = 0; b < reference.skeleton.boneCount(); ++b) {
        const Bone& r = reference.skeleton.bones()[b];
        const Bone& s = scaled.skeleton.bones()[b];
        EXPECT_EQ(reference.skeleton.indexOfJoint(r.head), scaled.skeleton.indexOfJoint(s.head));
        EXPECT_EQ(reference.skeleton.indexOfJoint(r.tail), scaled.skeleton.indexOfJoint(s.tail));
    }
    EXPECT_EQ(reference.skeleton.indexOfJoint(reference.skeleton.root()),
              scaled.skeleton.indexOfJoint(scaled.skeleton.root()));
}

TEST_P(PartScale, ScaledStrokeGivesTheSameWeights) {
    const auto& [sketch, scale] = GetParam();
    const Part& reference = parttest::sharedPart(sketch).part;
    const Part& scaled = parttest::sharedPart(sketch, scale).part;
    ASSERT_EQ(scaled.mesh.vertexCount(), reference.mesh.vertexCount());
    ASSERT_EQ(scaled.skeleton.boneCount(), reference.skeleton.boneCount());
    const int boneCount = reference.skeleton.boneCount();
    double worst = 0.0;
    const SkinWeights referenceWeights = parttest::weightsByPosition(reference);
    const SkinWeights scaledWeights = parttest::weightsByPosition(scaled);
    for (int v = 0; v < reference.mesh.vertexCount(); ++v) {
        const auto a = parttest::denseWeights(referenceWeights.perVertex[v], boneCount);
        const auto b = parttest::denseWeights(scaledWeights.perVertex[v], boneCount);
        for (int i = 0; i < boneCount; ++i)
            worst = std::max(worst, std::abs(a[i] - b[i]));
    }
    EXPECT_LE(worst, kWeightTolerance);
}

INSTANTIATE_TEST_SUITE_P(SharedSketches, PartScale, ::testing::ValuesIn(scaleCases()),
                         scaleCaseName);

}  // namespace
}  // namespace rigmesh
