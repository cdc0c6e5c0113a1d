// A part's named clips: the active one (PartNode::clip) and the
// others (PartNode::otherClips, sorted by name). A clip read from an older
// file or made without a name is called "Action" (Blender's name for a new
// action); names are unique within a part, so a clip is addressed by
// (part, name) in commands and recipes.
#pragma once

#include <set>
#include <string>
#include <vector>

#include "model/PartNode.h"
#include "pose/Clip.h"

namespace rigmesh::model {

inline constexpr const char* kDefaultClipName = "Action";
inline constexpr std::size_t kMaxClipNameLength = 63;

// The clip's name, or kDefaultClipName when it has none.
std::string clipName(const rigmesh::Clip& clip);
// The active clip and the others, sorted by name.
std::vector<const rigmesh::Clip*> clipsOf(const PartNode& node);
// The clip of that name (clipName), or nullptr.
const rigmesh::Clip* findClip(const PartNode& node, const std::string& name);
// Throws rigmesh::Error unless the name is 1 to kMaxClipNameLength bytes
// without control characters or surrounding spaces.
void checkClipName(const std::string& name);
// Throws rigmesh::Error when two of the clips share a name.
void checkClipNamesUnique(const rigmesh::Clip& active, const std::vector<rigmesh::Clip>& others);
// A name checkClipName takes, made from `wanted` (an imported animation's):
// control characters become spaces, surrounding spaces go, at most
// kMaxClipNameLength bytes (whole UTF-8 characters), kDefaultClipName when
// nothing is left; then unique among `taken` with Blender's ".001", ".002",
// ... suffixes.
std::string usableClipName(const std::string& wanted, const std::set<std::string>& taken);
// `others` sorted by name (the order PartNode::otherClips keeps).
std::vector<rigmesh::Clip> sortedByName(std::vector<rigmesh::Clip> others);

}  // namespace rigmesh::model
