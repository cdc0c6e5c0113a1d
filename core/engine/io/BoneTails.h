// Where each imported bone ends and which bones are connected to their
// parent (Blender's "Connected"), from what a file gives: bone heads and
// node axes (the bind pose), the node hierarchy, tails our exporter or
// Blender wrote (end bones, tail metadata, COLLADA tips and `connect`
// flags), and the vertices each bone weights. glTF, FBX and most game
// formats store no tails: they are guessed here as Blender's importers
// guess them, preferring the weighted vertices where those say more.
//
// The file's bone axis: programs lay a bone's node out with one local axis
// along the bone (Blender +Y; Maya and 3ds Max, e.g. DirectX files, +X).
// The signed axis along which most bones with children have a child is the
// file's bone axis when at least three quarters of them do.
//
// A bone's tail, most trusted first:
//  1. the head of a child the file flags as connected (COLLADA);
//  2. the tail the file states (our end bones and tail hints, Blender's
//     COLLADA tips);
//  3. with a bone axis, the nearest child lying on the bone's axis (its
//     continuation; other children are disconnected, as in Blender's files);
//     without one, the only child, or of several the one best in line with
//     them all (the direction Blender's glTF importer points a bone);
//  4. otherwise a guess: along the bone axis (without one: toward the
//     vertices the bone leads, else along its parent), as far as the
//     vertices it leads reach along that line (90th percentile), so the
//     bone lies inside its limb; failing that, as far as its nearest
//     child, its parent's length (Blender's guess for a leaf), or a tenth of
//     the mesh's size. A guess that leaves the surface (the reach of a
//     tapering or curving limb's vertices, measured along a straight bone)
//     while its head is inside is pulled back along the bone to where it
//     leaves, and 1e-4 of the size further in, so that importers such as
//     Blender show it inside by ray-cast parity as our own tails are
//     (docs/EXCHANGE.md, "Leaf bones in Blender").
// A guessed tail is never on the head: a bone the file gives no length (a
// glTF leaf, a child at its parent's head) is kept with a guessed one, since
// Blender cannot hold zero-length bones either.
// A child is connected when the file flags it so, or, without a flag, when
// its head is on its parent's tail (within 1e-5 of the mesh's size).
#pragma once

#include <optional>
#include <vector>

#include <Eigen/Geometry>

#include "base/Types.h"
#include "mesh/TriMesh.h"

namespace rigmesh {

struct TailBone {
    Vec3 head = Vec3::Zero();
    // The bind frame's axes (columns; scale taken out).
    Eigen::Matrix3d axes = Eigen::Matrix3d::Identity();
    int parent = -1;                  // index in the list (parents come first), -1: a root bone
    std::optional<Vec3> statedTail;   // step 2
    std::optional<bool> connectFlag;  // the file's "connected" flag, if it has one
};

struct BoneTailsResult {
    std::vector<Vec3> tails;
    // Per bone: its head is its parent's tail (false for root bones).
    std::vector<bool> connected;
    // The file's bone axis (0..5: +X, -X, +Y, -Y, +Z, -Z), or -1 for none.
    int boneAxis = -1;
};

// `mesh`'s vertices with `dominantBone` (per vertex, the index of the bone
// leading it, -1 for none); its faces, if any, are the surface guesses stay
// inside (inside by generalized winding number, autorig/SurfaceProbe);
// `size` the mesh's (or skeleton's) diagonal.
BoneTailsResult guessBoneTails(const std::vector<TailBone>& bones, const TriMesh& mesh,
                               const std::vector<int>& dominantBone, double size);

}  // namespace rigmesh
