// Every rigged format, for the rigged parts of tube, y_branch and biped with
// the pose-demo clip, read back by our importer: same mesh, bones, weights
// and clip within tolerance.
#include <gtest/gtest.h>

#include <map>
#include <set>
#include <tuple>

#include "IoTestSupport.h"
#include "io/ExportFormat.h"
#include "io/InfluenceLimit.h"
#include "io/PoseDemoClip.h"
#include "io/SceneExport.h"
#include "io/SceneImport.h"
#include "pose/ForwardKinematics.h"
#include "pose/Skinning.h"

namespace rigmesh {
namespace {

using Param = std::tuple<std::string, std::string>;  // extension, sketch

class RoundTrip : public testing::TestWithParam<Param> {
  protected:
    void SetUp() override {
        const auto& [extension, sketch] = GetParam();
        part_ = &iotest::sharedPart(sketch);
        clip_ = poseDemoClip(*part_);
        path_ = (iotest::scratchFolder() / (sketch + extension)).string();
        ExportPart item;
        item.part = part_;
        ExportOptions options;
        options.maxInfluences = 0;  // all the format allows
        exportScene({item}, &clip_, path_, options);
        imported_ = importScene(path_);
        limit_ = effectiveInfluenceLimit(exportFormatFromPath(path_), 0);
        ASSERT_EQ(imported_.parts.size(), 1u);
        ASSERT_FALSE(imported_.needsRig) << imported_.message;
        back_ = &imported_.parts[0];
        size_ = iotest::meshSize(part_->mesh);
        // Imported bone index by our bone's name.
        for (std::size_t b = 0; b < back_->boneNames.size(); ++b)
            boneByName_[back_->boneNames[b]] = static_cast<int>(b);
    }
    std::string boneName(int bone) const {
        return part_->name + "_bone" + std::to_string(part_->skeleton.bones()[bone].id);
    }
    int importedBone(int bone) const {
        const auto it = boneByName_.find(boneName(bone));
        return it == boneByName_.end() ? -1 : it->second;
    }

