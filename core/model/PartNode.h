// One part of a document: the immutable engine value plus what the document
// adds around it (stable id, user name, placement, visibility, the raw stroke
// and options it was built from, so it can be rebuilt, and its current pose
// with the joints pinned for IK, and its animation clip).
#pragma once

#include <Eigen/Geometry>
#include <QString>
#include <cstdint>
#include <memory>
#include <set>
#include <vector>

#include "base/Types.h"
#include "part/Part.h"
#include "pose/Clip.h"
#include "pose/Pose.h"

namespace rigmesh::model {

// Stable part id: assigned once, never changed. Ids start at 1.
using PartId = std::uint32_t;
inline constexpr PartId kNoPart = 0;

// The user-facing build options of a part (what the properties panel edits).
struct BuildOptions {
    double targetEdgeLength = 0.0;  // 0 = automatic (the cleaned outline's spacing)
    bool smoothing = true;          // Least-Squares Meshes smoothing of the surface
    // A symmetric outline's joints mirrored (rig/SkeletonSymmetry). Off for
    // parts of recipes and documents made before it existed, so that they
    // replay and rebuild to the skeleton they were made with.
    bool mirrorJoints = true;

    friend bool operator==(const BuildOptions&, const BuildOptions&) = default;
};

// Where a part sits in the scene: p_world = rotation * p_part + translation.
struct Placement {
    Vec3 translation = Vec3::Zero();
    Eigen::Quaterniond rotation = Eigen::Quaterniond::Identity();

    Vec3 toWorld(const Vec3& local) const { return rotation * local + translation; }
    Vec3 toLocal(const Vec3& world) const { return rotation.conjugate() * (world - translation); }
    // A direction (no translation) from the world into the part.
    Vec3 directionToLocal(const Vec3& world) const { return rotation.conjugate() * world; }
    Eigen::Affine3d affine() const { return Eigen::Translation3d(translation) * rotation; }

    friend bool operator==(const Placement& a, const Placement& b) {
        return a.translation == b.translation && a.rotation.coeffs() == b.rotation.coeffs();
    }
};

struct PartNode;
// The box around the part's surface placed in the scene (empty without a part).
Eigen::AlignedBox3d worldBounds(const PartNode& node);

struct PartNode {
    PartId id = kNoPart;
    QString name;
    // Never mutated once shared: edits build a new Part and swap the pointer.
    std::shared_ptr<const Part> part;
    std::vector<Vec2> stroke;  // the raw sketch, as drawn
    BuildOptions options;
    Placement placement;
    bool visible = true;
    // The current pose of the part's skeleton. Every joint id in it is a joint
    // of part->skeleton; a joint not in it is at its rest (identity) rotation,
    // so a default Pose is the rest pose too.
    rigmesh::Pose pose;
    // Joints that IK keeps in place (all joints of part->skeleton).
    std::set<rigmesh::JointId> pinnedJoints;
    // Keyframed poses of this part (every joint id in every key is a joint of
    // part->skeleton). A new part has no keys at 24 frames per second.
    // This is the part's active clip: the one keyed, played and posed from.
    rigmesh::Clip clip = rigmesh::Clip();  // (Clip's default constructor is explicit)
    // The part's other named clips ("idle", "walk"), sorted by name;
    // every clip name of the part (clipName) is unique (PartClips.h).
    std::vector<rigmesh::Clip> otherClips;
};

// The rest pose of a node: restPose(skeleton), or an empty Pose without a part.
rigmesh::Pose restPoseOf(const PartNode& node);
// Exact (bitwise value) equality: same joints, same quaternion coefficients,
// same root translation.
bool identicalPoses(const rigmesh::Pose& a, const rigmesh::Pose& b);
// Exact equality of clips: name, frame rate, interpolation, playback mode and
// every key (bitwise time, identicalPoses).
bool identicalClips(const rigmesh::Clip& a, const rigmesh::Clip& b);
// The clip without its keys: the same name, frame rate and modes.
rigmesh::Clip emptiedClip(const rigmesh::Clip& clip);
// The user-facing name of a joint ("Joint 3").
QString jointDisplayName(rigmesh::JointId joint);

}  // namespace rigmesh::model
