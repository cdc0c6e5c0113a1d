// The skinning type of an exported FBX's skin deformers. An FBX Skin
// deformer carries `SkinningType`: "Linear", "DualQuaternion", "Blend" (a
// per-vertex mix) or "Rigid"; Maya's FBX importer sets its skinCluster's
// skinning method from it. Assimp 5.2.5's exporter has no option for it: its
// FBXExporter.cpp writes `SkinningType: "Linear"` on every Skin deformer
// (marked "TODO: other modes?"), so this post-export pass rewrites that
// record. Blender 3.4.1's FBX importer reads no skinning type
// (docs/EXCHANGE.md, "Skinning in Blender").
#pragma once

#include <cstdint>
#include <string>
#include <vector>

#include "io/FbxRecords.h"
#include "pose/Skinning.h"

namespace rigmesh {

// The FBX name of a skinning method: "Linear" or "DualQuaternion".
const char* fbxSkinningTypeName(SkinningMethod method);

// Sets `SkinningType` to `method` on every Skin deformer of the parsed file
// (replacing the one there, else adding it).
void setFbxSkinningType(FbxFile& fbx, SkinningMethod method);
// The same on a binary FBX's bytes (written back sentinel-complete). Throws
// Error if the bytes are not a binary FBX.
std::vector<std::uint8_t> withFbxSkinningType(const std::vector<std::uint8_t>& file,
                                              SkinningMethod method);

// Each Skin deformer's `SkinningType` in file order ("" for a deformer
// without one). Throws Error if the bytes are not a binary FBX.
std::vector<std::string> fbxSkinningTypes(const std::vector<std::uint8_t>& file);

}  // namespace rigmesh
