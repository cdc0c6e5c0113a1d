// The post-export pass that lists each FBX skin's clusters parents first.
// Assimp 5.2.5's FBX exporter (FBXExporter.cpp) writes a mesh's clusters in
// the order of their bones' names (it keeps the skeleton in a set sorted by
// name), and the file's Connections give that order to every reader. Godot
// 3.2.3 imports FBX through its own Assimp and adds the bones to its Skeleton
// in that order, giving each the parent found among the bones added so far:
// a bone whose parent's name sorts after its own became a root and the
// character was deformed at rest (docs/EXCHANGE.md, rule 15). This pass moves
// the cluster-to-skin connections so that, within each skin, a cluster whose
// bone lies deeper in the node tree comes after every shallower one; the
// objects, ids and every other connection stay as they are.
#pragma once

#include <cstdint>
#include <vector>

#include "io/FbxRecords.h"

namespace rigmesh {

// A file without skins keeps its records.
void listFbxClustersParentsFirst(FbxFile& fbx);
// The same on a file's bytes; throws Error if they are not a binary FBX.
std::vector<std::uint8_t> withFbxClustersParentsFirst(const std::vector<std::uint8_t>& file);

}  // namespace rigmesh
