// Importing meshes, skeletons, skin weights and clips through Assimp:
// whatever Assimp reads (.glb, .gltf, .fbx, .dae, .x, .mdl, .smd,
// .md5mesh, .obj, .ply, ...). Assimp stays inside the .cpp files.
//
// Every rig a file holds comes in whole (ARCHITECTURE.md section 2e):
// - The skinned meshes sharing one skeleton (AssimpRigImport.h:
//   groupBySkeleton) become one part whose mesh is theirs one after the
//   other, kept as Part::meshPieces when there are several (exported as
//   separate meshes again); it is named after its first mesh's node (the
//   object a user named), else its mesh. Every other mesh becomes an
//   unrigged part of its own (a mesh instanced on several nodes is taken
//   once), with needsRig.
// - Vertices in world space: a skinned mesh where its bones' nodes and offset
//   matrices put it (as glTF and Blender do), another by its node's
//   transform; in metres (an FBX's UnitScaleFactor applied; Assimp applies
//   COLLADA's unit; COLLADA nodes by their names, not ids); shared again by
//   Assimp's JoinIdenticalVertices (so their order may differ from the
//   exporter's).
// - Bones: every bone the meshes name (by node; a bone naming no node is a
//   root bone at its bind place that never moves), the nodes between two of
//   them (as Blender makes them), bones weighting no vertex and bones outside
//   the skin alike. End bones (`<bone>_end` without weights: ours with
//   leafBones, Blender's FBX "Add Leaf Bones") only mark their parent's tail.
//   The bind pose comes from the offset (inverse bind) matrices; each bone's
//   bind axes are kept (Part::boneFrames). Tails and connections as
//   BoneTails.h says (the file's connect flags and tails first, then the
//   file's bone axis and children, then the weighted vertices). A connected
//   bone's head is its parent's tail joint; disconnected children of one
//   bone starting at one place share a joint attached to it; root bones at
//   the first one's head share the root joint; other root bones start
//   further root chains (Skeleton.h). Bone names are kept
//   (Part::boneNames) when distinct.
// - Every animation that moves a part's bones becomes one of its clips,
//   named after the animation (Blender's FBX `Rig|Wave` -> `Wave`), keys at
//   the file's key times (in seconds), the rate the first common one that
//   puts them on frames (AssimpBoneHints.h: clipRate), linear.
// A mesh without bones imports with an empty skeleton and needsRig = true:
// it can be posed once rigged (autorig/AutoRig).
#pragma once

#include <optional>
#include <string>
#include <vector>

#include "part/Part.h"
#include "pose/Clip.h"

namespace rigmesh {

struct ImportedPart {
    Part part;  // outline, origins, mirror and known closest bones stay empty
    // Per bone index (part.skeleton.bones() order): the bone's node name.
    std::vector<std::string> boneNames;
    bool needsRig = false;  // no usable skeleton or weights
    // Every animation of the file that moves this part's bones, in the
    // file's order, each named after its animation.
    std::vector<Clip> clips;
};

struct ImportedScene {
    std::vector<ImportedPart> parts;
    // True if any part needs a rig; `message` then says which and why.
    bool needsRig = false;
    std::string message;
};

// Throws Error naming the file and the reason when it is missing, not a
// format Assimp reads, broken, or holds no triangle mesh.
ImportedScene importScene(const std::string& path);

}  // namespace rigmesh
