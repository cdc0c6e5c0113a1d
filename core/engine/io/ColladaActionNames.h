// The action names inside a COLLADA file Blender wrote. Blender 3.x puts
// each object's action into one container `<animation id="action_container-
// OBJECT" name="OBJECT">` whose channels have ids OBJECT_ACTION_BONE_
// pose_matrix and target the joint nodes OBJECT_BONE, so the name Assimp
// reports for the animation is the object's ("metarig"), not the action's
// ("Walk"). The action name is read back from the channel ids here (the
// part between the object's name and the joint's), when every channel of
// the container agrees on it.
#pragma once

#include <map>
#include <string>

namespace tinyxml2 {
class XMLElement;
}

namespace rigmesh {

// Per top-level animation (keyed by its `name`, its `id`, and the name Assimp
// gives it, `name` + "_" + its first channel's name): the action
// name its channel ids carry. Empty for text that is not XML and for files
// whose animations do not follow Blender's naming.
std::map<std::string, std::string> readColladaActionNames(const std::string& dae);
// The same from a parsed document's root element.
std::map<std::string, std::string> readColladaActionNames(const tinyxml2::XMLElement& collada);

}  // namespace rigmesh
