// A skeleton (paper section 2.3): joints connected by bones, meant to form a
// tree hanging from a root joint. Joints and bones carry stable ids drawn from
// per-skeleton counters: an id is never reused, and the ids of surviving
// joints and bones never change when others are removed or collapsed. Dense
// indices (indexOfJoint/indexOfBone) are what solvers use; they follow the
// stable order of joints() and bones() and do change on removal.
//
// Disconnected bones (Blender's bones without "Connected": a Rigify thigh off
// the pelvis, a shoulder off the spine; ARCHITECTURE.md section 2e): the joint
// graph may be a forest of connected chains. The root joint of every chain
// but the root's own is *attached*: to a parent bone, whose frame its head
// follows rigidly (posing it moves and turns the chain as Blender moves a
// disconnected child), or to no bone (kNoBone), a further root chain that
// follows the skeleton's root transform as Blender's root bones follow their
// armature object. Sketched and auto-rigged skeletons have no attachments:
// one connected tree, as before.
//
// Structural edits may leave the skeleton in any shape; validate() says what
// keeps it from being a tree of chains, and reorient() makes every bone point
// away from its chain's root once it is one.
#pragma once

#include <cstdint>
#include <limits>
#include <map>
#include <optional>
#include <string>
#include <unordered_map>
#include <vector>

#include "base/Message.h"
#include "base/Types.h"

namespace rigmesh {

using JointId = std::uint32_t;
using BoneId = std::uint32_t;

inline constexpr JointId kNoJoint = std::numeric_limits<JointId>::max();
// In attachments(): the chain hangs from no bone (a further root chain).
inline constexpr BoneId kNoBone = std::numeric_limits<BoneId>::max();

struct Joint {
    JointId id;
    Vec3 position;
};

// After reorient(), head is the joint nearer the root.
struct Bone {
    BoneId id;
    JointId head, tail;
};

class Skeleton {
  public:
    // Rebuilds a skeleton from stored parts (file loading, undo) keeping their
    // ids. Nothing is checked here: call validate() on the result.
    static Skeleton restore(std::vector<Joint> joints, std::vector<Bone> bones, JointId root,
                            std::map<JointId, BoneId> attachments = {});

    // The first joint added becomes the root until setRoot() says otherwise.
    JointId addJoint(const Vec3& position);
    // Throws Error if either joint is unknown or head == tail.
    BoneId addBone(JointId head, JointId tail);

    void setJointPosition(JointId id, const Vec3& position);

    // Removes the bone only; its joints stay, possibly splitting the tree.
    // Chains attached to it hang from its parent bone instead.
    void removeBone(BoneId id);
    // Removes the joint and every bone touching it (chains attached to those
    // bones as removeBone says). If it was the root, the first remaining joint
    // becomes the root.
    void removeJoint(JointId id);
    // Merges the bone's two joints into its head, moved to mergedPosition:
    // bones touching the tail are rewired to the head, the bone itself (and
    // any other bone between the same two joints) disappears. Used to remove
    // short bones inside connecting regions (paper 2.3, Fig. 6 (b)). Chains
    // attached to it hang from its parent bone instead; the head keeps its
    // own attachment.
    void collapseBone(BoneId id, const Vec3& mergedPosition);

    // Inserts a joint at `position` on the bone (paper 3.2 "split", 3.3): the
    // bone keeps its id and now ends at the new joint; a new bone runs from
    // there to the old tail. A chain attached to the bone stays with the half
    // nearer its head. Returns the new joint.
    JointId splitBone(BoneId id, const Vec3& position);
    // Joint `gone` becomes `keep`: every bone touching it is rewired, it is
    // removed (paper 3.2 "snap": two skeletons joined at coincident joints).
    // `keep` keeps its attachment; `gone`'s is dropped (its chain is now
    // connected there).
    void mergeJoints(JointId keep, JointId gone);

