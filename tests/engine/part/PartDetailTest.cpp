// Detail levels for export: Loop subdivision and quadric
// decimation carry the skin weights and leave the rig as it is.
#include <gtest/gtest.h>

#include <map>
#include <string>

#include "PartTestSupport.h"
#include "base/Error.h"
#include "mesh/MeshChecks.h"
#include "part/PartDetail.h"

namespace rigmesh {
namespace {

void expectSameSkeleton(const Skeleton& a, const Skeleton& b) {
    ASSERT_EQ(a.jointCount(), b.jointCount());
    ASSERT_EQ(a.boneCount(), b.boneCount());
    for (std::size_t j = 0; j < a.joints().size(); ++j)
        EXPECT_EQ(a.joints()[j].position, b.joints()[j].position);
    EXPECT_EQ(a.root(), b.root());
}

class PartDetail : public testing::TestWithParam<std::string> {};

TEST_P(PartDetail, SubdividingMakesFourFacesOfEachAndCarriesTheWeights) {
    const Part& part = parttest::sharedPart(GetParam()).part;
    const Part finer = subdividedPart(part, 1);
    EXPECT_TRUE(finer.validate().empty()) << finer.validate().front();
    EXPECT_EQ(finer.mesh.faceCount(), 4 * part.mesh.faceCount());
    // V' = V + E, E = 3F/2 on a closed surface.
    EXPECT_EQ(finer.mesh.vertexCount(), part.mesh.vertexCount() + 3 * part.mesh.faceCount() / 2);
    const MeshReport report = analyseMesh(finer.mesh, false);
    EXPECT_TRUE(report.isWatertightGenus0());
    EXPECT_TRUE(report.isOutwardOriented());
    expectSameSkeleton(finer.skeleton, part.skeleton);
    ASSERT_EQ(finer.weights.perVertex.size(), finer.mesh.vertices.size());
    // A vertex's dominant bone was dominant at one of the vertices it came
    // from: weights are carried, not invented.
    std::map<BoneId, int> dominantCounts;
    for (const auto& list : finer.weights.perVertex) {
        ASSERT_FALSE(list.empty());
        BoneId best = list.front().first;
        double most = 0;
        for (const auto& [bone, w] : list)
            if (w > most) {
                most = w;
                best = bone;
            }
        ++dominantCounts[best];
    }
    EXPECT_EQ(static_cast<int>(dominantCounts.size()), part.skeleton.boneCount())
        << "every bone still dominates somewhere";
    // Loop's limit surface is inside the control mesh: the volume shrinks a
    // little, never grows.
    const double before = analyseMesh(part.mesh, false).volume;
    EXPECT_LT(report.volume, before);
    EXPECT_GT(report.volume, 0.9 * before);
}

TEST_P(PartDetail, DecimatingKeepsOriginalVerticesWithTheirOwnWeights) {
    const Part& part = parttest::sharedPart(GetParam()).part;
    const int target = part.mesh.faceCount() / 4;
    const Part coarser = decimatedPart(part, target);
    EXPECT_TRUE(coarser.validate().empty()) << coarser.validate().front();
    EXPECT_LE(coarser.mesh.faceCount(), target);
    EXPECT_GE(coarser.mesh.faceCount(), target - 4);
    const MeshReport report = analyseMesh(coarser.mesh, false);
    EXPECT_TRUE(report.isWatertightGenus0());
    EXPECT_TRUE(report.isOutwardOriented());
    expectSameSkeleton(coarser.skeleton, part.skeleton);
    std::map<std::array<double, 3>, int> original;
    for (int v = 0; v < part.mesh.vertexCount(); ++v) {
        const Vec3& p = part.mesh.vertices[static_cast<std::size_t>(v)];
        original[{p.x(), p.y(), p.z()}] = v;
    }
    for (int v = 0; v < coarser.mesh.vertexCount(); ++v) {
        const Vec3& p = coarser.mesh.vertices[static_cast<std::size_t>(v)];
        const auto source = original.find({p.x(), p.y(), p.z()});
        ASSERT_NE(source, original.end()) << "vertex " << v << " is not an original vertex";
        EXPECT_EQ(coarser.weights.perVertex[static_cast<std::size_t>(v)],
                  part.weights.perVertex[static_cast<std::size_t>(source->second)]);
    }
}

INSTANTIATE_TEST_SUITE_P(SharedSketches, PartDetail,
                         testing::Values("tube", "y_branch", "biped", "star"));

TEST(PartDetailLimits, OutOfRangeRequestsAreRefusedWithTheReason) {
    const Part& part = parttest::sharedPart("tube").part;
    EXPECT_THROW(subdividedPart(part, 5), Error);
    EXPECT_THROW(subdividedPart(part, -1), Error);
    EXPECT_THROW(decimatedPart(part, 3), Error);
    EXPECT_EQ(decimatedPart(part, part.mesh.faceCount()).mesh.faceCount(), part.mesh.faceCount());
    EXPECT_EQ(subdividedPart(part, 0).mesh.vertexCount(), part.mesh.vertexCount());
}

}  // namespace
}  // namespace rigmesh
