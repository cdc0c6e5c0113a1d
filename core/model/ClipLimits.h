// Bounds on a clip that keep what is derived from it small: an exported
// Smooth clip is baked once per frame between its first and last key, so a
// span of a billion frames (a key at 1e9 s, or 1e9 frames per second) would
// allocate gigabytes from a few bytes of input.
#pragma once

#include <string>

#include "pose/Clip.h"

namespace rigmesh::model {

// Over an hour at 24 frames per second.
inline constexpr double kMaxClipFrames = 100000;

// The frames between the first and last key at the clip's rate (0 without keys).
double clipSpanFrames(const rigmesh::Clip& clip);
// Throws rigmesh::Error naming `owner` when clipSpanFrames(clip) > kMaxClipFrames.
void checkClipSpan(const rigmesh::Clip& clip, const std::string& owner);

}  // namespace rigmesh::model
