// The rig of a part as JSON, so other tools can check it:
// {"about": how the file names joints and bones,
//  "joints": [{"id", "position": [x, y, z]}], "root": joint index, "root_id",
//  "bones": [{"id", "head": joint index, "tail": joint index,
//  "parent": bone index or -1, "head_id", "tail_id", "parent_id" (null for
//  none), "length"}], "mesh": the mesh file written with it (when given),
//  "vertex_count": n, "vertices": [[x, y, z] per mesh vertex],
//  "weights": [[[bone index, weight], ...] per mesh vertex],
//  "failed_bones": [bone index, ...], "warning": "..."}
// "head", "tail", "parent", "root", the weights and the failed bones name
// joints and bones by their position (from 0) in "joints" and "bones", as
// glTF's skins do; the "id" of each and the "*_id" fields are the stable
// ids the studio, documents and recipes use (Skeleton.h), which skip
// numbers once bones are deleted, so the two differ.
// Vertices and weights are in the part's mesh order, which every mesh file
// of one `rigmesh build` shares (OBJ, OFF, PLY, glTF, FBX, COLLADA), so a reader can pair them by
// index and check the pairing by position.
#pragma once

#include <array>
#include <cstdint>
#include <string>
#include <vector>

#include "part/Part.h"

namespace rigmesh {

// `meshFile` names the mesh file the weights go with (left out when empty).
std::string rigToJson(const Part& part, const std::string& meshFile = {});

// A colour per vertex from its dominant bone (distinct hues per bone), for
// showing weights in any mesh viewer (PLY vertex colours).
std::vector<std::array<std::uint8_t, 3>> dominantBoneColours(const Part& part);

}  // namespace rigmesh
