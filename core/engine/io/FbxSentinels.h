// The post-export pass that repairs Assimp 5.2.5's binary FBX (docs/EXCHANGE.md,
// table row `fbx`): its FBXExportNode.cpp writes an empty string where the null
// record (block sentinel) belongs, after every node's nested list and after
// the top-level list, so Blender (and Assimp's own reader) fail with "failed
// to read nested block sentinel". Fixed upstream in Assimp 5.3.0.
//
// Binary FBX node record: end offset (absolute), property count, property
// list length, name length (1 byte), name, properties, then the nested
// records terminated by a null record: 13 zero bytes for versions < 7500
// (32-bit fields), 25 for >= 7500 (64-bit). The FBX SDK gives a node that
// nested list when it has children, has no properties, or is an
// AnimationStack or AnimationLayer (Assimp's reader needs the last two to
// keep the animation). The pass parses the records, inserts the missing null
// records by that rule and rewrites every end offset.
#pragma once

#include <cstdint>
#include <map>
#include <string>
#include <vector>

#include "base/Types.h"
#include "io/FbxRecords.h"

namespace rigmesh {

// True when the linked Assimp writes binary FBX without sentinels (< 5.3).
bool assimpNeedsFbxSentinelFix();

// Returns the file with a null record closing every nested list (by the rule
// above) and the top-level list; a file that already has them comes back unchanged.
// Whatever follows the top-level records (the footer) is kept as is. Throws
// Error if the bytes are not a binary FBX or a record is out of range.
std::vector<std::uint8_t> addFbxSentinels(const std::vector<std::uint8_t>& file);

// Adds a user property `property` of type Vector to the Properties70 of
// each Model named in `values` (our leaf bones' tails, which Assimp's reader
// hands back as node metadata and Blender shows as a custom property).
void addFbxModelVectors(FbxFile& fbx, const std::string& property,
                        const std::map<std::string, Vec3>& values);
// The same with a user property of type KString (our bones' names where
// the file's had to differ, BoneTipHints.h).
void addFbxModelStrings(FbxFile& fbx, const std::string& property,
                        const std::map<std::string, std::string>& values);

}  // namespace rigmesh
