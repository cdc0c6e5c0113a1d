// Where each bone's tail is, written into the exported file for importers
// that would otherwise guess it. A bone node's
// frame gives the tail's direction, but not a leaf bone's length, and
// Blender's COLLADA importer reads no frame at all: it points every bone
// along the file's up axis unless the joint carries Blender's own
// `<extra><technique profile="blender">` with `tip_x/y/z`, the tail minus
// the head in the file's coordinates (measured with Blender 3.4.1: with it
// every bone's head, direction and length match ours). In glTF every bone's
// node gets `extras.rigmesh_tail`, its tail in the node's own frame, which
// our importer (through Assimp's node metadata) reads back; Blender shows it
// as a custom property of the bone. FBX gets the same as a user property of
// the bone's Model. Every bone, not only the leaves: a bone whose tail is not
// where a child starts (an imported rig's bone with disconnected children
// only, or with a connected child beside others) would otherwise get a
// guessed tail, and with it other connections (io/BoneTails.h).
#pragma once

#include <map>
#include <string>
#include <vector>

#include "io/ExportRig.h"
#include "io/FbxRecords.h"

namespace tinyxml2 {
class XMLElement;
}

namespace rigmesh {

// The COLLADA text with Blender's tip extra added to every joint node of
// `rigs` (as the node's last child, where the schema puts <extra>).
// Throws Error on text that is not XML.
std::string withColladaBoneTips(const std::string& dae, const std::vector<ExportRig>& rigs);

// The glTF JSON with `extras.rigmesh_tail` (and `rigmesh_name` where the
// node is named otherwise than its bone) on every bone's node of `rigs`. Throws Error on JSON that
// is not glTF.
std::string withGltfBoneTails(const std::string& gltfJson, const std::vector<ExportRig>& rigs);

// Adds to a binary FBX a user property `rigmesh_tail` (a Vector: the tail
// in the node's own frame) on every bone's Model, and `rigmesh_name` (a
// KString) where the Model is named otherwise than its bone.
void addFbxBoneTails(FbxFile& fbx, const std::vector<ExportRig>& rigs);

// The metadata key our importer reads (glTF extras, FBX user property).
inline constexpr const char* kTailMetadataKey = "rigmesh_tail";
// Beside the tail, on a bone whose node had to be named otherwise to stay
// unique in the file (ExportBoneNode::renamedFrom): the bone's own name,
// which our importer gives the bone back.
inline constexpr const char* kNameMetadataKey = "rigmesh_name";

// Per joint name: Blender's tip (tail minus head, in the armature's space)
// from a COLLADA file's `<technique profile="blender">` extras, as our
// exporter and Blender's write them. Empty for text that is not XML. With
// `profile` "rigmesh": our exporter's exact tip where Blender is shown
// another (ExportBoneNode::shownTail).
std::map<std::string, Vec3> readColladaBoneTips(const std::string& dae,
                                                const std::string& profile = "blender");
// Per joint name: Blender's "Connected" flag from the same extras (`connect`,
// which Blender's COLLADA importer honours and we write from the skeleton).
// A joint with Blender's extra but no `connect` is not connected.
std::map<std::string, bool> readColladaBoneConnections(const std::string& dae);
// Per joint name: the bone's own name our exporter wrote where the joint had
// to be named otherwise (`<technique profile="rigmesh">`, kNameMetadataKey).
std::map<std::string, std::string> readColladaBoneNames(const std::string& dae);

// The same read from a parsed document's root element (io/SceneImport
// reads all of a file's extras from one parse).
std::map<std::string, Vec3> readColladaBoneTips(const tinyxml2::XMLElement& collada,
                                                const std::string& profile = "blender");
std::map<std::string, bool> readColladaBoneConnections(const tinyxml2::XMLElement& collada);
std::map<std::string, std::string> readColladaBoneNames(const tinyxml2::XMLElement& collada);

}  // namespace rigmesh
