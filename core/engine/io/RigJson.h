// The rig of a part as JSON, so other tools can check it:
// {"joints": [{"id", "position": [x, y, z]}], "root": joint index,
//  "bones": [{"id", "head": joint index, "tail": joint index, "parent": bone index or -1,
//  "length"}], "weights": [[[bone index, weight], ...] per mesh vertex, in mesh order],
//  "failed_bones": [...], "warning": "..."}
#pragma once

#include <array>
#include <cstdint>
#include <string>
#include <vector>

#include "part/Part.h"

namespace rigmesh {

std::string rigToJson(const Part& part);

// A colour per vertex from its dominant bone (distinct hues per bone), for
// showing weights in any mesh viewer (PLY vertex colours).
std::vector<std::array<std::uint8_t, 3>> dominantBoneColours(const Part& part);

}  // namespace rigmesh
