// The file formats exportScene writes, chosen by the path's extension,
// and what each allows: skin influences per vertex and whether it
// carries a skeleton and an animation at all.
#pragma once

#include <string>

namespace rigmesh {

enum class ExportFormat { Glb, Gltf, Fbx, Collada, Obj };

// Case-insensitive: .glb, .gltf, .fbx, .dae, .obj. Throws Error naming the
// extensions we write otherwise.
ExportFormat exportFormatFromPath(const std::string& path);

// True for the formats that carry a skeleton, skin weights and a clip.
bool isRiggedFormat(ExportFormat format);

// The most influences per vertex the format (as Assimp 5.2.5 writes it)
// keeps: 4 for glTF (JOINTS_0/WEIGHTS_0 only), 0 = no limit otherwise.
int formatInfluenceLimit(ExportFormat format);

// How many influences to keep for a requested maximum (0 = all the format
// allows): the smaller of the two limits, 0 meaning unlimited.
int effectiveInfluenceLimit(ExportFormat format, int requested);

}  // namespace rigmesh
