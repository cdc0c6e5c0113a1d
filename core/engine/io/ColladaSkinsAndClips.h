// What a game engine's COLLADA importer needs beyond what Assimp writes,
// read from Godot 3.2's importer (editor/collada/collada.cpp,
// editor/import/editor_import_collada.cpp) and measured with Godot 3.2.3:
//
// - Skins' skeletons. Assimp names the node above the joints (our
//   `Armature`, a plain node) as each skin's `<skeleton>`. Godot makes one
//   Skeleton of each tree of joints and finds a skin's Skeleton through its
//   `<skeleton>` nodes, which must be joints: with a plain node it stops
//   ("_move_geometry_to_skeletons: Condition "!nj" is true"), gives no joint
//   its rest transform and imports nothing. So each skin names the root
//   joints of the trees its joints are in, one `<skeleton>` each (the
//   COLLADA 1.4.1 specification allows several); Godot then merges those
//   trees into one Skeleton whose rests are the skin's bind poses.
// - Animation names. Godot names the animations after the file's
//   `<animation_clip>`s and puts every track outside a clip into one
//   animation called "default"; Assimp writes one `<animation>` per clip and
//   no clips. So each top-level `<animation>` gets an `<animation_clip>` of
//   its name, from its first key time to its last.
// - Animation ids. Assimp names each animation's sources and samplers after
//   the node alone ("Pelvis_matrix-input"), so with several animations every
//   id repeats and a reader (Assimp's own, measured) takes one animation's
//   keys for all of them: a 30-key clip came back with the 1 key of another.
//   The ids inside each `<animation>` get its id as a prefix.
//
// Blender 3.4.1 reads the same files as before (tests/external: its dae
// checks pass on files with both).
#pragma once

#include <string>

namespace rigmesh {

// The COLLADA text with every skin's `<skeleton>` elements replaced by its
// root joints, the ids inside each top-level `<animation>` prefixed with its
// id, and one `<animation_clip>` per top-level `<animation>`.
// Throws Error on text that is not XML.
std::string withColladaSkinRootsAndClips(const std::string& dae);

}  // namespace rigmesh
