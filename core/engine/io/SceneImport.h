// Importing meshes, skeletons, skin weights and a clip through Assimp (issue
// 6 item 2): whatever Assimp reads (.glb, .gltf, .fbx, .dae, .obj, .ply, ...).
// Assimp stays inside the .cpp files.
//
// Each mesh becomes a part (a mesh instanced on several nodes is taken once),
// its vertices in world space (the node's transform applied), vertices
// shared again by Assimp's JoinIdenticalVertices (so their order may differ
// from the exporter's). A skinned mesh gets a skeleton from the node
// hierarchy of its bones: every bone node's head is a joint (joints at the
// same place are one), its tail is the head of its first child bone, or its
// `<bone>_end` tip node anywhere in the file (SceneExport.h), or else half its parent's length
// further along its parent's direction (a tenth of the mesh's size up for a
// lone bone). The bind pose comes from the bones' offset (inverse bind)
// matrices. The first animation becomes a Clip of the part whose bones it
// moves. A mesh without bones imports with an empty skeleton and
// needsRig = true: it can be posed once rigged, which comes later.
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
};

struct ImportedScene {
    std::vector<ImportedPart> parts;
    // True if any part needs a rig; `message` then says which and why.
    bool needsRig = false;
    std::string message;
    // The file's first animation, for parts[clipPart].
    std::optional<Clip> clip;
    int clipPart = -1;
};

// Throws Error naming the file and the reason when it is missing, not a
// format Assimp reads, broken, or holds no triangle mesh.
ImportedScene importScene(const std::string& path);

}  // namespace rigmesh
