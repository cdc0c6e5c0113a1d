// The rig of a part as JSON, so other tools can check it:
// {"joints": [{"id", "position": [x, y, z]}], "root": joint index,
//  "bones": [{"id", "head": joint index, "tail": joint index, "parent": bone index or -1,
//  "length"}], "mesh": the mesh file written with it (when given),
//  "vertex_count": n, "vertices": [[x, y, z] per mesh vertex],
//  "weights": [[[bone index, weight], ...] per mesh vertex],
//  "failed_bones": [...], "warning": "..."}
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
