#include <random>

#include "PoseTestSupport.h"
#include "base/Error.h"
#include "pose/InverseKinematics.h"

namespace rigmesh::posetest {
namespace {

// A reachable target is reached within this fraction of the part's bounding
// box diagonal.
constexpr double kReachRelative = 1e-4;
// IK keeps bone lengths to this fraction of each rest length.
constexpr double kLengthRelative = 1e-9;
// Pinned joints stay within this fraction of the skeleton's size.
constexpr double kPinnedRelative = 1e-12;
// While dragging, no joint moves more than this many times the target's step.
constexpr double kMaxJumpPerStep = 4.0;
// Crossing the edge of reach with exact reach: no joint moves more than this
// times sqrt(step * chain reach) in one step.
constexpr double kMaxJumpPerSqrtStep = 2.0;
constexpr int kRandomTargets = 20;

Vec3 jointPosition(const Skeleton& skeleton, const Pose& pose, JointId joint) {
    return forwardKinematics(skeleton, pose).jointPositions[skeleton.indexOfJoint(joint)];
}

std::vector<Vec3> restPositions(const Skeleton& skeleton) {
    std::vector<Vec3> positions;
    for (const Joint& joint : skeleton.joints())
        positions.push_back(joint.position);
    return positions;
}

void expectBoneLengthsKept(const Skeleton& skeleton, const Pose& pose) {
    const std::vector<double> lengths = posedBoneLengths(skeleton, pose);
    for (int b = 0; b < skeleton.boneCount(); ++b) {
        const double rest = skeleton.boneLength(skeleton.bones()[b].id);
        EXPECT_NEAR(lengths[b], rest, kLengthRelative * rest);
    }
}

// A random pose of the bones from the root to `joint` (the chain IK turns),
// whose result is therefore a reachable target for it.
Pose randomChainPose(const Skeleton& skeleton, JointId joint, std::mt19937& rng, double maxAngle) {
    const PoseHierarchy h(skeleton);
    Pose pose;
    for (int j = h.indexOf(joint); h.parent(j) >= 0; j = h.parent(j))
        pose.setRotation(h.jointId(j), randomRotation(rng, maxAngle));
    return pose;
}

class InverseKinematicsOnParts : public ::testing::TestWithParam<std::string> {};

TEST_P(InverseKinematicsOnParts, ReachesReachableTargetsAndKeepsBoneLengths) {
    const Part& part = sharedPart(GetParam());
    const Skeleton& skeleton = part.skeleton;
    const double size = boundingBoxDiagonal(part.mesh.vertices);
    std::mt19937 rng(11);
    for (const JointId joint : {deepestJoint(skeleton), skeleton.joints().back().id}) {
        if (joint == skeleton.root())
            continue;
        for (int k = 0; k < kRandomTargets; ++k) {
            const Vec3 target =
                jointPosition(skeleton, randomChainPose(skeleton, joint, rng, 1.0), joint);
            const IkResult result = dragJoint(skeleton, restPose(skeleton), joint, target);
            EXPECT_TRUE(result.reached);
            EXPECT_LT((jointPosition(skeleton, result.pose, joint) - target).norm(),
                      kReachRelative * size);
            expectBoneLengthsKept(skeleton, result.pose);
        }
    }
}

TEST_P(InverseKinematicsOnParts, PinnedJointsDoNotMove) {
    const Part& part = sharedPart(GetParam());
    const Skeleton& skeleton = part.skeleton;
    const double size = boundingBoxDiagonal(restPositions(skeleton));
    const PoseHierarchy h(skeleton);
    const JointId dragged = deepestJoint(skeleton);
    // Pin the dragged joint's grandparent (if not the root) and every leaf
    // outside its branch.
    std::vector<JointId> pinned;
    const int parent = h.parent(h.indexOf(dragged));
    if (parent >= 0 && h.parent(parent) >= 0)
        pinned.push_back(h.jointId(h.parent(parent)));
    for (int j = 0; j < h.jointCount(); ++j) {
        if (h.children(j).empty() && h.jointId(j) != dragged)
            pinned.push_back(h.jointId(j));
    }
    std::mt19937 rng(5);
    Pose pose = randomPose(skeleton, rng, 0.5);
    const PosedSkeleton before = forwardKinematics(skeleton, pose);
    for (int k = 0; k < kRandomTargets; ++k) {
        const Vec3 target =
            before.jointPositions[skeleton.indexOfJoint(dragged)] + 0.3 * size * Vec3::Random();
        pose = dragJoint(skeleton, pose, dragged, target, pinned).pose;
        const PosedSkeleton after = forwardKinematics(skeleton, pose);
        for (JointId id : pinned) {
            const int j = skeleton.indexOfJoint(id);
            EXPECT_LT((after.jointPositions[j] - before.jointPositions[j]).norm(),
                      kPinnedRelative * size)
                << GetParam() << " joint " << id;
        }
        expectBoneLengthsKept(skeleton, pose);
    }
}

// Whole-body reach (Alt + drag) runs to the root, through junctions whose
// other branches hold pins: a pinned shoulder stays where it is while the
// other hand is dragged, exactly (the chain stops at the junction below it).
TEST_P(InverseKinematicsOnParts, PinsInOtherBranchesHoldUnderWholeBodyReach) {
    const Part& part = sharedPart(GetParam());
    const Skeleton& skeleton = part.skeleton;
    const double size = boundingBoxDiagonal(restPositions(skeleton));
    const PoseHierarchy h(skeleton);
    const JointId dragged = deepestJoint(skeleton);
    // Every joint off the dragged joint's way to the root is pinned in turn
    // (leaves, shoulders, hips).
    std::vector<bool> onWay(h.jointCount(), false);
    for (int j = h.indexOf(dragged); j >= 0; j = h.parent(j))
        onWay[j] = true;
    IkOptions wholeBody;
    wholeBody.stopAtJunctions = false;
    std::mt19937 rng(11);
    int checked = 0;
    for (int p = 0; p < h.jointCount(); ++p) {
        if (onWay[p])
            continue;
        const std::vector<JointId> pinned{h.jointId(p)};
        const int index = skeleton.indexOfJoint(h.jointId(p));
        Pose pose = randomPose(skeleton, rng, 0.3);
        const Vec3 before = forwardKinematics(skeleton, pose).jointPositions[index];
        const Vec3 start = jointPosition(skeleton, pose, dragged);
        for (int k = 0; k < 5; ++k) {
            pose = dragJoint(skeleton, pose, dragged, start + 0.2 * size * Vec3::Random(), pinned,
                             wholeBody)
                       .pose;
            EXPECT_LT((forwardKinematics(skeleton, pose).jointPositions[index] - before).norm(),
                      kPinnedRelative * size)
                << GetParam() << " pinned joint " << h.jointId(p);
            expectBoneLengthsKept(skeleton, pose);
        }
        ++checked;
    }
    if (GetParam() != "tube") {
        EXPECT_GT(checked, 0);
    }
}

INSTANTIATE_TEST_SUITE_P(SharedSketches, InverseKinematicsOnParts,
                         ::testing::Values("tube", "y_branch", "biped"),
                         testsupport::sketchTestName);

TEST(InverseKinematics, ChainStopsAtTheNearestPinnedJoint) {
    const Skeleton chain = straightChain(5, 1.0);
    const IkResult result = dragJoint(chain, Pose{}, 5, Vec3(4, 1, 0), {2});
    EXPECT_EQ(result.chain, (std::vector<JointId>{2, 3, 4, 5}));
    EXPECT_TRUE(result.reached);
    // Joints above the pin keep their rotations.
    EXPECT_EQ(result.pose.rotations.count(0), 0u);
    EXPECT_EQ(result.pose.rotations.count(1), 0u);
}

TEST(InverseKinematics, UnreachableTargetStretchesTheChainTowardIt) {
    const Skeleton chain = straightChain(4, 1.0);  // reach 4 from the root
    Pose start;
    start.setRotation(1, Eigen::Quaterniond(Eigen::AngleAxisd(1.0, Vec3::UnitZ())));
    start.setRotation(2, Eigen::Quaterniond(Eigen::AngleAxisd(-0.7, Vec3::UnitY())));
    const Vec3 target(-3, 8, 5);
    const IkResult result = dragJoint(chain, start, 4, target);
    EXPECT_FALSE(result.reached);
    const PosedSkeleton posed = forwardKinematics(chain, result.pose);
    const Vec3 towards = target.normalized();
    for (int j = 0; j <= 4; ++j) {
        ASSERT_TRUE(posed.jointPositions[j].allFinite());
        EXPECT_NEAR((posed.jointPositions[j] - j * towards).norm(), 0, 1e-9) << j;
    }
    EXPECT_NEAR(result.distanceToTarget, target.norm() - 4.0, 1e-9);
    expectBoneLengthsKept(chain, result.pose);
}

// The largest joint move of one drag step over the step's length, and over
// the square root of (step length * chain reach).
struct DragJumps {
    double perStep = 0;
    double perSqrtStep = 0;
};

// Drags `joint` along a closed path (a circle around `centre` of radius
// `radius`, wobbling out of the xy plane) in `steps` steps, each warm started
// from the previous result. The first step comes from the rest pose and is
// not measured.
DragJumps dragAlongCircle(const Skeleton& skeleton, JointId joint, const Vec3& centre,
                          double radius, int steps, const IkOptions& options = {}) {
    const PoseHierarchy h(skeleton);
    double reach = 0;
    for (const Bone& bone : skeleton.bones())
        reach += skeleton.boneLength(bone.id);
    Pose pose;
    std::vector<Vec3> previous;
    Vec3 previousTarget;
    DragJumps worst;
    for (int k = 0; k <= steps; ++k) {
        const double a = 2 * M_PI * k / steps;
        const Vec3 target = centre + radius * Vec3(std::cos(a), std::sin(a), 0.2 * std::sin(3 * a));
        pose = dragJoint(h, pose, joint, target, {}, options).pose;
        const std::vector<Vec3> current = forwardKinematics(h, pose).jointPositions;
        if (k > 0) {
            const double step = (target - previousTarget).norm();
            for (int j = 0; j < h.jointCount(); ++j) {
                EXPECT_TRUE(current[j].allFinite());
                const double move = (current[j] - previous[j]).norm();
                worst.perStep = std::max(worst.perStep, move / step);
                worst.perSqrtStep = std::max(worst.perSqrtStep, move / std::sqrt(step * reach));
            }
        }
        previous = current;
        previousTarget = target;
    }
    return worst;
}

// A 6-bone chain along +x from the origin: reach 6.
constexpr int kChainBones = 6;
constexpr int kDragSteps = 2000;

TEST(InverseKinematics, DraggingOutOfReachIsContinuous) {
    const Skeleton chain = straightChain(kChainBones, 1.0);
    // Every target of this circle is 7 to 9 from the base.
    const DragJumps jumps = dragAlongCircle(chain, kChainBones, Vec3::Zero(), 8.0, kDragSteps);
    EXPECT_LT(jumps.perStep, kMaxJumpPerStep);
}

TEST(InverseKinematics, DraggingWithinReachIsContinuous) {
    const Skeleton chain = straightChain(kChainBones, 1.0);
    // Targets 1 to 5 from the base.
    const DragJumps jumps =
        dragAlongCircle(chain, kChainBones, Vec3(3.0, 0.0, 0.0), 2.0, kDragSteps);
    EXPECT_LT(jumps.perStep, kMaxJumpPerStep);
}

TEST(InverseKinematics, SoftReachKeepsDraggingAcrossTheEdgeOfReachContinuous) {
    const Skeleton chain = straightChain(kChainBones, 1.0);
    IkOptions soft;
    soft.softReach = 0.05;
    // Targets from 1.5 (inside reach) to 8.5 (outside) from the base.
    const DragJumps jumps =
        dragAlongCircle(chain, kChainBones, Vec3(3.5, 1.0, 0.0), 5.0, kDragSteps, soft);
    std::cout << "soft reach 0.05, crossing the edge of reach: largest joint move / target step "
              << jumps.perStep << "\n";
    EXPECT_LT(jumps.perStep, kMaxJumpPerStep);
}

TEST(InverseKinematics, ExactReachCrossingMovesJointsLikeTheSquareRootOfTheStep) {
    // Without soft reach, reaching exactly makes the chain straighten with
    // the square root of the remaining slack: bounded per sqrt(step * reach),
    // not per step.
    const Skeleton chain = straightChain(kChainBones, 1.0);
    const DragJumps jumps =
        dragAlongCircle(chain, kChainBones, Vec3(3.5, 1.0, 0.0), 5.0, kDragSteps);
    std::cout << "exact reach, crossing the edge of reach: largest joint move / target step "
              << jumps.perStep << ", / sqrt(step * reach) " << jumps.perSqrtStep << "\n";
    EXPECT_LT(jumps.perSqrtStep, kMaxJumpPerSqrtStep);
}

TEST(InverseKinematics, DraggingABipedHandWithSoftReachIsContinuous) {
    const Skeleton& skeleton = sharedPart("biped").skeleton;
    const JointId hand = deepestJoint(skeleton);
    const double size = boundingBoxDiagonal(restPositions(skeleton));
    const Vec3 start = skeleton.joint(hand).position;
    IkOptions soft;
    soft.softReach = 0.05;
    const DragJumps jumps =
        dragAlongCircle(skeleton, hand, start + Vec3(0.2 * size, 0, 0), 0.6 * size, 3000, soft);
    std::cout << "biped hand, soft reach 0.05: largest joint move / target step " << jumps.perStep
              << "\n";
    EXPECT_LT(jumps.perStep, kMaxJumpPerStep);
}

TEST(InverseKinematics, ConeLimitsBoundEachJointsSwing) {
    const Skeleton chain = straightChain(5, 1.0);
    IkOptions options;
    const double limit = 0.4;
    for (JointId j = 1; j <= 5; ++j)
        options.coneLimits[j] = limit;
    std::mt19937 rng(9);
    std::uniform_real_distribution<double> coordinate(-5, 5);
    Pose pose;
    for (int k = 0; k < kRandomTargets; ++k) {
        const Vec3 target(coordinate(rng), coordinate(rng), coordinate(rng));
        pose = dragJoint(chain, pose, 5, target, {}, options).pose;
        for (JointId j = 1; j <= 5; ++j) {
            // The swing of the bone's rotation away from the rest direction +x.
            const Vec3 dir = pose.rotation(j).normalized() * Vec3::UnitX();
            EXPECT_LE(std::acos(std::clamp(dir.x(), -1.0, 1.0)), limit + 1e-9);
        }
        expectBoneLengthsKept(chain, pose);
    }
}

TEST(InverseKinematics, DraggingTheRootMovesEverythingUnlessSomethingIsPinned) {
    const Skeleton chain = straightChain(3, 1.0);
    const IkResult moved = dragJoint(chain, Pose{}, 0, Vec3(1, 2, 3));
    EXPECT_EQ(moved.pose.rootTranslation, Vec3(1, 2, 3));
    const IkResult pinned = dragJoint(chain, Pose{}, 0, Vec3(1, 2, 3), {3});
    EXPECT_EQ(pinned.pose.rootTranslation, Vec3::Zero());
    EXPECT_TRUE(pinned.chain.empty());
}

TEST(InverseKinematics, RandomTargetsNeverGiveNaN) {
    const Skeleton& skeleton = sharedPart("biped").skeleton;
    const double size = boundingBoxDiagonal(restPositions(skeleton));
    std::mt19937 rng(13);
    std::uniform_real_distribution<double> coordinate(-2 * size, 2 * size);
    std::uniform_int_distribution<int> pick(0, skeleton.jointCount() - 1);
    Pose pose;
    for (int k = 0; k < 200; ++k) {
        const JointId joint = skeleton.joints()[pick(rng)].id;
        const Vec3 target(coordinate(rng), coordinate(rng), coordinate(rng));
        pose = dragJoint(skeleton, pose, joint, target).pose;
        ASSERT_TRUE(pose.isFinite());
        for (const Vec3& p : forwardKinematics(skeleton, pose).jointPositions)
            ASSERT_TRUE(p.allFinite());
    }
    expectBoneLengthsKept(skeleton, pose);
}

TEST(InverseKinematics, BadInputIsAnError) {
    const Skeleton chain = straightChain(2, 1.0);
    EXPECT_THROW(dragJoint(chain, Pose{}, 99, Vec3::Zero()), Error);
    EXPECT_THROW(dragJoint(chain, Pose{}, 2, Vec3(NAN, 0, 0)), Error);
}

// The joints a limb-reach drag of `joint` may move: the subtree of the
// junction's (or the root's) child on the way up from it.
std::vector<bool> limbOf(const PoseHierarchy& h, int joint) {
    int top = joint;
    while (h.parent(h.parent(top)) >= 0 && h.children(h.parent(top)).size() == 1)
        top = h.parent(top);
    std::vector<bool> inLimb(h.jointCount(), false);
    for (int j : h.parentFirstOrder())
        inLimb[j] = j == top || (h.parent(j) >= 0 && inLimb[h.parent(j)]);
    return inLimb;
}

// Whether a whole-body chain from `joint` to the root passes through a
// junction (other than the root) whose other branches must then move.
bool passesAJunction(const PoseHierarchy& h, int joint) {
    for (int j = h.parent(joint); j >= 0 && h.parent(j) >= 0; j = h.parent(j))
        if (h.children(j).size() > 1)
            return true;
    return false;
}

class LimbReach : public ::testing::TestWithParam<std::string> {};

TEST_P(LimbReach, DraggingALeafMovesOnlyItsLimbUnlessWholeBodyReach) {
    const Skeleton& skeleton = sharedPart(GetParam()).skeleton;
    const PoseHierarchy h(skeleton);
    const double size = boundingBoxDiagonal(restPositions(skeleton));
    const PosedSkeleton rest = forwardKinematics(h, Pose{});
    int leaves = 0, throughJunctions = 0;
    for (int leaf = 0; leaf < h.jointCount(); ++leaf) {
        if (!h.children(leaf).empty() || leaf == h.root())
            continue;
        ++leaves;
        const std::vector<bool> inLimb = limbOf(h, leaf);
        const Vec3 target = rest.jointPositions[leaf] + Vec3(0.1, 0.15, 0.05) * size;
        IkOptions limb;
        limb.stopAtJunctions = true;
        const IkResult limbDrag = dragJoint(h, Pose{}, h.jointId(leaf), target, {}, limb);
        const PosedSkeleton posed = forwardKinematics(h, limbDrag.pose);
        EXPECT_LT((posed.jointPositions[leaf] - target).norm(),
                  (rest.jointPositions[leaf] - target).norm())
            << "the dragged joint did not move toward the target";
        for (int j = 0; j < h.jointCount(); ++j) {
            if (!inLimb[j]) {
                EXPECT_EQ(posed.jointPositions[j], rest.jointPositions[j])
                    << "joint " << h.jointId(j) << " outside the dragged limb moved";
            }
        }
        // Whole-body reach (the default) also moves the branches of every
        // junction the chain passes through; never the root's other ones.
        const PosedSkeleton body =
            forwardKinematics(h, dragJoint(h, Pose{}, h.jointId(leaf), target).pose);
        bool movedOutside = false;
        for (int j = 0; j < h.jointCount(); ++j)
            if (!inLimb[j] &&
                (body.jointPositions[j] - rest.jointPositions[j]).norm() > 1e-6 * size)
                movedOutside = true;
        EXPECT_EQ(movedOutside, passesAJunction(h, leaf)) << "leaf " << h.jointId(leaf);
        throughJunctions += passesAJunction(h, leaf) ? 1 : 0;
    }
    EXPECT_GE(leaves, 3);
    if (GetParam() == "biped") {
        EXPECT_GE(throughJunctions, 3) << "the biped's arms and head hang from the chest";
    }
}

INSTANTIATE_TEST_SUITE_P(SharedSketches, LimbReach,
                         ::testing::Values("y_branch", "star", "biped", "quadruped"));

// A limb drag of a joint hanging right below a junction
// turns that limb's first bone (the one leaving the junction) and nothing
// else: every joint and bone outside the dragged joint's subtree keeps its
// place and transform exactly, from any pose.
class JunctionChild : public ::testing::TestWithParam<std::string> {};

TEST_P(JunctionChild, LimbDragTurnsOnlyTheBoneLeavingTheJunction) {
    const Skeleton& skeleton = sharedPart(GetParam()).skeleton;
    const PoseHierarchy h(skeleton);
    const double size = boundingBoxDiagonal(restPositions(skeleton));
    std::mt19937 rng(17);
    const Pose start = randomPose(skeleton, rng, 0.3, 0.1 * size);
    const PosedSkeleton before = forwardKinematics(h, start);
    IkOptions limb;
    limb.stopAtJunctions = true;
    int dragged = 0;
    for (int joint = 0; joint < h.jointCount(); ++joint) {
        const int junction = h.parent(joint);
        if (junction < 0 || h.children(junction).size() < 2)
            continue;
        ++dragged;
        const Vec3 from = before.jointPositions[joint];
        const Vec3 target = from + Vec3(0.05, -0.08, 0.03) * size;
        const IkResult result = dragJoint(h, start, h.jointId(joint), target, {}, limb);
        EXPECT_EQ(result.chain, (std::vector<JointId>{h.jointId(junction), h.jointId(joint)}));
        const PosedSkeleton after = forwardKinematics(h, result.pose);
        // The bone turned about the junction toward the target.
        EXPECT_LT((after.jointPositions[joint] - target).norm(), (from - target).norm());
        EXPECT_NEAR((after.jointPositions[joint] - after.jointPositions[junction]).norm(),
                    (from - before.jointPositions[junction]).norm(), 1e-12 * size);
        // Only the turned bone's rotation changed.
        for (const auto& [id, q] : result.pose.rotations)
            if (id != h.jointId(joint)) {
                EXPECT_EQ(q.coeffs(), start.rotation(id).coeffs()) << "joint " << id;
            }
        std::vector<bool> below(h.jointCount(), false);
        for (int j : h.parentFirstOrder())
            below[j] = j == joint || (h.parent(j) >= 0 && below[h.parent(j)]);
        for (int j = 0; j < h.jointCount(); ++j)
            if (!below[j]) {
                EXPECT_EQ(after.jointPositions[j], before.jointPositions[j])
                    << GetParam() << ": joint " << h.jointId(j) << " moved";
            }
        for (int b = 0; b < h.boneCount(); ++b)
            if (!below[h.boneTailJoint(b)]) {
                EXPECT_EQ(after.boneTransforms[b].rotation.coeffs(),
                          before.boneTransforms[b].rotation.coeffs());
                EXPECT_EQ(after.boneTransforms[b].translation,
                          before.boneTransforms[b].translation);
            }
    }
    EXPECT_GE(dragged, 3) << GetParam() << " has junction children";
}

INSTANTIATE_TEST_SUITE_P(SharedSketches, JunctionChild,
                         ::testing::Values("y_branch", "star", "biped", "quadruped"));

}  // namespace
}  // namespace rigmesh::posetest
