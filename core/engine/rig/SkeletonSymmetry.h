// Symmetric rigs: a skeleton made for a mirror-symmetric surface made
// symmetric too, so mirrored limbs get mirrored bones (an auto-rigged star's
// identical arms one or two bones each, a hand-drawn biped's shoulders at
// different heights). The surface's mirror plane is found by
// rig/MirrorSymmetry; the skeleton's branches (runs of joints between
// junctions and tips) are paired with their mirror images, a branch with
// fewer joints than its image gets as many (its bones split), and every pair
// of joints is moved to the mean of the one and the other's reflection
// (joints mapped onto themselves onto the plane). Topology other than those
// splits, and ids, are kept.
#pragma once

#include <optional>
#include <vector>

#include "mesh/TriMesh.h"
#include "rig/MirrorSymmetry.h"
#include "rig/Skeleton.h"

namespace rigmesh {

struct SymmetrizeOptions {
    MirrorSearch search;
    // Split bones of a branch whose image has more joints; off, such
    // branches keep their joints where they are (and stay unmirrored).
    bool matchJointCounts = true;
};

// A bone split to match its branch's image (Skeleton::splitBone): `bone`
// now ends at `middle`, `added` runs from there to the old tail.
struct BoneSplit {
    BoneId bone;
    BoneId added;
    JointId middle;
};

struct SymmetrizeReport {
    std::optional<MirrorFit> mirror;  // none: no plane, nothing changed
    int pairedJoints = 0;             // joints moved with an image (each pair counts 2)
    int jointsOnPlane = 0;            // joints their own image, moved onto the plane
    std::vector<BoneSplit> splits;    // bones split matching a branch to its image, in order
    // One joint added per split.
    int jointsAdded() const { return static_cast<int>(splits.size()); }
};

SymmetrizeReport symmetrizeSkeleton(Skeleton& skeleton, const TriMesh& mesh,
                                    const SymmetrizeOptions& options = {});

}  // namespace rigmesh