    // Disconnected bones: `joint`, the root joint of a chain, hangs from
    // bone `parent` (kNoBone: from no bone, a further root chain). Throws
    // Error for an unknown joint or bone, or the skeleton's root.
    void attach(JointId joint, BoneId parent);
    // The joint is no longer attached (its chain is loose until connected).
    void detach(JointId joint);
    // Attached joints and the bone each hangs from (kNoBone: none).
    const std::map<JointId, BoneId>& attachments() const { return attachments_; }
    bool isAttached(JointId joint) const { return attachments_.contains(joint); }
    // True when no chain hangs from another: one connected tree (every
    // sketched or auto-rigged skeleton).
    bool isConnectedTree() const { return attachments_.empty(); }
    // Chain roots attached to this bone.
    std::vector<JointId> attachedTo(BoneId bone) const;

    void setRoot(JointId id);
    JointId root() const { return root_; }  // kNoJoint only when there are no joints
    // Flips bones so that every head is nearer the root than its tail (by
    // breadth-first order from the root). Bones not reachable from the root
    // keep their direction. Call after structural edits.
    void reorient();
    bool isOrientedFromRoot() const;

    const std::vector<Joint>& joints() const { return joints_; }  // in order of creation
    const std::vector<Bone>& bones() const { return bones_; }     // in order of creation
    int jointCount() const { return static_cast<int>(joints_.size()); }
    int boneCount() const { return static_cast<int>(bones_.size()); }
    bool hasJoint(JointId id) const { return jointIndex_.contains(id); }
    bool hasBone(BoneId id) const { return boneIndex_.contains(id); }
    // The lookups below throw Error on an unknown id.
    const Joint& joint(JointId id) const { return joints_[indexOfJoint(id)]; }
    const Bone& bone(BoneId id) const { return bones_[indexOfBone(id)]; }
    int indexOfJoint(JointId id) const;
    int indexOfBone(BoneId id) const;

    // The bone whose tail is this bone's head, or the bone its head is
    // attached to; none for bones at the root or a root chain's root.
    std::optional<BoneId> parentBone(BoneId id) const;
    // Whether the bone's head is its parent bone's tail (Blender's
    // "Connected"); false for root bones.
    bool isConnected(BoneId id) const;
    // The bones whose head is this joint (their tails are its child joints).
    std::vector<BoneId> childrenOf(JointId id) const;
    // Every bone touching this joint, whatever its direction.
    std::vector<BoneId> bonesAt(JointId id) const;
    int degree(JointId id) const;
    double boneLength(BoneId id) const;
    // Bones reachable from the root, each after its parent bone (breadth
    // first through bones, then the chains attached to each bone): the
    // order forward kinematics needs.
    std::vector<BoneId> bonesInHierarchyOrder() const;

    // The problems (base/MessageCatalogValidation.cpp) keeping this from being a valid tree of
    // chains: no joints, missing or duplicate ids, a bad root, non-finite
    // positions, self-loops, zero-length bones (relative to the skeleton's
    // size), cycles, a chain other than the root's hanging from nothing,
    // bad attachments (unknown joint or bone, the root attached, two in one
    // chain, a chain hanging from itself or chains hanging from each other
    // in a loop). Empty means valid.
    std::vector<Message> validate() const;

  private:
    void rebuildIndex();
    // Chains attached to `gone` hang from `instead` (kNoBone: from none).
    void reattach(BoneId gone, BoneId instead);

    std::vector<Joint> joints_;
    std::vector<Bone> bones_;
    std::unordered_map<JointId, int> jointIndex_;
    std::unordered_map<BoneId, int> boneIndex_;
    std::map<JointId, BoneId> attachments_;
    JointId root_ = kNoJoint;
    JointId nextJointId_ = 0;
    BoneId nextBoneId_ = 0;
};

// The bone a joint stands for when a tool or view needs one (the weight
// views, the paint tool): the bone ending at it, or, at the root, its first
// child bone; none for an unknown joint or a lone root.
std::optional<BoneId> boneForJoint(const Skeleton& skeleton, JointId joint);

// The graph centre by bone lengths: the joint minimising the longest path to
// any other joint. Ties prefer joints of degree >= 3, then the earlier joint.
// On a disconnected skeleton, the centre of the component with the most
// joints. Throws Error on an empty skeleton.
JointId chooseCentralRoot(const Skeleton& skeleton);

}  // namespace rigmesh
