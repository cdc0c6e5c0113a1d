#include "io/ColladaActionNames.h"

#include <tinyxml2.h>

#include <optional>

namespace rigmesh {
namespace {

// The action in one channel animation's id: `id` is OBJECT_ACTION_JOINT_
// pose_matrix and its channel targets OBJECT_JOINT/transform.
std::optional<std::string> actionOfChannel(const tinyxml2::XMLElement& animation,
                                           const std::string& object) {
    const char* idText = animation.Attribute("id");
    const tinyxml2::XMLElement* channel = animation.FirstChildElement("channel");
    const char* targetText = channel != nullptr ? channel->Attribute("target") : nullptr;
    if (idText == nullptr || targetText == nullptr)
        return std::nullopt;
    const std::string id = idText;
    std::string target = targetText;
    target = target.substr(0, target.find('/'));
    const std::string objectPrefix = object + "_";
    const std::string suffix = "_pose_matrix";
    if (!target.starts_with(objectPrefix) || !id.starts_with(objectPrefix) || !id.ends_with(suffix))
        return std::nullopt;
    const std::string joint = target.substr(objectPrefix.size());
    const std::string middle =
        id.substr(objectPrefix.size(), id.size() - objectPrefix.size() - suffix.size());
    if (!middle.ends_with("_" + joint) || middle.size() <= joint.size() + 1)
        return std::nullopt;
    return middle.substr(0, middle.size() - joint.size() - 1);
}

}  // namespace

std::map<std::string, std::string> readColladaActionNames(const std::string& dae) {
    tinyxml2::XMLDocument document;
    if (document.Parse(dae.data(), dae.size()) != tinyxml2::XML_SUCCESS ||
        document.RootElement() == nullptr)
        return {};
    return readColladaActionNames(*document.RootElement());
}

std::map<std::string, std::string> readColladaActionNames(const tinyxml2::XMLElement& collada) {
    std::map<std::string, std::string> names;
    const tinyxml2::XMLElement* library = collada.FirstChildElement("library_animations");
    for (const tinyxml2::XMLElement* container =
             library != nullptr ? library->FirstChildElement("animation") : nullptr;
         container != nullptr; container = container->NextSiblingElement("animation")) {
        const char* id = container->Attribute("id");
        const char* name = container->Attribute("name");
        if (id == nullptr || name == nullptr ||
            container->FirstChildElement("animation") == nullptr)
            continue;
        std::optional<std::string> action;
        bool agree = true;
        for (const tinyxml2::XMLElement* channel = container->FirstChildElement("animation");
             channel != nullptr && agree; channel = channel->NextSiblingElement("animation")) {
            const std::optional<std::string> found = actionOfChannel(*channel, name);
            agree = found && (!action || *action == *found);
            action = found;
        }
        if (agree && action) {
            names[name] = *action;
            names[id] = *action;
            // Assimp names a container of one-channel animations after the
            // container and its first channel: NAME_CHANNELNAME.
            const char* first = container->FirstChildElement("animation")->Attribute("name");
            if (first != nullptr)
                names[std::string(name) + "_" + first] = *action;
        }
    }
    return names;
}

}  // namespace rigmesh
