// The names of a clip's interpolation and playback modes in files and
// recipes: "constant" / "linear" / "smooth" and "hold" / "loop" / "ping_pong"
// (the last of each since document format version 2).
#pragma once

#include <optional>
#include <string_view>

#include "pose/Clip.h"

namespace rigmesh::model {

const char* interpolationName(rigmesh::Interpolation interpolation);
const char* playbackName(rigmesh::PlaybackMode mode);
// nullopt for any other name.
std::optional<rigmesh::Interpolation> interpolationFromName(std::string_view name);
std::optional<rigmesh::PlaybackMode> playbackFromName(std::string_view name);

}  // namespace rigmesh::model
