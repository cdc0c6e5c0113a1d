#include <cstring>
#include <random>
#include <stdexcept>

#include "PoseTestSupport.h"
#include "mesh/MeshPrimitives.h"
#include "mesh/VertexNormals.h"
#include "pose/Skinning.h"

namespace rigmesh::posetest {
namespace {

// A rigid pose must move vertices rigidly to this fraction of the mesh size.
constexpr double kRigidRelative = 1e-12;
constexpr double kUnitNormalTolerance = 1e-12;
constexpr double kTwistAngle = M_PI / 2;

const SkinningMethod kMethods[] = {SkinningMethod::LinearBlend, SkinningMethod::DualQuaternion};

SkinnedVertices skinPart(const Part& part, const Pose& pose, SkinningMethod method,
                         int threads = 2) {
    const PosedSkeleton posed = forwardKinematics(part.skeleton, pose);
    return skinVertices(part.mesh.vertices, vertexNormals(part.mesh), part.weights.perVertex,
                        SkinningTransforms(part.skeleton, posed.boneTransforms), {method, threads});
}

class SkinningOnParts : public ::testing::TestWithParam<std::string> {};

TEST_P(SkinningOnParts, RestPoseReturnsTheRestMeshBitExactly) {
    const Part& part = sharedPart(GetParam());
    const std::vector<Vec3> normals = vertexNormals(part.mesh);
    for (SkinningMethod method : kMethods) {
        const SkinnedVertices skinned = skinPart(part, restPose(part.skeleton), method);
        EXPECT_EQ(skinned.positions, part.mesh.vertices);
        EXPECT_EQ(skinned.normals, normals);
    }
}

TEST_P(SkinningOnParts, RigidPoseMovesTheMeshRigidly) {
    const Part& part = sharedPart(GetParam());
    const double size = boundingBoxDiagonal(part.mesh.vertices);
    Pose pose;
    const Eigen::Quaterniond q(Eigen::AngleAxisd(2.0, Vec3(1, 2, 3).normalized()));
    pose.setRotation(part.skeleton.root(), q);
    pose.rootTranslation = Vec3(1, -2, 0.5);
    const RigidTransform expected =
        RigidTransform{Eigen::Quaterniond::Identity(), pose.rootTranslation} *
        RigidTransform::rotationAbout(q, part.skeleton.joint(part.skeleton.root()).position);
    const std::vector<Vec3> normals = vertexNormals(part.mesh);
    for (SkinningMethod method : kMethods) {
        const SkinnedVertices skinned = skinPart(part, pose, method);
        for (int v = 0; v < part.mesh.vertexCount(); ++v) {
            ASSERT_LT((skinned.positions[v] - expected.apply(part.mesh.vertices[v])).norm(),
                      kRigidRelative * size);
            ASSERT_LT((skinned.normals[v] - q * normals[v]).norm(), kUnitNormalTolerance);
        }
    }
}

TEST_P(SkinningOnParts, RandomPosesNeverGiveNaNAndNormalsStayUnit) {
    const Part& part = sharedPart(GetParam());
    std::mt19937 rng(17);
    for (int k = 0; k < 10; ++k) {
        const Pose pose = randomPose(part.skeleton, rng, M_PI, 1.0);
        for (SkinningMethod method : kMethods) {
            const SkinnedVertices skinned = skinPart(part, pose, method);
            for (int v = 0; v < part.mesh.vertexCount(); ++v) {
                ASSERT_TRUE(skinned.positions[v].allFinite());
                ASSERT_TRUE(skinned.normals[v].allFinite());
                // LBS's blended matrix can be singular (opposite rotations):
                // the normal then falls back to the rest one, still unit.
                ASSERT_NEAR(skinned.normals[v].norm(), 1.0, 1e-9);
            }
        }
    }
}

TEST_P(SkinningOnParts, OneAndTwoThreadsGiveIdenticalOutput) {
    const Part& part = sharedPart(GetParam());
    std::mt19937 rng(19);
    const Pose pose = randomPose(part.skeleton, rng, 1.5, 1.0);
    for (SkinningMethod method : kMethods) {
        const SkinnedVertices one = skinPart(part, pose, method, 1);
        const SkinnedVertices two = skinPart(part, pose, method, 2);
        const SkinnedVertices seven = skinPart(part, pose, method, 7);
        EXPECT_EQ(one.positions, two.positions);
        EXPECT_EQ(one.normals, two.normals);
        EXPECT_EQ(one.positions, seven.positions);
    }
}

// Saved documents must deform to the same bits as they always did
// (tests/model/LegacyDocumentTest.cpp compares a posed OBJ byte for byte), so
// skinning does the arithmetic of the plain per-vertex Eigen formulation
// below, operation for operation, however it is laid out and vectorised
// (pose/SkinningKernel.h). Large random rotations, so that some bones' quaternions
// are flipped into the dominant bone's hemisphere.
struct PlainSkinning {
    const Skeleton& skeleton;
    const std::vector<RigidTransform>& bones;

