// The post-export pass that keeps an FBX clip's keys as they are. Assimp
// 5.2.5's FBX exporter writes each rotation key as Euler angles in degrees
// (aiMatrix4x4::Decompose, each angle in [-180, 180]), so a bone turning
// smoothly past an angle's end jumps by nearly 360 degrees between two keys.
// Assimp's FBX reader (and Blender's) interpolate Euler curves linearly:
// Assimp inserts keys of its own wherever an angle changes by 180 degrees or
// more between two keys (measured: a three-key clip came back with five),
// and an animation player would turn the long way round. This pass rewrites
// every rotation curve's values so that each key's angles are, of the
// equivalent triples (x + 360a, y + 360b, z + 360c) and
// (x + 180, 180 - y, z + 180) + 360(a, b, c), the one nearest the key
// before: the same rotation at every key, the shortest turn between keys.
#pragma once

#include <cstdint>
#include <vector>

#include "io/FbxRecords.h"

namespace rigmesh {

// Curves other than the X, Y, Z curves of a rotation ("R") curve node, and
// arrays stored compressed, are left as they are.
void makeFbxRotationsContinuous(FbxFile& fbx);
// The same on a file's bytes; throws Error if they are not a binary FBX.
std::vector<std::uint8_t> withContinuousFbxRotations(const std::vector<std::uint8_t>& file);

}  // namespace rigmesh
