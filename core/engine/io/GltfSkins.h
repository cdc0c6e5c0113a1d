// One glTF skin per part. Assimp 5.2.5's glTF exporter
// writes a single skin listing every part's bones, so Blender's importer
// makes one armature of all parts (it puts the armature at the deepest
// common ancestor of a skin's joints). This pass gives each skinned mesh a
// skin of its own part's joints: the joints under the same non-joint
// ancestor (the part's `<part>_armature` node) as the joints the mesh is
// weighted to, their inverse bind matrices copied into a new accessor, and
// the mesh's JOINTS_0 renumbered in the buffer. Skins that cannot be split
// so (a mesh weighted to joints of two armature nodes, joint indices that
// are not 8- or 16-bit) are left as they are.
#pragma once

#include <string>

namespace rigmesh {

// The glTF JSON and its buffer 0 (`bin`, grown by the new inverse bind
// matrices) with one skin per armature node. Throws Error on JSON that is
// not glTF or accessors outside the buffer.
std::string withOneSkinPerArmature(const std::string& gltfJson, std::string& bin);

}  // namespace rigmesh
