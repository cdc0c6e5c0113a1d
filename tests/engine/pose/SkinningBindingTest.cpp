#include <random>
#include <stdexcept>

#include "PoseTestSupport.h"
#include "mesh/MeshPrimitives.h"
#include "mesh/VertexNormals.h"
#include "pose/SkinningBinding.h"

namespace rigmesh::posetest {
namespace {

const SkinningMethod kMethods[] = {SkinningMethod::LinearBlend, SkinningMethod::DualQuaternion};

SkinningTransforms transformsOf(const Part& part, const Pose& pose) {
    return SkinningTransforms(part.skeleton, forwardKinematics(part.skeleton, pose).boneTransforms);
}

class SkinningBindingOnParts : public ::testing::TestWithParam<std::string> {};

// The binding holds the same influences in the same order and runs the same
// kernels: the same bits as the weight lists, whatever the thread count, and
// buffers reused from an earlier pose change nothing.
TEST_P(SkinningBindingOnParts, GivesTheWeightListsResultBitForBit) {
    const Part& part = sharedPart(GetParam());
    const std::vector<Vec3> normals = vertexNormals(part.mesh);
    const SkinningBinding binding(part.weights.perVertex);
    ASSERT_EQ(binding.vertexCount(), part.mesh.vertexCount());
    std::mt19937 rng(29);
    SkinnedVertices reused;
    for (int k = 0; k < 3; ++k) {
        const SkinningTransforms transforms =
            transformsOf(part, randomPose(part.skeleton, rng, 1.5, 1.0));
        for (SkinningMethod method : kMethods) {
            const SkinnedVertices lists = skinVertices(
                part.mesh.vertices, normals, part.weights.perVertex, transforms, {method, 2});
            for (int threads : {1, 2, 7}) {
                skinVertices(part.mesh.vertices, normals, binding, transforms, {method, threads},
                             reused);
                EXPECT_EQ(reused.positions, lists.positions);
                EXPECT_EQ(reused.normals, lists.normals);
            }
        }
    }
    // Without normals the reused buffer's normals go.
    skinVertices(part.mesh.vertices, {}, binding, transformsOf(part, restPose(part.skeleton)), {},
                 reused);
    EXPECT_EQ(reused.positions, part.mesh.vertices);
    EXPECT_TRUE(reused.normals.empty());
}

// The blend, divided by its norm, is applied as a rigid transform: checked
// against the product of Eigen's quaternions, 2 d conj(q) for the
// translation, and q's rotation of the point and the normal.
TEST_P(SkinningBindingOnParts, DualQuaternionsAreTheNormalisedBlendsTransform) {
    const Part& part = sharedPart(GetParam());
    const std::vector<Vec3> normals = vertexNormals(part.mesh);
    std::mt19937 rng(31);
    const Pose pose = randomPose(part.skeleton, rng, M_PI, 1.0);
    const std::vector<RigidTransform> bones = forwardKinematics(part.skeleton, pose).boneTransforms;
    const SkinnedVertices skinned =
        skinVertices(part.mesh.vertices, normals, part.weights.perVertex,
                     SkinningTransforms(part.skeleton, bones), {SkinningMethod::DualQuaternion});
    const double size = boundingBoxDiagonal(part.mesh.vertices);
    for (int v = 0; v < part.mesh.vertexCount(); ++v) {
        const auto& list = part.weights.perVertex[v];
        const RigidTransform& lead = bones[part.skeleton.indexOfBone(leadingBone(list))];
        Eigen::Vector4d real = Eigen::Vector4d::Zero(), dual = Eigen::Vector4d::Zero();
        for (const auto& [bone, weight] : list) {
            const RigidTransform& t = bones[part.skeleton.indexOfBone(bone)];
            const Eigen::Quaterniond q = t.rotation.normalized();
            const Eigen::Quaterniond d =
                Eigen::Quaterniond(0, t.translation.x(), t.translation.y(), t.translation.z()) * q;
            const double w =
                q.coeffs().dot(lead.rotation.normalized().coeffs()) < 0 ? -weight : weight;
            real += w * q.coeffs();
            dual += 0.5 * w * d.coeffs();
        }
        const double norm = real.norm();
        const Eigen::Quaterniond q(Eigen::Vector4d(real / norm));
        const Eigen::Quaterniond d(Eigen::Vector4d(dual / norm));
        // The translation: the vector part of 2 d conj(q).
        const Vec3 translation = 2.0 * (d * q.conjugate()).vec();
        ASSERT_LT((skinned.positions[v] - (q * part.mesh.vertices[v] + translation)).norm(),
                  1e-12 * size)
            << v;
        ASSERT_LT((skinned.normals[v] - q * normals[v]).norm(), 1e-12) << v;
    }
}

INSTANTIATE_TEST_SUITE_P(SharedSketches, SkinningBindingOnParts,
                         ::testing::Values("tube", "y_branch", "biped"),
                         testsupport::sketchTestName);

// Ids far beyond the bone count (a hand-edited file) number compactly in the
// binding: the same skinning as the lists.
TEST(SkinningBinding, BoneIdsFarBeyondTheBoneCountSkinAsTheLists) {
    const TriMesh tube = makeCylinderTube(8, 12, 0.3, 2.0);
    Skeleton chain;
    const JointId root = chain.addJoint(Vec3(0, 0, -1));
    const JointId middle = chain.addJoint(Vec3(0, 0, 0));
    const JointId tip = chain.addJoint(Vec3(0, 0, 1));
    std::vector<Bone> bones = {Bone{7, root, middle}, Bone{1000000, middle, tip}};
    const Skeleton far = Skeleton::restore(chain.joints(), bones, root);
    WeightsById weights;
    for (const Vec3& v : tube.vertices) {
        const double w = std::clamp(v.z() / 2.0 + 0.5, 0.0, 1.0);
        weights.push_back(w <= 0
                              ? std::vector<std::pair<BoneId, double>>{{7, 1.0}}
                              : std::vector<std::pair<BoneId, double>>{{7, 1 - w}, {1000000, w}});
    }
    const SkinningBinding binding(weights);
    EXPECT_EQ(binding.bones(), (std::vector<BoneId>{7, 1000000}));
    const SkinningTransforms transforms(
        far,
        {RigidTransform{Eigen::Quaterniond(Eigen::AngleAxisd(0.3, Vec3::UnitX())), Vec3(0, 0, 0.1)},
         RigidTransform{Eigen::Quaterniond(Eigen::AngleAxisd(2.5, Vec3::UnitZ())),
                        Vec3(0.2, 0, 0)}});
    for (SkinningMethod method : kMethods) {
        SkinnedVertices bound;
        skinVertices(tube.vertices, {}, binding, transforms, {method, 2}, bound);
        EXPECT_EQ(bound.positions,
                  skinVertices(tube.vertices, {}, weights, transforms, {method, 2}).positions);
    }
}

TEST(SkinningBinding, MismatchedInputIsAProgrammingError) {
    const Part& part = sharedPart("tube");
    const SkinningTransforms transforms = transformsOf(part, Pose{});
    SkinnedVertices out;
    WeightsById tooFew = part.weights.perVertex;
    tooFew.pop_back();
    EXPECT_THROW(skinVertices(part.mesh.vertices, {}, SkinningBinding(tooFew), transforms, {}, out),
                 std::logic_error);
    WeightsById badBone = part.weights.perVertex;
    badBone[0] = {{99, 1.0}};
    EXPECT_THROW(
        skinVertices(part.mesh.vertices, {}, SkinningBinding(badBone), transforms, {}, out),
        std::logic_error);
    const SkinningBinding binding(part.weights.perVertex);
    EXPECT_THROW(skinVertices(part.mesh.vertices, {Vec3::UnitX()}, binding, transforms, {}, out),
                 std::logic_error);
    EXPECT_THROW(skinVertices(part.mesh.vertices, {}, binding, transforms,
                              {SkinningMethod::LinearBlend, 0}, out),
                 std::logic_error);
}

}  // namespace
}  // namespace rigmesh::posetest
