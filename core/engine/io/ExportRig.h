// The node layout of one part's skeleton in an exported file (issue 6 item 1,
// notes items 2, 6, 7), independent of Assimp: one node per bone, placed at
// the bone's head (its joint nearer the root) as Blender's bones are, and
// parented by the bone hierarchy, so that bones sharing a joint are separate
// nodes that rotate independently. Root bones hang from the `Armature` node.
// A leaf bone also gets a tip node `<bone>_end` (no skin, under a `BoneTips`
// node beside the armature) at its tail, so the tail joint survives the
// round trip.
//
// Positions are baked: a point x of the part becomes unitScale * placement(x).
// Every bone node has the world axes at rest (our joint frames, Pose.h), so
// its rest transform is a translation and, in a pose, its local rotation is
// the pose's rotation of its head joint (conjugated by the placement's
// rotation); root bones add the pose's root translation.
#pragma once

#include <string>
#include <vector>

#include <Eigen/Geometry>

#include "part/Part.h"
#include "pose/Pose.h"

namespace rigmesh {

struct ExportBoneNode {
    std::string name;
    int bone = -1;      // index in skeleton.bones()
    int parent = -1;    // index in ExportRig::nodes, -1 = the Armature node
    JointId headJoint;  // the joint nearer the root: its rotation turns the node
    JointId tailJoint;
    Vec3 head;  // placed and scaled
    Vec3 tail;
    Vec3 restTranslation;  // local to the parent node (or to the Armature)
    bool leaf = false;     // no child bone: gets a `<name>_end` tip node
};

struct ExportRig {
    // Parent first; bones the root cannot reach are left out.
    std::vector<ExportBoneNode> nodes;
    // Per bone index: its node index, -1 when left out.
    std::vector<int> nodeOfBone;
    Eigen::Quaterniond placementRotation = Eigen::Quaterniond::Identity();
    double unitScale = 1.0;

    // A node's local transform in `pose` (translation, rotation).
    Vec3 localTranslation(int node, const Pose& pose) const;
    Eigen::Quaterniond localRotation(int node, const Pose& pose) const;
};

// The placement must be rigid (rotation and translation); scale goes into
// unitScale. `partName` is the (already unique) name prefix of the bones:
// `<partName>_bone<id>`. Throws Error on a skeleton with no root.
ExportRig makeExportRig(const Part& part, const std::string& partName,
                        const Eigen::Affine3d& placement, double unitScale);

// A name safe in every format: letters, digits and '_' (others become '_'),
// never empty, not starting with a digit.
std::string sanitizedName(const std::string& name);

}  // namespace rigmesh
