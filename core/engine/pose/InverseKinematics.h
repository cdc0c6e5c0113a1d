// Inverse kinematics for dragging a joint (paper section 3: parts are posed
// with FK/IK). The dragged joint moves toward the target by turning the
// bones of the chain above it (Pose.h: each bone its own rotation about its
// head), from the chain's base (the root, the nearest pinned joint, or with
// limb reach the nearest junction) down to the dragged joint; the base stays
// in place and each chain bone carries only its own subtree, so the base's
// other branches never move.
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
// Positions are turned back into bone rotations during the forward sweep:
// each bone gets the minimal rotation taking its current direction to the
// new one, which keeps twist continuous from one drag step to the next.
// Optional cone limits clamp the angle between a bone and where it would
// point at its rest rotation.
//
// With IkOptions::stopAtJunctions the chain stops at the nearest junction:
// the bone leaving it toward the dragged joint turns, its sibling limbs do
// not move. Without it (whole-body reach) the chain runs up to the root;
// siblings move only where the chain passes through their parent, and the
// root's own rotation and translation stay.
//
// Pinned joints keep their world positions exactly, at any reach: the chain
// stops at the nearest ancestor that is pinned or has a pin in another
// branch below it (turning the bone above it would carry that pin). A
// pinned dragged joint, or one with a pinned joint below it, does not move.
// Dragging the root with nothing pinned moves the whole skeleton (root
// translation).
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
    // between the bone ending at the joint and its direction at its rest
    // rotation (relative to its parent bone). Joints not listed are free.
    std::unordered_map<JointId, double> coneLimits;
    // Limb reach: the chain also stops at the nearest junction (a joint with
    // two or more children): dragging a hand turns the arm's bones up to and
    // including the one leaving the chest, never the body, the head or the
    // other arm. Off (whole-body reach): up to the root or a pinned joint.
    bool stopAtJunctions = false;
};

struct IkResult {
    Pose pose;
    // The chain's joints, base first (it stays; the bones between
    // consecutive joints turned), dragged joint last; the root alone when
    // the root was dragged; empty when nothing could move.
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
