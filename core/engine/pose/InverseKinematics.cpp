#include "pose/InverseKinematics.h"

#include <algorithm>
#include <cmath>
#include <stdexcept>

#include "base/Error.h"
#include "pose/ForwardKinematics.h"

namespace rigmesh {

namespace {

// Below this fraction of a bone's length a direction counts as undefined and
// the bone keeps its current one.
constexpr double kDegenerateDirection = 1e-12;
// A FABRIK sweep that leaves more than this fraction of the residual counts
// as crawling and is followed by a damped least-squares step.
constexpr double kSlowSweep = 0.5;
// A chain whose joints and target are all within this fraction of its length
// from one line counts as straight, and is bowed sideways by kUnfoldBow of
// its length before solving.
constexpr double kStraightChain = 1e-9;
constexpr double kUnfoldBow = 1e-3;

Vec3 directionOr(const Vec3& v, double scale, const Vec3& fallback) {
    const double norm = v.norm();
    return norm > kDegenerateDirection * scale ? Vec3(v / norm) : fallback;
}

// Rotates `desired` back into the cone of half-angle `limit` around `ref`
// (both unit), turning in the plane of the two (or of `current` when they are
// parallel or opposite).
Vec3 clampToCone(const Vec3& ref, const Vec3& desired, const Vec3& current, double limit) {
    const double angle = std::acos(std::clamp(ref.dot(desired), -1.0, 1.0));
    if (angle <= limit)
        return desired;
    Vec3 axis = ref.cross(desired);
    if (axis.norm() < kDegenerateDirection)
        axis = ref.cross(current);
    if (axis.norm() < kDegenerateDirection)
        axis = ref.unitOrthogonal();
    return Eigen::AngleAxisd(limit, axis.normalized()) * ref;
}

// The chain being solved: pivots c_0 (base, fixed) .. c_n (dragged),
// positions, and the rotations of its segments c_i -> c_{i+1}. A segment is
// a bone (Pose.h: its rotation keyed by c_{i+1}), or, where c_{i+1} is an
// attached chain's root, the bone it hangs from together with the rigid
// link to it (keyed by that bone's tail, which is no pivot): the chain
// crosses a disconnected joint as its head follows its parent's frame.
struct Chain {
    std::vector<int> joints;
    std::vector<double> lengths;  // per segment c_i -> c_{i+1}
    std::vector<Vec3> restDirs;   // unit, per segment
    std::vector<double> limits;   // per segment: its cone limit (or > pi)
    std::vector<Eigen::Quaterniond> local;
    // Per segment: the rotation of the chain root it ends at (identity at a
    // joint a bone ends at), turning the segments below it (FK's r_j about
    // an attached joint).
    std::vector<Eigen::Quaterniond> after;
    std::vector<Vec3> positions;
    Eigen::Quaterniond baseParentWorld;  // world rotation of the bone ending at c_0
    double totalLength = 0;

    int bones() const { return static_cast<int>(lengths.size()); }

    // FABRIK forward pass from the fixed base, turning every bone toward the
    // next backward-pass position (or `fixedDir`) by its minimal rotation, so
    // positions and bone rotations stay consistent (Aristidou & Lasenby
    // 2011, with the per-bone frames giving the rotations).
    void forward(const Vec3* fixedDir) {
        Eigen::Quaterniond parentWorld = baseParentWorld;
        for (int i = 0; i < bones(); ++i) {
            Eigen::Quaterniond world = parentWorld * local[i];
            const Vec3 current = world * restDirs[i];
            Vec3 desired = fixedDir
                               ? *fixedDir
                               : directionOr(positions[i + 1] - positions[i], lengths[i], current);
            if (limits[i] < M_PI)
                desired = clampToCone(parentWorld * restDirs[i], desired, current, limits[i]);
            world = (Eigen::Quaterniond::FromTwoVectors(current, desired) * world).normalized();
            local[i] = (parentWorld.conjugate() * world).normalized();
            positions[i + 1] = positions[i] + lengths[i] * (world * restDirs[i]);
            parentWorld = world * after[i];
        }
    }

    // One damped least-squares step (Wampler 1986; Buss 2004) on a world
    // rotation vector per chain joint, for the end game where FABRIK crawls:
    // with the chain nearly straight each sweep shortens it very little.
    // With r_i = end - P_i, d(end)/d(omega_i) = -[r_i]x, so
    //     y = (sum_i (|r_i|^2 I - r_i r_i^T) + lambda^2 I)^-1 (target - end),
    //     omega_i = r_i x y,
    // applied from the base down. Only the positions change here; forward()
    // then turns the bones onto them (and applies the cone limits).
    void dampedStep(const Vec3& target, double lambda) {
        const Vec3 end = positions[bones()];
        Eigen::Matrix3d jjt = lambda * lambda * Eigen::Matrix3d::Identity();
        for (int i = 0; i < bones(); ++i) {
            const Vec3 r = end - positions[i];
            jjt += r.squaredNorm() * Eigen::Matrix3d::Identity() - r * r.transpose();
        }
        const Vec3 y = jjt.ldlt().solve(target - end);
        Eigen::Quaterniond turn = Eigen::Quaterniond::Identity();
        Vec3 previousOld = positions[0];
        for (int i = 0; i < bones(); ++i) {
            const Vec3 omega = (end - previousOld).cross(y);
            const double angle = omega.norm();
            if (angle > 0)
                turn = (Eigen::Quaterniond(Eigen::AngleAxisd(angle, omega / angle)) * turn)
                           .normalized();
            const Vec3 nextOld = positions[i + 1];
            positions[i + 1] = positions[i] + turn * (nextOld - previousOld);
            previousOld = nextOld;
        }
    }

