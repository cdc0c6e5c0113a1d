// Lifts the children of Assimp's root node into the glTF scene. Assimp 5.2.5's glTF exporter writes
// its one root node as the scene's only root, so Blender shows it as a stray empty `RootNode` and
// the skinned mesh is never a root node (the validator's NODE_SKINNED_MESH_NON_ROOT: a skinned
// mesh's parent transforms are ignored). Our root is always the identity (SceneExport.h), so its
// children can be the scene's roots instead, with the same world transforms.
#pragma once

#include <string>

namespace rigmesh {

// The glTF JSON with scene 0's single root node removed and its children
// made the scene's roots, every node index (children, skins, animation
// targets, scenes) renumbered. Unchanged when the scene has several roots or
// the root has a transform, a mesh, a skin or a camera. Throws Error on JSON
// that is not glTF.
std::string withRootChildrenAsSceneRoots(const std::string& gltfJson);

}  // namespace rigmesh
