#include "model/RigCarryOver.h"

#include "model/PartNode.h"

namespace rigmesh::model {
namespace {

// Joints of `from` that `to` still has: same id, about the same place.
std::set<JointId> survivingJoints(const Skeleton& from, const Skeleton& to) {
    double total = 0.0;
    for (const Bone& bone : from.bones())
        total += from.boneLength(bone.id);
    const double tolerance = from.boneCount() > 0 ? 0.25 * total / from.boneCount() : 0.0;
    std::set<JointId> kept;
    for (const Joint& joint : from.joints())
        if (to.hasJoint(joint.id) &&
            (to.joint(joint.id).position - joint.position).norm() <= tolerance)
            kept.insert(joint.id);
    return kept;
}

rigmesh::Pose filtered(const rigmesh::Pose& pose, const std::set<JointId>& kept, bool rootKept) {
    rigmesh::Pose out;
    for (const auto& [joint, rotation] : pose.rotations)
        if (kept.contains(joint))
            out.rotations[joint] = rotation;
    if (rootKept)
        out.rootTranslation = pose.rootTranslation;
    return out;
}

std::vector<const rigmesh::Clip*> clipPointers(const rigmesh::Clip& clip,
                                               const std::vector<rigmesh::Clip>& others) {
    std::vector<const rigmesh::Clip*> out{&clip};
    for (const rigmesh::Clip& other : others)
        out.push_back(&other);
    return out;
}

rigmesh::Clip filteredClip(const rigmesh::Clip& clip, const std::set<JointId>& kept,
                           bool rootKept) {
    rigmesh::Clip out = emptiedClip(clip);
    for (const auto& [time, key] : clip.keys())
        out.insertExactKey(time, filtered(key, kept, rootKept));
    return out;
}

}  // namespace

CarriedRig carryRigOver(const Skeleton& from, const Skeleton& to, const rigmesh::Pose& pose,
                        const std::set<JointId>& pinned, const rigmesh::Clip& clip,
                        const std::vector<rigmesh::Clip>& otherClips) {
    const std::set<JointId> kept = survivingJoints(from, to);
    const bool rootKept = from.root() == to.root() && kept.contains(from.root());

    // Every joint the user touched: posed, pinned or keyed.
    std::set<JointId> touched(pinned.begin(), pinned.end());
    for (const auto& [joint, rotation] : pose.rotations)
        touched.insert(joint);
    for (const rigmesh::Clip* keyed : clipPointers(clip, otherClips))
        for (const auto& [time, key] : keyed->keys())
            for (const auto& [joint, rotation] : key.rotations)
                touched.insert(joint);

    CarriedRig out;
    out.pose = filtered(pose, kept, rootKept);
    for (JointId joint : pinned)
        if (kept.contains(joint))
            out.pinned.insert(joint);
    out.clip = filteredClip(clip, kept, rootKept);
    for (const rigmesh::Clip& other : otherClips)
        out.otherClips.push_back(filteredClip(other, kept, rootKept));
    for (JointId joint : touched)
        (kept.contains(joint) ? out.keptJoints : out.droppedJoints) += 1;
    return out;
}

PartNode editedNode(const PartNode& from, std::shared_ptr<const Part> part, int* droppedJoints) {
    PartNode node = from;
    node.stroke.clear();
    node.part = std::move(part);
    const CarriedRig carried = carryRigOver(from.part->skeleton, node.part->skeleton, from.pose,
                                            from.pinnedJoints, from.clip, from.otherClips);
    node.pose = carried.pose;
    node.pinnedJoints = carried.pinned;
    node.clip = carried.clip;
    node.otherClips = carried.otherClips;
    if (droppedJoints)
        *droppedJoints = carried.droppedJoints;
    return node;
}

}  // namespace rigmesh::model
