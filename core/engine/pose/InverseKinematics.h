// Inverse kinematics for dragging a joint (paper section 3: parts are posed
// with FK/IK). The dragged joint moves toward the target by changing the
// local rotations of the chain of joints above it, from the chain's base (the
// root, or the nearest pinned joint) down to the dragged joint's parent; the
// rest of every subtree follows rigidly.
//
// Solver: FABRIK (Aristidou & Lasenby 2011), not damped least squares. For
// continuous dragging FABRIK is the stabler choice: every sweep places joints
// at exact bone lengths (no drift, no length constraint to enforce), it needs
// no Jacobian or damping factor and so has no singularity at a fully
// stretched chain (where DLS either oscillates or, damped enough to be
// stable, lags behind the cursor), and warm started from the current pose
// each sweep moves joints only as far as needed, so the pose follows the
// cursor smoothly. An unreachable target is handled in closed form: the
// chain is stretched straight toward it, which is the closest reach.
// FABRIK only crawls in one case, a target near full extension (each sweep
// straightens a nearly straight chain very little); a sweep that fails to
// halve the residual is followed by one damped least-squares step (damping =
// the residual, Levenberg style), kept only if it gets closer. That step
// converges quadratically exactly where FABRIK is slow, and cannot make the
// result worse.
//
// Positions are turned back into local rotations during the forward sweep:
// each joint gets the minimal rotation taking its current bone direction to
// the new one, which keeps twist continuous from one drag step to the next.
// Optional cone limits clamp the angle between a bone and where it would
// point at its rest local rotation.
//
// With IkOptions::stopAtJunctions the chain also stops below the nearest
// junction, so sibling limbs never move.
//
// Pinned joints keep their positions: the chain stops at a pinned ancestor,
// and also below any chain joint whose other subtrees hold a pinned joint
// (turning it would move them). A pinned dragged joint, or one with a pinned
// joint below it, does not move. Dragging the root with nothing pinned moves
// the whole skeleton (root translation).
#pragma once

#include <unordered_map>
#include <vector>

#include "pose/Pose.h"
#include "pose/PoseHierarchy.h"

namespace rigmesh {

struct IkOptions {
    // FABRIK sweeps (one backward + one forward pass) per drag step at most.
    // Warm started from the current pose a drag step usually needs a few.
    int maxIterations = 100;
    // Stop when the dragged joint is within this fraction of the chain's
    // length (sum of its bone lengths) of the target.
    double tolerance = 1e-7;
    // Soft reach (0 = off): the fraction of the chain's length near full
    // extension in which the reached distance eases exponentially toward the
    // full length. An exactly reached target makes joints move like the
    // square root of the target's motion as the chain straightens (a
    // geometric fact: the chain's slack shrinks quadratically with its
    // bend); a band of e.g. 0.05 keeps every joint's motion within a few
    // times the target's while dragging across the edge of the reach, at the
    // price of missing targets inside the band by up to ~0.37 of its width.
    double softReach = 0.0;
    // Optional cone limits: joint -> largest angle (radians, in [0, pi])
    // between the bone(s) it carries and their direction at its rest local
    // rotation. Joints not listed are free.
    std::unordered_map<JointId, double> coneLimits;
    // Limb reach: the chain also stops below the nearest junction (a joint
    // with two or more children), whose turn would swing its other branches:
    // dragging a hand moves the arm, never the body or the other arm. Off
    // (whole-body reach): up to the root or a pinned joint. A joint hanging
    // directly from a junction has no bone of its own to turn (a joint's
    // rotation carries every bone leaving it), so its drag reaches on up as
    // with whole-body reach.
    bool stopAtJunctions = false;
};

struct IkResult {
    Pose pose;
    // The joints that moved or turned, base first, dragged joint last; empty
    // when nothing could move.
    std::vector<JointId> chain;
    // Distance from the dragged joint's new position to the target.
    double distanceToTarget = 0;
    // Whether distanceToTarget is within the tolerance.
    bool reached = false;
    int iterations = 0;
};

// Drags `joint` toward `target` from `pose`, keeping `pinned` joints in place.
// Throws Error on an unknown joint, a non-finite target or a bad pose.
IkResult dragJoint(const PoseHierarchy& hierarchy, const Pose& pose, JointId joint,
                   const Vec3& target, const std::vector<JointId>& pinned = {},
                   const IkOptions& options = {});
IkResult dragJoint(const Skeleton& skeleton, const Pose& pose, JointId joint, const Vec3& target,
                   const std::vector<JointId>& pinned = {}, const IkOptions& options = {});

}  // namespace rigmesh
