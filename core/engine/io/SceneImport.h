// Importing meshes, skeletons, skin weights and a clip through Assimp:
// whatever Assimp reads (.glb, .gltf, .fbx, .dae, .obj, .ply, ...).
// Assimp stays inside the .cpp files.
//
// Each mesh becomes a part (a mesh instanced on several nodes is taken once),
// named after its node (else its mesh), its vertices in world space: a
// skinned mesh where its bones' nodes and offset matrices put it (as glTF
// and Blender do), another by its node's transform; in metres (an FBX's
// UnitScaleFactor applied; Assimp applies COLLADA's unit; COLLADA nodes by
// their names, not ids). Bone names are kept (Part::boneNames) when
// distinct, and the animation's name (Blender's FBX `Rig|Wave` -> `Wave`)
// as the clip's. vertices
// shared again by Assimp's JoinIdenticalVertices (so their order may differ
// from the exporter's). A skinned mesh gets a skeleton from the node
// hierarchy of its bones: every bone node's head is a joint (joints at the
// same place are one, within 1e-5 of the mesh's size), its tail is the head
// of its first child bone, or of its end bone (`<bone>_end` without weights:
// ours with leafBones, Blender's FBX "Add Leaf Bones"), or a `<bone>_end`
// node anywhere (our older exports), or our tail hint (glTF
// extras, FBX user property, BoneTipHints.h), or Blender's COLLADA tip
// extra; else, as Blender guesses, along the bone node's +Y as long as its
// parent (a tenth of the mesh's size for a lone bone). End bones are not
// bones of the part. The bind pose comes from the bones'
// offset (inverse bind) matrices. Each animation becomes the Clip of the first part whose
// bones it moves (one per part). A mesh without bones imports with an empty skeleton and
// needsRig = true: it can be posed once rigged (autorig/AutoRig).
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
    // The first animation of the file that moves this part's bones.
    std::optional<Clip> clip;
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