    Eigen::Quaterniond rotation(BoneId bone) const {
        return bones[skeleton.indexOfBone(bone)].rotation.normalized();
    }
    Vec3 translation(BoneId bone) const { return bones[skeleton.indexOfBone(bone)].translation; }
    bool atRest(const std::vector<std::pair<BoneId, double>>& list) const {
        for (const auto& [bone, weight] : list)
            if (!bones[skeleton.indexOfBone(bone)].isIdentity())
                return false;
        return true;
    }
    static Vec3 times(const Eigen::Matrix3d& m, const Vec3& x) {
        return Vec3(m(0, 0) * x[0] + m(0, 1) * x[1] + m(0, 2) * x[2],
                    m(1, 0) * x[0] + m(1, 1) * x[1] + m(1, 2) * x[2],
                    m(2, 0) * x[0] + m(2, 1) * x[1] + m(2, 2) * x[2]);
    }
    static Vec3 normalisedOr(const Vec3& v, const Vec3& fallback) {
        const double length = std::sqrt(v[0] * v[0] + v[1] * v[1] + v[2] * v[2]);
        return length > 0 ? Vec3(v[0] / length, v[1] / length, v[2] / length) : fallback;
    }

    void linearBlend(const std::vector<std::pair<BoneId, double>>& list, const Vec3& x,
                     const Vec3& n, Vec3& xOut, Vec3& nOut) const {
        Eigen::Matrix3d m = Eigen::Matrix3d::Zero();
        Vec3 t = Vec3::Zero();
        for (const auto& [bone, weight] : list) {
            m.noalias() += weight * rotation(bone).toRotationMatrix();
            t.noalias() += weight * translation(bone);
        }
        xOut = times(m, x) + t;
        nOut = normalisedOr(times(m, n), n);
    }

