// The last check before an aiScene is handed to Assimp's exporters: every
// number that will be written is finite (key times of 1e308 once put
// Infinity into a .glb). Internal to io/: the header only forward-declares
// Assimp.
#pragma once

struct aiScene;

namespace rigmesh {

// Throws Error naming the first non-finite vertex, normal, bone weight or
// offset, node transform or animation key.
void checkSceneIsFinite(const aiScene& scene);

}  // namespace rigmesh
