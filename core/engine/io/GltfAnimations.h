// The animations of a glTF export, written by us into the JSON and buffer 0
// that Assimp's exporter made without them. Assimp 5.2.5's glTF exporter
// appends every accessor by reallocating the whole buffer to its exact new
// size (glTF2Asset.inl, Buffer::Grow), so its time was the buffer's size
// times the number of accessors: a smooth clip of the biped (10 bones) with
// 20,000 keys took tens of seconds, nearly all of it copying. Here every
// sample is written once, into a buffer grown geometrically, and the
// translation, rotation and scale samplers of a bone node share one time
// accessor (Assimp wrote three), so the export is linear in the keys.
#pragma once

#include <string>
#include <vector>

struct aiAnimation;

namespace rigmesh {

// The glTF JSON with one glTF animation per `animations` entry, named as it
// is: per channel, LINEAR samplers for translation, rotation and scale
// keyed at the channel's times (in seconds: mTicksPerSecond is 1,
// docs/EXCHANGE.md rule 4) on the node of the channel's name. Their accessors (float
// SCALAR input with min and max, VEC3 / VEC4 outputs) go at the end of
// `bin`, 4-byte aligned. Throws Error on JSON that is not glTF or a channel
// whose node the JSON does not have.
std::string withGltfAnimations(const std::string& gltfJson, std::string& bin,
                               const std::vector<const aiAnimation*>& animations);

}  // namespace rigmesh
