// Clips as an aiAnimation following docs/EXCHANGE.md rules 4
// and 5: mTicksPerSecond = 1 with key times in seconds, and every bone node a
// channel with position, rotation and scaling keys at the same times. One
// animation may animate several rigs, each by its own clip (the clips of
// several parts sharing a name).
// Internal to io/: the header only forward-declares Assimp.
#pragma once

#include <string>
#include <vector>

#include "io/ExportRig.h"
#include "pose/Clip.h"

struct aiAnimation;

namespace rigmesh {

// Most samples written between two keys of a Smooth clip.
constexpr int kMaxFramesPerSegment = 64;

// The times written, ascending: the key times for a Linear clip (viewers
// interpolate linearly between them too); for a Smooth or Constant clip also
// every frame between two keys (at most kMaxFramesPerSegment evenly spaced
// samples in a longer segment), so that the curve between keys survives (a
// Constant clip's step then happens within the frame before the next key).
// At most (kMaxFramesPerSegment + 1) times per key, whatever the clip's length.
std::vector<double> exportedKeyTimes(const Clip& clip);

// One rig animated by one clip.
struct AnimatedRig {
    const Clip* clip = nullptr;
    const ExportRig* rig = nullptr;
};

// Throws Error on no rigs or a clip without keys.
aiAnimation* makeAnimation(const std::vector<AnimatedRig>& rigs, const std::string& name);

// Each channel's position and scaling keys cut to the first where all are
// equal (a bone's fixed offset, unit scale): FBX keeps a curve per
// component, so a smooth clip's constant curves were two thirds of the file.
// For FBX only: it stores each curve with its own times (and Blender reads a
// one-key curve as constant), while COLLADA needs the same times on every
// channel (docs/EXCHANGE.md rule 5).
void keepConstantChannelsAsOneKey(aiAnimation& animation);

}  // namespace rigmesh