    // A straight chain pulled along its own line toward its base cannot
    // bend: FABRIK keeps it straight and every bend direction is equally
    // (un)helpful to DLS. Bow the inner joints slightly sideways (a fixed
    // direction perpendicular to the chain) so that the solve has a
    // direction to bend in; this happens only in that degenerate start.
    void unfoldIfStraight(const Vec3& target) {
        const Vec3 axis = (positions[bones()] - positions[0]).normalized();
        const double scale = kStraightChain * totalLength;
        if (bones() < 2 || (target - positions[0]).cross(axis).norm() > scale)
            return;
        for (int i = 1; i < bones(); ++i) {
            if ((positions[i] - positions[0]).cross(axis).norm() > scale)
                return;
        }
        const Vec3 side = axis.unitOrthogonal();
        for (int i = 1; i < bones(); ++i)
            positions[i] += kUnfoldBow * totalLength * std::sin(M_PI * i / bones()) * side;
    }

    // FABRIK backward pass: the dragged joint on the target, each joint
    // pulled back toward its old place at bone length from its child.
    void backward(const Vec3& target) {
        positions[bones()] = target;
        for (int i = bones() - 1; i >= 0; --i) {
            const Vec3 fallback = (positions[i] - positions[i + 1]).normalized();
            positions[i] =
                positions[i + 1] +
                lengths[i] * directionOr(positions[i] - positions[i + 1], lengths[i], fallback);
        }
    }
};

// Soft reach: within the last `soft` fraction of the chain's length the
// distance the chain reaches for grows as
//     d' = (L - s) + s (1 - exp(-(d - (L - s)) / s)),   s = soft * L,
// which has slope 1 where the band starts and approaches L exponentially, so
// the chain straightens smoothly instead of with the square-root speed-up of
// an exactly reached target near full extension.
Vec3 softenedTarget(const Vec3& base, const Vec3& target, double length, double soft) {
    const double s = soft * length;
    const Vec3 toTarget = target - base;
    const double d = toTarget.norm();
    if (!(s > 0) || d <= length - s)
        return target;
    const double reach = (length - s) + s * (1 - std::exp(-(d - (length - s)) / s));
    return base + toTarget * (reach / d);
}

}  // namespace

IkResult dragJoint(const PoseHierarchy& h, const Pose& pose, JointId joint, const Vec3& target,
                   const std::vector<JointId>& pinned, const IkOptions& options) {
    if (!target.allFinite())
        throw Error(MessageId::IkTargetNotFinite);

    if (options.maxIterations < 0 || !(options.tolerance >= 0) ||
        !(options.softReach >= 0 && options.softReach < 1))
        throw std::logic_error(
            "IK options need a non-negative iteration count and tolerance and a soft reach in "
            "[0, 1).");
    const int dragged = h.indexOf(joint);
    const PosedSkeleton posed = forwardKinematics(h, pose);

    IkResult result;
    result.pose = pose;
    result.distanceToTarget = (posed.jointPositions[dragged] - target).norm();

    // Pinned joints per subtree (self included), children before parents.
    const int n = h.jointCount();
    std::vector<bool> isPinned(n, false);
    for (JointId id : pinned)
        isPinned[h.indexOf(id)] = true;
    std::vector<int> pinsBelow(n, 0);
    const std::vector<int>& order = h.parentFirstOrder();
    for (auto it = order.rbegin(); it != order.rend(); ++it) {
        pinsBelow[*it] += isPinned[*it] ? 1 : 0;
        if (h.parent(*it) >= 0)
            pinsBelow[h.parent(*it)] += pinsBelow[*it];
    }
    if (!h.reachable(dragged) || pinsBelow[dragged] > 0)
        return result;
    if (dragged == h.root()) {
        // Nothing reachable is pinned (checked above): translate everything.
        result.pose.rootTranslation += target - posed.jointPositions[dragged];
        result.chain = {joint};
        result.distanceToTarget = 0;
        result.reached = true;
        return result;
    }

    // Walk up to the base: the root, the nearest joint with a pin at or below
    // it or, with limb reach, the nearest junction. The base stays in place;
    // the bones below it turn, each about its head, and carry only their own
    // subtrees, so the base's other branches never move. A bone above a
    // joint with a pin in its subtree would carry the pin along, so the chain
    // never reaches past one: pins hold in world space at any reach. An
    // attached chain's root is crossed by turning the bone it hangs from (its
    // tail is no pivot), unless that bone cannot turn alone: a root chain (no
    // bone), a tail with a pin at or below it or, with limb reach, a tail
    // where other bones or chains leave.
    auto stopsAt = [&](int at) {
        return pinsBelow[at] > 0 || (options.stopAtJunctions && h.children(at).size() > 1);
    };
    std::vector<int> joints{dragged};
    std::vector<int> keys;  // per segment, walking up: the joint its rotation is keyed by
    for (int current = dragged; h.parent(current) >= 0;) {
        int up = h.parent(current);
        int key = current;
        if (h.attached(current)) {
            if (up == h.root() || stopsAt(up))
                break;
            key = up;
            up = h.parent(up);
        }
        keys.push_back(key);
        joints.push_back(up);
        current = up;
        if (stopsAt(current))
            break;
    }
    std::reverse(joints.begin(), joints.end());
    std::reverse(keys.begin(), keys.end());
    if (keys.empty())
        return result;  // a root chain's root: no bone carries it

    Chain chain;
    chain.joints = joints;
    const int bones = static_cast<int>(keys.size());
    for (int i = 0; i < bones; ++i) {
        const Vec3 rest = h.restPosition(joints[i + 1]) - h.restPosition(joints[i]);
        chain.lengths.push_back(rest.norm());
        // A zero-length segment (a chain hanging at its parent bone's head)
        // has no direction of its own; it never moves the next pivot.
        chain.restDirs.push_back(rest.norm() > 0 ? Vec3(rest.normalized()) : Vec3::UnitY());
        chain.totalLength += chain.lengths.back();
        const JointId key = h.jointId(keys[static_cast<std::size_t>(i)]);
        const auto limit = options.coneLimits.find(key);
        chain.limits.push_back(limit == options.coneLimits.end() ? 2 * M_PI : limit->second);
        // The rotation FK used (normalised; FK rejected zero and non-finite).
        chain.local.push_back(pose.rotation(key).normalized());
        chain.after.push_back(h.attached(joints[i + 1])
                                  ? pose.rotation(h.jointId(joints[i + 1])).normalized()
                                  : Eigen::Quaterniond::Identity());
    }
    chain.baseParentWorld = posed.jointTransforms[joints[0]].rotation;
    for (int j : joints)
        chain.positions.push_back(posed.jointPositions[j]);

    const double tolerance = options.tolerance * chain.totalLength;
    const Vec3 base = chain.positions[0];
    const Vec3 goal = softenedTarget(base, target, chain.totalLength, options.softReach);
    double distance = (chain.positions[bones] - goal).norm();
    int iterations = 0;
    if (distance > tolerance) {
        const Vec3 toTarget = goal - base;
        if (toTarget.norm() >= chain.totalLength) {
            // Out of reach: the closest reach is the chain stretched straight
            // toward the target.
            const Vec3 dir = toTarget.normalized();
            chain.forward(&dir);
            iterations = 1;
        } else {
            chain.unfoldIfStraight(goal);
            while (iterations < options.maxIterations && distance > tolerance) {
                const double before = distance;
                chain.backward(goal);
                chain.positions[0] = base;
                chain.forward(nullptr);
                distance = (chain.positions[bones] - goal).norm();
                ++iterations;
                if (distance <= tolerance || distance < kSlowSweep * before)
                    continue;
                // FABRIK is crawling: try a damped least-squares step, damped
                // by the residual (Levenberg), kept only if it gets closer.
                const std::vector<Vec3> savedPositions = chain.positions;
                const std::vector<Eigen::Quaterniond> savedLocal = chain.local;
                chain.dampedStep(goal, distance);
                chain.forward(nullptr);
                const double polished = (chain.positions[bones] - goal).norm();
                if (polished < distance) {
                    distance = polished;
                } else {
                    chain.positions = savedPositions;
                    chain.local = savedLocal;
                }
            }
        }
        for (int i = 0; i < bones; ++i)
            result.pose.setRotation(h.jointId(keys[static_cast<std::size_t>(i)]), chain.local[i]);
    }

    result.iterations = iterations;
    result.distanceToTarget = (chain.positions[bones] - target).norm();
    result.reached = result.distanceToTarget <= tolerance;
    for (int j : joints)
        result.chain.push_back(h.jointId(j));
    return result;
}

IkResult dragJoint(const Skeleton& skeleton, const Pose& pose, JointId joint, const Vec3& target,
                   const std::vector<JointId>& pinned, const IkOptions& options) {
    return dragJoint(PoseHierarchy(skeleton), pose, joint, target, pinned, options);
}

}  // namespace rigmesh
