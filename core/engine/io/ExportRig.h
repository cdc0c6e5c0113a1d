// The node layout of one part's skeleton in an exported file
// (docs/EXCHANGE.md rules 2, 6, 7), independent of Assimp: one node per bone, placed at
// the bone's head (its joint nearer the root) as Blender's bones are, and
// parented by the bone hierarchy, so that bones sharing a joint are separate
// nodes that rotate independently. Root bones hang from the part's armature
// node (`<part>_armature`; in COLLADA the one `Armature`: AssimpSceneBuilder.cpp).
//
// Bone frames: at rest a bone node's +Y axis runs from its
// head to its tail, Blender's bone convention, which its glTF, FBX and
// COLLADA importers read to place each tail. The frame is the shortest
// rotation taking +Y onto the bone (no roll), or the bone's frame kept from
// an imported file (Part::boneFrames), so that importers guess from it what
// they guessed from the file; in FBX and COLLADA (BoneAxes::PlusY) a kept
// frame whose +Y runs elsewhere than along the bone (a DirectX .x file's) is
// turned onto the bone, keeping its roll; in glTF one with no axis along the
// bone has its nearest axis turned onto it (docs/EXCHANGE.md rule 27).
//
// Disconnected bones (Skeleton.h): a bone leaving an attached chain's root
// is a child of the node of the bone the chain hangs from, placed at its own
// head (Blender's disconnected child); a root chain's bones hang from the
// Armature node like root bones. Optionally (ExportOptions::leafBones) a leaf
// bone gets an end node `<bone>_end` at its tail, child of the bone node and
// a joint without weights, like Blender's FBX "Add Leaf Bones": importers then
// know the leaf's length too (endBoneOf).
//
// Positions are baked: a point x of the part becomes unitScale * placement(x).
// Our bone frames (Pose.h) are the world axes at rest and every bone turns
// about its head by its own rotation, exactly as a node here does, so a bone
// node's posed global transform is its old axis-aligned one times its rest
// frame R: its local rotation is R_parent^-1 * q * R, where q is the pose's
// rotation of the bone (keyed by its tail joint; conjugated by the
// placement's rotation). Root bones take the root's rotation (the whole
// skeleton's) before their own and add the pose's root translation.
#pragma once

#include <string>
#include <vector>

#include <Eigen/Geometry>

#include "part/Part.h"
#include "pose/Pose.h"

namespace rigmesh {

struct ExportBoneNode {
    std::string name;
    // The bone's own name when `name` had to differ from it to stay unique
    // in the file (AssimpSceneBuilder: makeBoneNamesUnique), else empty;
    // written beside the node for importers to map back (BoneTipHints.h).
    std::string renamedFrom;
    int bone = -1;      // index in skeleton.bones()
    int parent = -1;    // index in ExportRig::nodes, -1 = the Armature node
    JointId headJoint;  // the joint nearer the root, about which the node turns
    JointId tailJoint;  // its pose rotation is the node's (Pose.h)
    // Rotations applied before the node's own, outermost first (Pose.h): the
    // root's for nodes under the Armature, a chain root's for its bones.
    std::vector<JointId> turnedBy;
    // For a node under the Armature: the pose's root joint and its placed
    // rest position, about which the root's rotation turns the node's head.
    JointId rootJoint = kNoJoint;
    Vec3 rootPosition = Vec3::Zero();
    // Its head is its parent bone's tail (Blender's "Connected").
    bool connected = false;
    Vec3 head;  // placed and scaled
    Vec3 tail;
    // Where Blender is told the tail lies (COLLADA's tip, an end bone's
    // head): `tail`, except for a leaf bone whose tail lies on the part's
    // surface, pulled off it into the part along the bone (pullTailsOffSurface).
    // Our own tail hints (BoneTipHints.h) keep `tail`.
    Vec3 shownTail;
    // Global rest orientation (placed): +Y (or -Z, BoneAxes) along head -> tail.
    Eigen::Quaterniond restFrame = Eigen::Quaterniond::Identity();
    // Local rest transform, relative to the parent node (or to the Armature).
    Vec3 restTranslation;
    Eigen::Quaterniond restRotation = Eigen::Quaterniond::Identity();
    bool leaf = false;  // no child bone

    // The inverse bind matrix: world (placed) to this node's rest frame.
    Eigen::Affine3d inverseBind() const;
    // The tail in this node's rest frame.
    Vec3 localTail() const { return restFrame.conjugate() * (tail - head); }
    // Blender's roll of this frame (radians): the angle about the bone from
    // the frame without roll (+Y turned onto the bone by the shortest arc)
    // to restFrame; 0 for a bone without length.
    double roll() const;
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

// The end bone `<leaf>_end` of a leaf bone node: a joint without weights
// whose head is the leaf's shown tail and whose frame is the leaf's turned half a
// turn about an axis across the bone, so that its bone axis runs back along
// the leaf (tail = the leaf's head). Blender's glTF and FBX importers give
// an end bone its parent's length along its own axis (docs/EXCHANGE.md,
// "Leaf bones in Blender"): pointing on out of the limb, as Blender's own
// end bones do, it would end a leaf's length outside the surface; pointing
// back it lies inside, along the leaf, and the leaf keeps its length.
// `parent` and `bone` stay -1: the node is not one of the rig's bones.
ExportBoneNode endBoneOf(const ExportBoneNode& leaf);

// Which local axis of a bone node runs along the bone. Blender's glTF
// importer (3.4, default "Temperance" bone heuristic) points a bone at its
// child bones, snapped to the node's axes, and a leaf bone along its parent
// bone's choice; but a leaf bone with no parent bone keeps the node's local
// -Z (measured: +Y ones come out 90 degrees off). So for glTF a root leaf's
// frame runs along -Z; every other bone, and every bone in FBX and COLLADA,
// along +Y.
enum class BoneAxes { PlusY, GltfRootLeavesMinusZ };

// The placement must be rigid (rotation and translation); scale goes into
// unitScale. A bone's node is named after it (Part::boneNames, unchanged),
// else `<partName>_bone<id>`; names may repeat other parts' or nodes' (the
// scene builder makes them unique). Throws Error on a skeleton with no root.
ExportRig makeExportRig(const Part& part, const std::string& partName,
                        const Eigen::Affine3d& placement, double unitScale,
                        BoneAxes axes = BoneAxes::PlusY);

// A name safe in every format: letters, digits and '_' (others become '_'),
// never empty, not starting with a digit.
std::string sanitizedName(const std::string& name);

}  // namespace rigmesh
