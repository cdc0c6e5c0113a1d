// Disconnected bones and the RigMesh edits (paper 3.1-3.3). Cutting and
// merging rebuild a part's skeleton as one connected tree (joining pieces,
// snapping joints), so they refuse a skeleton with disconnected bones
// (Skeleton.h) and name the bone; Edit > Connect Bone connects it first, as
// Blender's "Connected" does: the bone's head moves onto its parent's tail.
// Splitting and deleting a bone work on any skeleton (Skeleton::splitBone
// and collapseBone carry the attachments).
#pragma once

#include <optional>
#include <string>

#include "part/Part.h"

namespace rigmesh {

// The first bone (hierarchy order) whose head is an attached chain's root
// (a disconnected bone, or a further root chain's bone); none for a
// connected tree.
std::optional<BoneId> firstDisconnectedBone(const Skeleton& skeleton);

// The bone's name for messages: its kept name in quotes, else its id.
std::string boneLabel(const Part& part, BoneId bone);

// Throws Error(BoneNotConnected) naming the first disconnected bone.
void requireConnectedSkeleton(const Part& part);

// The part with `bone`'s head joined to its parent bone's tail (for a bone
// of a further root chain: to the nearest joint of the chains it does not
// carry), so the bone and the others leaving that head are connected. Every
// bone leaving the head now starts there; the surface, the weights and the
// other joints stay; the moved bones lose their kept frames. Throws Error
// for an unknown bone, a bone already connected or a bone at the root.
Part connectBone(const Part& part, BoneId bone);

}  // namespace rigmesh
