// Left-right mirror symmetry of a surface and its skeleton, as Blender's
// X-mirror uses it for weight painting and posing: the plane is found by a
// principal component analysis of the vertices (each principal axis, and each
// coordinate axis, a candidate normal through the centroid), refined by a
// reflection check in the manner of ICP (each vertex's reflection paired with
// the nearest vertex, the plane refitted to the pairs) and accepted when the
// reflected surface lies within a tolerance of the surface. Joints and bones
// are paired with the nearest one to their reflection.
#pragma once

#include <Eigen/Geometry>
#include <map>
#include <optional>

#include "base/Types.h"
#include "mesh/TriMesh.h"
#include "rig/Skeleton.h"

namespace rigmesh {

struct Part;

struct MirrorPlane {
    Vec3 point = Vec3::Zero();
    Vec3 normal = Vec3::UnitX();  // unit

    Vec3 reflect(const Vec3& p) const { return p - 2.0 * normal.dot(p - point) * normal; }
    Vec3 reflectDirection(const Vec3& d) const { return d - 2.0 * normal.dot(d) * normal; }
    // The rotation M R M, M the reflection: the same turn seen in the
    // mirror (its axis reflected, its sense reversed).
    Eigen::Quaterniond reflectRotation(const Eigen::Quaterniond& q) const;
};

struct MirrorSearch {
    // The largest mean distance of the reflected surface from the surface,
    // as a fraction of the bounding box diagonal, for a plane to count.
    double tolerance = 0.02;
    // The plane contains this axis (its normal is kept perpendicular to it):
    // a sketched part's left-right plane contains the sketch plane's normal
    // z, so its exact front-back symmetry through z = 0 is never chosen.
    std::optional<Vec3> containing;
};

struct MirrorFit {
    MirrorPlane plane;
    // The mean distance of the reflected surface from the surface over the
    // bounding box diagonal.
    double error = 0.0;
};

// The best mirror plane of `mesh` within the tolerance, if any (faces are
// used to measure distances to the surface; without faces, to the vertices).
std::optional<MirrorFit> findMirrorPlane(const TriMesh& mesh, const MirrorSearch& search = {});

// How far `mesh` reflected through `plane` lies from itself: the mean
// distance over the bounding box diagonal.
double mirrorError(const TriMesh& mesh, const MirrorPlane& plane);

// The distance within which a joint's reflection must find its image: a
// quarter of the mean bone length, or four times the surface's own mismatch
// (MirrorFit::error over a surface of this diagonal) if that is larger.
double mirrorJointTolerance(const Skeleton& skeleton, const MirrorFit& fit, double diagonal);

// Each joint's mirror image: the joint nearest its reflection when the two
// are each other's nearest and within `tolerance` (a length) of it; a joint
// on the plane is its own image. Joints without an image are left out.
std::map<JointId, JointId> mirrorJoints(const Skeleton& skeleton, const MirrorPlane& plane,
                                        double tolerance);

// Each bone's mirror image: the bone between its joints' images (itself when
// the bone lies across the plane or has no image).
std::map<BoneId, BoneId> mirrorBones(const Skeleton& skeleton,
                                     const std::map<JointId, JointId>& joints);

// The points of a sketch's outline (z = 0), its segments as degenerate
// triangles, as a mesh to look for the outline's own mirror in.
TriMesh outlinePoints(const std::vector<Vec2>& outline);

// A part's left-right symmetry: its plane, the joints' and bones' images.
// A sketched part (with its outline) mirrors about its outline's mirror
// line (a plane containing z; never its sketch plane z = 0, which is front
// and back); any other part about the best plane of its surface. None when
// the part has no such plane.
struct PartSymmetry {
    MirrorPlane plane;
    std::map<JointId, JointId> joints;
    std::map<BoneId, BoneId> bones;
    BoneId imageOf(BoneId bone) const {
        auto found = bones.find(bone);
        return found != bones.end() ? found->second : bone;
    }
};
std::optional<PartSymmetry> findPartSymmetry(const Part& part);

}  // namespace rigmesh