    void dualQuaternions(const std::vector<std::pair<BoneId, double>>& list, const Vec3& x,
                         const Vec3& n, Vec3& xOut, Vec3& nOut) const {
        const Eigen::Vector4d pivot = rotation(leadingBone(list)).coeffs();
        Eigen::Vector4d real = Eigen::Vector4d::Zero();
        Eigen::Vector4d dual = Eigen::Vector4d::Zero();
        for (const auto& [bone, weight] : list) {
            const Eigen::Quaterniond q = rotation(bone);
            const Vec3 tr = translation(bone);
            const Vec3 dv = 0.5 * (q.w() * tr + tr.cross(q.vec()));
            const Eigen::Vector4d d(dv.x(), dv.y(), dv.z(), -0.5 * tr.dot(q.vec()));
            const double w = q.coeffs().dot(pivot) < 0 ? -weight : weight;
            real.noalias() += w * q.coeffs();
            dual.noalias() += w * d;
        }
        const double norm = real.norm();
        ASSERT_GT(norm, 0);
        real /= norm;
        dual /= norm;
        const Eigen::Quaterniond q(real[3], real[0], real[1], real[2]);
        const Vec3 rv = real.head<3>(), dv = dual.head<3>();
        const Vec3 translation = 2.0 * (real[3] * dv - dual[3] * rv + rv.cross(dv));
        const Eigen::Matrix3d r = q.toRotationMatrix();
        xOut = times(r, x) + translation;
        nOut = normalisedOr(times(r, n), n);
    }
};

TEST_P(SkinningOnParts, GivesThePlainEigenFormulationsBitsForBits) {
    const Part& part = sharedPart(GetParam());
    const std::vector<Vec3> normals = vertexNormals(part.mesh);
    std::mt19937 rng(37);
    for (int k = 0; k < 3; ++k) {
        const std::vector<RigidTransform> bones =
            forwardKinematics(part.skeleton, randomPose(part.skeleton, rng, M_PI, 1.0))
                .boneTransforms;
        const PlainSkinning plain{part.skeleton, bones};
        for (SkinningMethod method : kMethods) {
            const SkinnedVertices skinned =
                skinVertices(part.mesh.vertices, normals, part.weights.perVertex,
                             SkinningTransforms(part.skeleton, bones), {method, 2});
            int differ = 0;
            for (int v = 0; v < part.mesh.vertexCount(); ++v) {
                const auto& list = part.weights.perVertex[v];
                Vec3 x = part.mesh.vertices[v], n = normals[v];
                if (!list.empty() && !plain.atRest(list)) {
                    if (method == SkinningMethod::DualQuaternion)
                        plain.dualQuaternions(list, part.mesh.vertices[v], normals[v], x, n);
                    else
                        plain.linearBlend(list, part.mesh.vertices[v], normals[v], x, n);
                }
                // Bits, not values: no tolerance, and -0 differs from 0.
                if (std::memcmp(x.data(), skinned.positions[v].data(), sizeof(Vec3)) != 0 ||
                    std::memcmp(n.data(), skinned.normals[v].data(), sizeof(Vec3)) != 0)
                    ++differ;
            }
            EXPECT_EQ(differ, 0) << "of " << part.mesh.vertexCount() << " vertices, pose " << k
                                 << (method == SkinningMethod::DualQuaternion ? ", DQS" : ", LBS");
        }
    }
}

INSTANTIATE_TEST_SUITE_P(SharedSketches, SkinningOnParts,
                         ::testing::Values("tube", "y_branch", "biped"),
                         testsupport::sketchTestName);

// A rig whose end bone can twist relative to the bone before it, and the
// 90-degree twist pose.
struct TwistRig {
    Part part;
    Pose twist;
    std::string source;
};

// The twist of the bone ending at `tip` about its own axis.
Pose twistAbove(const Skeleton& skeleton, JointId tip) {
    const PoseHierarchy h(skeleton);
    const int middle = h.parent(h.indexOf(tip));
    const Vec3 axis = (h.restPosition(h.indexOf(tip)) - h.restPosition(middle)).normalized();
    Pose pose;
    // The end bone's rotation, keyed by the joint it ends at (Pose.h).
    pose.setRotation(tip, Eigen::Quaterniond(Eigen::AngleAxisd(kTwistAngle, axis)));
    return pose;
}

// A capped tube along z (length 4, radius 0.5) with joints at z = -2, 0, 2,
// rooted at z = -2, weights blending smoothly from the first bone to the
// second over |z| < kBlendHalfWidth around the middle joint.
constexpr double kBlendHalfWidth = 0.6;
Part syntheticTwoBoneTube() {
    Part part;
    part.name = "cylinder tube";
    part.mesh = makeCylinderTube(41, 32, 0.5, 4.0);
    const JointId a = part.skeleton.addJoint(Vec3(0, 0, -2));
    const JointId b = part.skeleton.addJoint(Vec3(0, 0, 0));
    const JointId c = part.skeleton.addJoint(Vec3(0, 0, 2));
    part.skeleton.addBone(a, b);
    part.skeleton.addBone(b, c);
    for (const Vec3& v : part.mesh.vertices) {
        const double u = std::clamp((v.z() + kBlendHalfWidth) / (2 * kBlendHalfWidth), 0.0, 1.0);
        const double w = u * u * (3 - 2 * u);  // smoothstep
        if (w <= 0)
            part.weights.perVertex.push_back({{0, 1.0}});
        else if (w >= 1)
            part.weights.perVertex.push_back({{1, 1.0}});
        else
            part.weights.perVertex.push_back({{0, 1 - w}, {1, w}});
    }
    return part;
}

// The rigged tube part re-rooted at one end, so that turning the middle joint
// twists the end bone relative to the first (at the default central root both
// bones hang from the root and a twist there would turn the tube rigidly);
// the synthetic tube when the sketch gives fewer than two bones.
TwistRig tubeTwist() {
    TwistRig rig{sharedPart("tube"), {}, "rigged tube sketch"};
    if (rig.part.skeleton.boneCount() < 2) {
        rig.part = syntheticTwoBoneTube();
        rig.source = "makeCylinderTube, 2-bone rig (tube sketch gave " +
                     std::to_string(sharedPart("tube").skeleton.boneCount()) + " bone)";
    } else {
        Skeleton& skeleton = rig.part.skeleton;
        const PoseHierarchy central(skeleton);
        for (int j = 0; j < central.jointCount(); ++j) {
            if (central.children(j).empty()) {
                skeleton.setRoot(central.jointId(j));
                break;
            }
        }
        skeleton.reorient();
    }
    rig.twist = twistAbove(rig.part.skeleton, deepestJoint(rig.part.skeleton));
    return rig;
}

TEST(Skinning, DualQuaternionsKeepVolumeBetterThanLinearBlendUnderTwist) {
    const TwistRig rig = tubeTwist();
    ASSERT_GE(rig.part.skeleton.boneCount(), 2);
    const double rest = signedVolume(rig.part.mesh.vertices, rig.part.mesh.faces);
    ASSERT_GT(rest, 0);
    const double lbs =
        signedVolume(skinPart(rig.part, rig.twist, SkinningMethod::LinearBlend).positions,
                     rig.part.mesh.faces) /
        rest;
    const double dqs =
        signedVolume(skinPart(rig.part, rig.twist, SkinningMethod::DualQuaternion).positions,
                     rig.part.mesh.faces) /
        rest;
    std::cout << rig.source << ", " << rig.part.skeleton.boneCount()
              << " bones, 90 degree twist of the end bone: volume / rest volume LBS " << lbs
              << ", DQS " << dqs << "\n";
    EXPECT_LT(std::abs(dqs - 1), std::abs(lbs - 1));
    EXPECT_LT(lbs, 1.0);  // the candy wrapper collapses
}

TEST(Skinning, DualQuaternionBlendingIgnoresTheSignOfEachBonesQuaternion) {
    // q and -q are the same rotation; the antipodal fix makes DQS agree.
    const TriMesh tube = makeCylinderTube(8, 12, 0.3, 2.0);
    Skeleton chain;
    const JointId root = chain.addJoint(Vec3(0, 0, -1));
    const JointId middle = chain.addJoint(Vec3(0, 0, 0));
    const BoneId first = chain.addBone(root, middle);
    const BoneId second = chain.addBone(middle, chain.addJoint(Vec3(0, 0, 1)));
    WeightsById weights;
    for (const Vec3& v : tube.vertices) {
        const double w = std::clamp(v.z() / 2.0 + 0.5, 0.0, 1.0);
        weights.push_back({{first, 1 - w}, {second, w}});
    }
    RigidTransform a{Eigen::Quaterniond(Eigen::AngleAxisd(0.3, Vec3::UnitX())), Vec3(0, 0, 0.1)};
    RigidTransform b{Eigen::Quaterniond(Eigen::AngleAxisd(2.5, Vec3::UnitZ())), Vec3(0.2, 0, 0)};
    RigidTransform flipped = b;
    flipped.rotation.coeffs() = -flipped.rotation.coeffs();
    const SkinnedVertices plain =
        skinVertices(tube.vertices, {}, weights, SkinningTransforms(chain, {a, b}));
    const SkinnedVertices negated =
        skinVertices(tube.vertices, {}, weights, SkinningTransforms(chain, {a, flipped}));
    for (int v = 0; v < tube.vertexCount(); ++v)
        EXPECT_LT((plain.positions[v] - negated.positions[v]).norm(), 1e-12);
}

TEST(Skinning, MismatchedInputIsAProgrammingError) {
    const Part& part = sharedPart("tube");
    const std::vector<RigidTransform> rest =
        forwardKinematics(part.skeleton, Pose{}).boneTransforms;
    const SkinningTransforms transforms(part.skeleton, rest);
    WeightsById tooFew = part.weights.perVertex;
    tooFew.pop_back();
    EXPECT_THROW(skinVertices(part.mesh.vertices, {}, tooFew, transforms), std::logic_error);
    WeightsById badBone = part.weights.perVertex;
    badBone[0] = {{99, 1.0}};
    EXPECT_THROW(skinVertices(part.mesh.vertices, {}, badBone, transforms), std::logic_error);
    EXPECT_THROW(
        skinVertices(part.mesh.vertices, {Vec3::UnitX()}, part.weights.perVertex, transforms),
        std::logic_error);
    EXPECT_THROW(skinVertices(part.mesh.vertices, {}, part.weights.perVertex, transforms,
                              {SkinningMethod::LinearBlend, 0}),
                 std::logic_error);
    std::vector<RigidTransform> oneShort = rest;
    oneShort.pop_back();
    EXPECT_THROW(SkinningTransforms(part.skeleton, oneShort), std::logic_error);
}

// Weights name bones by id: after a bone goes, the bones after it move up in
// the bone list but skin exactly as before.
TEST(Skinning, WeightsFollowBoneIdsWhenAnEarlierBoneIsGone) {
    const Part contiguous = syntheticTwoBoneTube();
    Part gapped = contiguous;
    // The same chain, built after a bone that was then removed: ids 1 and 2
    // at positions 0 and 1.
    Skeleton skeleton;
    const JointId spare = skeleton.addJoint(Vec3(5, 0, 0));
    const JointId a = skeleton.addJoint(Vec3(0, 0, -2));
    const JointId b = skeleton.addJoint(Vec3(0, 0, 0));
    const JointId c = skeleton.addJoint(Vec3(0, 0, 2));
    skeleton.removeBone(skeleton.addBone(spare, a));
    skeleton.removeJoint(spare);
    const BoneId lower = skeleton.addBone(a, b);
    const BoneId upper = skeleton.addBone(b, c);
    ASSERT_EQ(skeleton.indexOfBone(lower), 0);
    ASSERT_NE(lower, 0u);
    gapped.skeleton = skeleton;
    for (auto& list : gapped.weights.perVertex)
        for (auto& [bone, w] : list)
            bone = bone == 0 ? lower : upper;
    ASSERT_TRUE(gapped.validate().empty()) << gapped.validate().front();
    Pose bent, bentGapped;
    bent.setRotation(contiguous.skeleton.bone(1).head,
                     Eigen::Quaterniond(Eigen::AngleAxisd(0.7, Vec3::UnitX())));
    bentGapped.setRotation(b, Eigen::Quaterniond(Eigen::AngleAxisd(0.7, Vec3::UnitX())));
    for (SkinningMethod method : kMethods) {
        const SkinnedVertices expected = skinPart(contiguous, bent, method);
        const SkinnedVertices got = skinPart(gapped, bentGapped, method);
        ASSERT_EQ(got.positions.size(), expected.positions.size());
        double moved = 0.0;
        for (std::size_t v = 0; v < got.positions.size(); ++v) {
            EXPECT_LT((got.positions[v] - expected.positions[v]).norm(), 1e-12) << v;
            moved = std::max(moved, (got.positions[v] - gapped.mesh.vertices[v]).norm());
        }
        EXPECT_GT(moved, 0.5) << "the bend moves the upper half";
    }
}

// Ids far beyond the bone count (a hand-edited file) take the other path
// (per-bone data by position): the same skinning.
TEST(Skinning, BoneIdsFarBeyondTheBoneCountSkinTheSame) {
    const Part contiguous = syntheticTwoBoneTube();
    Part far = contiguous;
    std::vector<Bone> bones = contiguous.skeleton.bones();
    const BoneId ids[] = {7, 1000000};
    for (std::size_t b = 0; b < bones.size(); ++b)
        bones[b].id = ids[b];
    far.skeleton =
        Skeleton::restore(contiguous.skeleton.joints(), bones, contiguous.skeleton.root());
    for (auto& list : far.weights.perVertex)
        for (auto& [bone, w] : list)
            bone = ids[bone];
    ASSERT_TRUE(far.validate().empty()) << far.validate().front();
    Pose bent;
    bent.setRotation(contiguous.skeleton.bones()[1].head,
                     Eigen::Quaterniond(Eigen::AngleAxisd(0.7, Vec3::UnitY())));
    for (SkinningMethod method : kMethods) {
        const SkinnedVertices expected = skinPart(contiguous, bent, method);
        const SkinnedVertices got = skinPart(far, bent, method);
        for (std::size_t v = 0; v < got.positions.size(); ++v)
            ASSERT_LT((got.positions[v] - expected.positions[v]).norm(), 1e-12) << v;
    }
}

TEST(Skinning, PosePartKeepsFacesAndSkinsPositions) {
    const Part& part = sharedPart("biped");
    std::mt19937 rng(23);
    const Pose pose = randomPose(part.skeleton, rng, 0.5);
    const PosedMesh posed = posePart(part, pose);
    EXPECT_EQ(posed.mesh.faces, part.mesh.faces);
    EXPECT_EQ(posed.mesh.vertices, skinPart(part, pose, SkinningMethod::DualQuaternion).positions);
}

}  // namespace
}  // namespace rigmesh::posetest
