// A rigged part: the value every modelling operation takes and returns
// (paper sections 2-3): surface, skeleton and skin weights (an imported
// static mesh has no skeleton until it is auto-rigged: autorig/AutoRig.h), plus the per-vertex
// bookkeeping that local updates (cut, merge, bone edits) reuse.
#pragma once

#include <map>
#include <set>
#include <string>
#include <vector>

#include <Eigen/Geometry>

#include "mesh/TriMesh.h"
#include "part/BoneWeights.h"
#include "rig/Skeleton.h"
#include "surface/SketchSurface.h"

namespace rigmesh {

// One of the meshes an imported skeleton was shared by (several meshes bound
// to one armature come in as one part: ARCHITECTURE.md section 2e): the
// part's vertices and faces are the pieces' in order, each piece's faces
// using its own vertices only.
struct PartMeshPiece {
    std::string name;
    int vertexCount = 0;
    int faceCount = 0;
};

struct Part {
    std::string name;
    // The cleaned sketch polygon it was built from; empty once the part is no
    // longer one sketch (a merge, an import).
    std::vector<Vec2> outline;
    TriMesh mesh;
    // Per vertex: its sketch region and axis position. Only a fresh sketch
    // has them; any topology edit clears them rather than keep stale values.
    std::vector<VertexOrigin> origins;
    // Per vertex: its reflection through the sketch plane; empty once the
    // part is not mirror symmetric any more.
    std::vector<int> mirror;
    Skeleton skeleton;
    // Per vertex, keyed by stable bone id (never by position in
    // skeleton.bones(), which shifts when a bone goes), positive, summing to
    // 1. Solvers, skinning and exports convert at their boundary
    // (part/BoneWeights.h).
    SkinWeightsById weights;
    // Per vertex: the closest bone(s) by id known at creation (paper 2.4's
    // shortcut for cylindrical vertices); empty where visibility had to be
    // tested.
    ClosestBonesById knownClosestBones;
    // Bone names kept from an imported file: exported as
    // they are (made unique); a bone without one is `<part>_bone<id>`.
    std::map<BoneId, std::string> boneNames;
    // Rest orientations kept from an imported file: the axes of each bone's
    // node in the bind pose (Blender's bone axes and roll, or another
    // program's), exported as they are so that importers guess the same
    // tails, rolls and connections from them. A bone without one (sketched,
    // or moved by an edit) is exported with +Y along the bone.
    std::map<BoneId, Eigen::Quaterniond> boneFrames;
    // The meshes of a shared skeleton (empty: one mesh), exported as
    // separate meshes again. Any edit of the surface's topology clears it.
    std::vector<PartMeshPiece> meshPieces;
    // Bones whose weights painting and the weight clean-ups keep as they are:
    // an editing aid saved with the part, like Blender's
    // vertex group locks. Every id is a bone of the skeleton.
    std::set<BoneId> lockedBones;
    // True once the weights were edited by hand (paint, clean-ups): a
    // rebuild from the sketch would recompute them, so the studio asks first.
    // Merges and cuts keep it (they re-skin only near the seam).
    bool weightsPainted = false;
    // True for a surface read from another program's file (an import, as
    // it was): it may be open or non-manifold, which merge and cut refuse.
    // Every surface made here (sketch, merge, cut, auto-rig) is closed,
    // manifold and consistently oriented, and a document's reader checks it
    // (validateSolid) on every rigged part whose surface is not from a file.
    bool surfaceFromFile = false;

    // Bones as segments in the order of skeleton.bones().
    std::vector<BoneSegment> boneSegments() const;

    // Human-readable problems that make this part unusable (at most a
    // dozen); empty means valid: finite vertices, faces of three distinct
    // vertices in range, per-vertex tables of the right length with indices
    // in range, a skeleton that is a tree (or no skeleton at all, for an
    // unrigged import), and weights that name bones the skeleton has, are
    // finite, positive, sorted by bone id and sum to 1 for every vertex,
    // known closest bones and failed bones the skeleton has, bone names for
    // existing bones, non-empty and distinct, locked bones that exist, bone
    // frames of existing bones (finite unit quaternions), mesh pieces that
    // cover the mesh and keep their faces to their vertices. Every
    // operation that changes a
    // part checks its result with it; so does every reader of untrusted data.
    std::vector<Message> validate() const;
    // validate() plus what every modelling operation (merge, cut, bone edits)
    // must keep: a closed, manifold, consistently oriented surface and a
    // rigged one (imported meshes may be open, so validate() does not ask).
    std::vector<Message> validateSolid() const;
};

}  // namespace rigmesh