    const Part* part_ = nullptr;
    Clip clip_;
    std::string path_;
    ImportedScene imported_;
    const ImportedPart* back_ = nullptr;
    int limit_ = 0;
    double size_ = 1;
    std::map<std::string, int> boneByName_;
};

TEST_P(RoundTrip, SameMeshUpToVertexOrder) {
    const TriMesh& a = part_->mesh;
    const TriMesh& b = back_->part.mesh;
    ASSERT_EQ(b.vertexCount(), a.vertexCount());
    EXPECT_EQ(b.faceCount(), a.faceCount());
    const std::vector<int> match = iotest::matchVertices(a.vertices, b.vertices);
    std::set<int> used;
    for (std::size_t v = 0; v < a.vertices.size(); ++v) {
        ASSERT_GE(match[v], 0);
        EXPECT_LE((a.vertices[v] - b.vertices[static_cast<std::size_t>(match[v])]).norm(),
                  1e-5 * size_);
        used.insert(match[v]);
    }
    EXPECT_EQ(used.size(), a.vertices.size());
    // The faces map onto faces (same triangles, same orientation).
    std::set<std::array<int, 3>> faces;
    for (const auto& f : b.faces)
        faces.insert({f[0], f[1], f[2]});
    int found = 0;
    for (const auto& f : a.faces) {
        const int x = match[static_cast<std::size_t>(f[0])],
                  y = match[static_cast<std::size_t>(f[1])],
                  z = match[static_cast<std::size_t>(f[2])];
        found +=
            faces.contains({x, y, z}) || faces.contains({y, z, x}) || faces.contains({z, x, y});
    }
    EXPECT_EQ(found, a.faceCount());
}

TEST_P(RoundTrip, SameBonesJointsAndParents) {
    const Skeleton& ours = part_->skeleton;
    const Skeleton& theirs = back_->part.skeleton;
    EXPECT_TRUE(theirs.validate().empty());
    ASSERT_EQ(theirs.boneCount(), ours.boneCount());
    EXPECT_EQ(theirs.jointCount(), ours.jointCount());
    EXPECT_EQ(std::set<std::string>(back_->boneNames.begin(), back_->boneNames.end()).size(),
              back_->boneNames.size());
    EXPECT_LE((theirs.joint(theirs.root()).position - ours.joint(ours.root()).position).norm(),
              1e-5 * size_);
    for (int b = 0; b < ours.boneCount(); ++b) {
        const int i = importedBone(b);
        ASSERT_GE(i, 0) << boneName(b);
        const Bone& a = ours.bones()[static_cast<std::size_t>(b)];
        const Bone& c = theirs.bones()[static_cast<std::size_t>(i)];
        EXPECT_LE((theirs.joint(c.head).position - ours.joint(a.head).position).norm(),
                  1e-5 * size_);
        EXPECT_LE((theirs.joint(c.tail).position - ours.joint(a.tail).position).norm(),
                  1e-5 * size_);
        const auto parentA = ours.parentBone(a.id);
        const auto parentC = theirs.parentBone(c.id);
        ASSERT_EQ(parentA.has_value(), parentC.has_value()) << boneName(b);
        if (parentA) {
            EXPECT_EQ(back_->boneNames[static_cast<std::size_t>(theirs.indexOfBone(*parentC))],
                      boneName(ours.indexOfBone(*parentA)));
        }
    }
}

TEST_P(RoundTrip, SameWeightsAfterTheFormatsCut) {
    // Bones by position in each skeleton, as importedBone() pairs them.
    const SkinWeights expected =
        limitInfluences(weightsByIndex(part_->skeleton, part_->weights), limit_);
    const SkinWeights imported = weightsByIndex(back_->part.skeleton, back_->part.weights);
    const std::vector<int> match =
        iotest::matchVertices(part_->mesh.vertices, back_->part.mesh.vertices);
    int worstCount = 0;
    double worst = 0;
    for (std::size_t v = 0; v < match.size(); ++v) {
        const auto& got = imported.perVertex[static_cast<std::size_t>(match[v])];
        worstCount = std::max(worstCount, static_cast<int>(got.size()));
        double sum = 0;
        std::map<int, double> byBone;
        for (const auto& [bone, w] : got) {
            sum += w;
            byBone[bone] = w;
        }
        EXPECT_NEAR(sum, 1.0, 1e-6);
        for (const auto& [bone, w] : expected.perVertex[v]) {
            const int i = importedBone(bone);
            worst = std::max(worst, std::abs(byBone[i] - w));
            byBone.erase(i);
        }
        for (const auto& [bone, w] : byBone)
            worst = std::max(worst, w);
    }
    EXPECT_LT(worst, 1e-5);
    if (limit_ > 0) {
        EXPECT_LE(worstCount, limit_);
    }
}

TEST_P(RoundTrip, SameClipKeysAndDeformation) {
    ASSERT_FALSE(imported_.parts[0].clips.empty());
    const std::vector<double> times = imported_.parts[0].clips.front().keyTimes();
    ASSERT_EQ(times.size(), 3u);
    for (int k = 0; k < 3; ++k)
        EXPECT_NEAR(times[static_cast<std::size_t>(k)], 0.5 * k, 1e-4);
    // Posed joints (through FK) and skinned vertices agree at every key.
    Part expectedPart = *part_;
    expectedPart.weights = limitInfluences(part_->weights, limit_);
    const std::vector<int> match =
        iotest::matchVertices(part_->mesh.vertices, back_->part.mesh.vertices);
    for (double t : times) {
        const Pose ours = clip_.evaluate(std::round(t * 2) / 2);
        const Pose theirs = imported_.parts[0].clips.front().evaluate(t);
        const PosedSkeleton a = forwardKinematics(part_->skeleton, ours);
        const PosedSkeleton b = forwardKinematics(back_->part.skeleton, theirs);
        for (int bone = 0; bone < part_->skeleton.boneCount(); ++bone) {
            const Bone& x = part_->skeleton.bones()[static_cast<std::size_t>(bone)];
            const Bone& y =
                back_->part.skeleton.bones()[static_cast<std::size_t>(importedBone(bone))];
            EXPECT_LE(
                (a.jointPositions[static_cast<std::size_t>(part_->skeleton.indexOfJoint(x.tail))] -
                 b.jointPositions[static_cast<std::size_t>(
                     back_->part.skeleton.indexOfJoint(y.tail))])
                    .norm(),
                1e-4 * size_)
                << "t=" << t << " " << boneName(bone);
        }
        const TriMesh posedA = posePart(expectedPart, ours).mesh;
        const TriMesh posedB = posePart(back_->part, theirs).mesh;
        double worst = 0;
        for (std::size_t v = 0; v < match.size(); ++v)
            worst = std::max(
                worst,
                (posedA.vertices[v] - posedB.vertices[static_cast<std::size_t>(match[v])]).norm());
        EXPECT_LT(worst, 1e-4 * size_) << "t=" << t;
    }
}

std::string paramName(const testing::TestParamInfo<Param>& info) {
    return std::get<0>(info.param).substr(1) + "_" + std::get<1>(info.param);
}

INSTANTIATE_TEST_SUITE_P(Formats, RoundTrip,
                         testing::Combine(testing::Values(".glb", ".gltf", ".fbx", ".dae"),
                                          testing::Values("tube", "y_branch", "biped")),
                         paramName);

}  // namespace
}  // namespace rigmesh
