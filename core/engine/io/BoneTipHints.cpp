#include "io/BoneTipHints.h"

#include <tinyxml2.h>
#include <nlohmann/json.hpp>

#include <cmath>
#include <map>
#include <utility>

#include "base/Error.h"
#include "io/ColladaXml.h"
#include "io/FbxSentinels.h"

namespace rigmesh {
namespace {

std::map<std::string, const ExportBoneNode*> bonesByName(const std::vector<ExportRig>& rigs) {
    std::map<std::string, const ExportBoneNode*> byName;
    for (const ExportRig& rig : rigs)
        for (const ExportBoneNode& node : rig.nodes)
            byName.emplace(node.name, &node);
    return byName;
}

void addParameter(tinyxml2::XMLElement& technique, const char* name, const char* type,
                  const std::string& value) {
    tinyxml2::XMLElement* parameter = technique.InsertNewChildElement(name);
    parameter->SetAttribute("sid", name);
    parameter->SetAttribute("type", type);
    parameter->SetText(value.c_str());
}

void addTips(tinyxml2::XMLElement& parent,
             const std::map<std::string, const ExportBoneNode*>& bones) {
    for (tinyxml2::XMLElement* node = parent.FirstChildElement("node"); node != nullptr;
         node = node->NextSiblingElement("node")) {
        addTips(*node, bones);
        const char* type = node->Attribute("type");
        const char* name = node->Attribute("name");
        if (type == nullptr || name == nullptr || std::string(type) != "JOINT")
            continue;
        const auto bone = bones.find(name);
        if (bone == bones.end())
            continue;
        // Blender's tip is the shown tail (ExportBoneNode::shownTail); our own
        // profile keeps the exact one where they differ.
        const Vec3 tip = bone->second->shownTail - bone->second->head;
        tinyxml2::XMLElement* technique =
            node->InsertNewChildElement("extra")->InsertNewChildElement("technique");
        technique->SetAttribute("profile", "blender");
        addParameter(*technique, "connect", "bool", bone->second->connected ? "1" : "0");
        addParameter(*technique, "layer", "string", "0");
        addParameter(*technique, "roll", "float", colladaNumber(bone->second->roll()));
        addParameter(*technique, "tip_x", "float", colladaNumber(tip.x()));
        addParameter(*technique, "tip_y", "float", colladaNumber(tip.y()));
        addParameter(*technique, "tip_z", "float", colladaNumber(tip.z()));
        const bool renamed = !bone->second->renamedFrom.empty();
        const bool shownElsewhere = bone->second->shownTail != bone->second->tail;
        if (renamed || shownElsewhere) {  // our own profile: Blender ignores it
            tinyxml2::XMLElement* ours =
                node->LastChildElement("extra")->InsertNewChildElement("technique");
            ours->SetAttribute("profile", "rigmesh");
            if (renamed)
                addParameter(*ours, kNameMetadataKey, "string", bone->second->renamedFrom);
            if (shownElsewhere) {
                const Vec3 exact = bone->second->tail - bone->second->head;
                addParameter(*ours, "tip_x", "float", colladaNumber(exact.x()));
                addParameter(*ours, "tip_y", "float", colladaNumber(exact.y()));
                addParameter(*ours, "tip_z", "float", colladaNumber(exact.z()));
            }
        }
    }
}

}  // namespace

std::string withColladaBoneTips(const std::string& dae, const std::vector<ExportRig>& rigs) {
    auto bones = bonesByName(rigs);
    // End bones (ExportOptions::leafBones) get the tip their glTF and FBX
    // nodes give Blender: back along the leaf (ExportRig.h endBoneOf). A
    // joint named so is always the end bone: the scene builder keeps every
    // `<bone>_end` name free for it.
    std::vector<ExportBoneNode> ends;
    for (const ExportRig& rig : rigs)
        for (const ExportBoneNode& node : rig.nodes)
            if (node.leaf)
                ends.push_back(endBoneOf(node));
    for (const ExportBoneNode& end : ends)
        bones.emplace(end.name, &end);
    return editColladaXml(dae, [&](tinyxml2::XMLElement& root) {
        tinyxml2::XMLElement* scenes = root.FirstChildElement("library_visual_scenes");
        for (tinyxml2::XMLElement* scene =
                 scenes != nullptr ? scenes->FirstChildElement("visual_scene") : nullptr;
             scene != nullptr; scene = scene->NextSiblingElement("visual_scene"))
            addTips(*scene, bones);
    });
}

namespace {

// Calls visit(joint name, technique) for every `<technique profile="...">`
// of every node below `parent`.
template <typename Visit>
void forEachBlenderTechnique(const tinyxml2::XMLElement& parent, const std::string& wanted,
                             Visit&& visit) {
    for (const tinyxml2::XMLElement* node = parent.FirstChildElement("node"); node != nullptr;
         node = node->NextSiblingElement("node")) {
        forEachBlenderTechnique(*node, wanted, visit);
        const char* name = node->Attribute("name");
        if (name == nullptr)
            continue;
        for (const tinyxml2::XMLElement* extra = node->FirstChildElement("extra"); extra != nullptr;
             extra = extra->NextSiblingElement("extra"))
            for (const tinyxml2::XMLElement* technique = extra->FirstChildElement("technique");
                 technique != nullptr; technique = technique->NextSiblingElement("technique")) {
                const char* profile = technique->Attribute("profile");
                if (profile != nullptr && std::string(profile) == wanted)
                    visit(std::string(name), *technique);
            }
    }
}

// The same for every visual scene of a COLLADA document's root element.
template <typename Visit>
void forEachBlenderJointTechnique(const tinyxml2::XMLElement& collada, Visit&& visit,
                                  const std::string& profile = "blender") {
    const tinyxml2::XMLElement* scenes = collada.FirstChildElement("library_visual_scenes");
    for (const tinyxml2::XMLElement* scene =
             scenes != nullptr ? scenes->FirstChildElement("visual_scene") : nullptr;
         scene != nullptr; scene = scene->NextSiblingElement("visual_scene"))
        forEachBlenderTechnique(*scene, profile, visit);
}

// What `read` gives for the root element of `dae` parsed, or an empty
// result for text that is not XML.
template <typename Read>
auto readParsed(const std::string& dae, Read&& read)
    -> decltype(read(std::declval<const tinyxml2::XMLElement&>())) {
    tinyxml2::XMLDocument document;
    if (document.Parse(dae.data(), dae.size()) != tinyxml2::XML_SUCCESS ||
        document.RootElement() == nullptr)
        return {};
    return read(*document.RootElement());
}

}  // namespace

void addFbxBoneTails(FbxFile& fbx, const std::vector<ExportRig>& rigs) {
    std::map<std::string, Vec3> tails;
    std::map<std::string, std::string> names;
    for (const ExportRig& rig : rigs)
        for (const ExportBoneNode& node : rig.nodes) {
            tails.emplace(node.name, node.localTail());
            if (!node.renamedFrom.empty())
                names.emplace(node.name, node.renamedFrom);
        }
    addFbxModelVectors(fbx, kTailMetadataKey, tails);
    if (!names.empty())
        addFbxModelStrings(fbx, kNameMetadataKey, names);
}

std::map<std::string, Vec3> readColladaBoneTips(const std::string& dae,
                                                const std::string& profile) {
    return readParsed(dae, [&](const tinyxml2::XMLElement& collada) {
        return readColladaBoneTips(collada, profile);
    });
}

std::map<std::string, bool> readColladaBoneConnections(const std::string& dae) {
    return readParsed(dae, [](const tinyxml2::XMLElement& collada) {
        return readColladaBoneConnections(collada);
    });
}

std::map<std::string, std::string> readColladaBoneNames(const std::string& dae) {
    return readParsed(
        dae, [](const tinyxml2::XMLElement& collada) { return readColladaBoneNames(collada); });
}

std::map<std::string, Vec3> readColladaBoneTips(const tinyxml2::XMLElement& dae,
                                                const std::string& profile) {
    std::map<std::string, Vec3> tips;
    forEachBlenderJointTechnique(
        dae,
        [&](const std::string& name, const tinyxml2::XMLElement& technique) {
            Vec3 tip;
            bool complete = true;
            const char* axes[] = {"tip_x", "tip_y", "tip_z"};
            for (int k = 0; k < 3; ++k) {
                const tinyxml2::XMLElement* value = technique.FirstChildElement(axes[k]);
                double number = 0;
                complete = complete && value != nullptr &&
                           value->QueryDoubleText(&number) == tinyxml2::XML_SUCCESS &&
                           std::isfinite(number);
                tip[k] = number;
            }
            if (complete)
                tips[name] = tip;
        },
        profile);
    return tips;
}

std::map<std::string, bool> readColladaBoneConnections(const tinyxml2::XMLElement& dae) {
    std::map<std::string, bool> connected;
    forEachBlenderJointTechnique(
        dae, [&](const std::string& name, const tinyxml2::XMLElement& technique) {
            // Blender's COLLADA exporter writes `connect` only for a connected
            // bone: a joint with Blender's extra but without it is disconnected
            // (Rigify's neck and finger roots lie on their parents' tails).
            const tinyxml2::XMLElement* value = technique.FirstChildElement("connect");
            int flag = 0;
            connected[name] = value != nullptr &&
                              value->QueryIntText(&flag) == tinyxml2::XML_SUCCESS && flag != 0;
        });
    return connected;
}

std::map<std::string, std::string> readColladaBoneNames(const tinyxml2::XMLElement& dae) {
    std::map<std::string, std::string> names;
    forEachBlenderJointTechnique(
        dae,
        [&](const std::string& name, const tinyxml2::XMLElement& technique) {
            const tinyxml2::XMLElement* value = technique.FirstChildElement(kNameMetadataKey);
            if (value != nullptr && value->GetText() != nullptr)
                names[name] = value->GetText();
        },
        "rigmesh");
    return names;
}

std::string withGltfBoneTails(const std::string& gltfJson, const std::vector<ExportRig>& rigs) {
    nlohmann::json gltf = nlohmann::json::parse(gltfJson, nullptr, false);
    if (gltf.is_discarded() || !gltf.is_object())
        throw Error(MessageId::ExportGltfInvalidJson);
    const auto bones = bonesByName(rigs);
    if (gltf.contains("nodes") && gltf["nodes"].is_array())
        for (nlohmann::json& node : gltf["nodes"]) {
            const auto bone = bones.find(node.value("name", std::string()));
            if (bone == bones.end())
                continue;
            const Vec3 tail = bone->second->localTail();
            node["extras"][kTailMetadataKey] = {tail.x(), tail.y(), tail.z()};
            if (!bone->second->renamedFrom.empty())
                node["extras"][kNameMetadataKey] = bone->second->renamedFrom;
        }
    return gltf.dump();
}

}  // namespace rigmesh
