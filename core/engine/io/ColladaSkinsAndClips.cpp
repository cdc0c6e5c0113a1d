#include "io/ColladaSkinsAndClips.h"

#include <tinyxml2.h>

#include <algorithm>
#include <cstdlib>
#include <limits>
#include <map>
#include <set>
#include <sstream>
#include <vector>

#include "io/ColladaXml.h"

namespace rigmesh {
namespace {

using tinyxml2::XMLElement;

bool hasName(const XMLElement* element, const char* name) {
    return element != nullptr && std::string(element->Name()) == name;
}

std::string attribute(const XMLElement& element, const char* name) {
    const char* value = element.Attribute(name);
    return value != nullptr ? value : "";
}

// "#id" -> "id" (COLLADA's local URIs).
std::string localId(const std::string& uri) {
    return !uri.empty() && uri.front() == '#' ? uri.substr(1) : uri;
}

std::vector<std::string> words(const char* text) {
    std::vector<std::string> out;
    std::istringstream stream(text != nullptr ? text : "");
    for (std::string word; stream >> word;)
        out.push_back(word);
    return out;
}

bool isJoint(const XMLElement* node) {
    return hasName(node, "node") && attribute(*node, "type") == "JOINT";
}

// Every <node> of the visual scenes in document order, with the lookups a
// skin's joint names need (Godot resolves them as sids, Blender as sids or
// ids; ours are equal).
struct SceneNodes {
    std::vector<XMLElement*> ordered;
    std::map<std::string, XMLElement*> byId, bySid;

    void collect(XMLElement& parent) {
        for (XMLElement* node = parent.FirstChildElement("node"); node != nullptr;
             node = node->NextSiblingElement("node")) {
            ordered.push_back(node);
            byId.emplace(attribute(*node, "id"), node);
            if (!attribute(*node, "sid").empty())
                bySid.emplace(attribute(*node, "sid"), node);
            collect(*node);
        }
    }

    XMLElement* joint(const std::string& name) const {
        for (const auto* lookup : {&bySid, &byId})
            if (const auto found = lookup->find(name);
                found != lookup->end() && isJoint(found->second))
                return found->second;
        return nullptr;
    }
};

// The joint names a <skin> binds: the Name_array (or IDREF_array) of the
// source its <joints> input of semantic JOINT names.
std::vector<std::string> skinJointNames(const XMLElement& skin) {
    const XMLElement* joints = skin.FirstChildElement("joints");
    for (const XMLElement* input = joints != nullptr ? joints->FirstChildElement("input") : nullptr;
         input != nullptr; input = input->NextSiblingElement("input")) {
        if (attribute(*input, "semantic") != "JOINT")
            continue;
        const std::string source = localId(attribute(*input, "source"));
        for (const XMLElement* candidate = skin.FirstChildElement("source"); candidate != nullptr;
             candidate = candidate->NextSiblingElement("source")) {
            if (attribute(*candidate, "id") != source)
                continue;
            for (const char* kind : {"Name_array", "IDREF_array"})
                if (const XMLElement* array = candidate->FirstChildElement(kind))
                    return words(array->GetText());
        }
    }
    return {};
}

// Per controller id: the ids of the root joints of the trees its skin's
// joints are in, in document order.
std::map<std::string, std::vector<std::string>> skinRoots(XMLElement& root,
                                                          const SceneNodes& nodes) {
    std::map<std::string, std::vector<std::string>> out;
    XMLElement* library = root.FirstChildElement("library_controllers");
    for (XMLElement* controller = library != nullptr ? library->FirstChildElement("controller")
                                                     : nullptr;
         controller != nullptr; controller = controller->NextSiblingElement("controller")) {
        const XMLElement* skin = controller->FirstChildElement("skin");
        if (skin == nullptr)
            continue;
        std::set<const XMLElement*> roots;
        for (const std::string& name : skinJointNames(*skin)) {
            const XMLElement* joint = nodes.joint(name);
            while (joint != nullptr && isJoint(joint->Parent()->ToElement()))
                joint = joint->Parent()->ToElement();
            if (joint != nullptr)
                roots.insert(joint);
        }
        std::vector<std::string>& ids = out[attribute(*controller, "id")];
        for (const XMLElement* node : nodes.ordered)
            if (roots.count(node) != 0)
                ids.push_back(attribute(*node, "id"));
    }
    return out;
}

void replaceSkeletons(XMLElement& instance, const std::vector<std::string>& roots) {
    while (XMLElement* old = instance.FirstChildElement("skeleton"))
        instance.DeleteChild(old);
    // The schema puts <skeleton> first, before <bind_material>.
    XMLElement* previous = nullptr;
    for (const std::string& id : roots) {
        XMLElement* skeleton = instance.GetDocument()->NewElement("skeleton");
        skeleton->SetText(("#" + id).c_str());
        if (previous == nullptr)
            instance.InsertFirstChild(skeleton);
        else
            instance.InsertAfterChild(previous, skeleton);
        previous = skeleton;
    }
}

void nameSkinSkeletons(XMLElement& root) {
    SceneNodes nodes;
    XMLElement* scenes = root.FirstChildElement("library_visual_scenes");
    for (XMLElement* scene = scenes != nullptr ? scenes->FirstChildElement("visual_scene")
                                               : nullptr;
         scene != nullptr; scene = scene->NextSiblingElement("visual_scene"))
        nodes.collect(*scene);
    const auto roots = skinRoots(root, nodes);
    for (XMLElement* node : nodes.ordered)
        for (XMLElement* instance = node->FirstChildElement("instance_controller");
             instance != nullptr; instance = instance->NextSiblingElement("instance_controller")) {
            const auto found = roots.find(localId(attribute(*instance, "url")));
            if (found != roots.end() && !found->second.empty())
                replaceSkeletons(*instance, found->second);
        }
}

// The first and last key time of an <animation>: the values of its sources
// whose accessor reads a TIME parameter.
std::pair<double, double> keyTimeRange(const XMLElement& animation) {
    double first = std::numeric_limits<double>::infinity();
    double last = -first;
    for (const XMLElement* source = animation.FirstChildElement("source"); source != nullptr;
         source = source->NextSiblingElement("source")) {
        const XMLElement* common = source->FirstChildElement("technique_common");
        const XMLElement* accessor =
            common != nullptr ? common->FirstChildElement("accessor") : nullptr;
        const XMLElement* param =
            accessor != nullptr ? accessor->FirstChildElement("param") : nullptr;
        const XMLElement* array = source->FirstChildElement("float_array");
        if (param == nullptr || array == nullptr || attribute(*param, "name") != "TIME")
            continue;
        for (const std::string& word : words(array->GetText())) {
            const double time = std::strtod(word.c_str(), nullptr);
            first = std::min(first, time);
            last = std::max(last, time);
        }
    }
    return first <= last ? std::make_pair(first, last) : std::make_pair(0.0, 0.0);
}

// Every id inside an <animation> (its sources, arrays, samplers), and the
// `#id` references to them there, prefixed with the animation's id.
void prefixIds(XMLElement& element, const std::string& prefix,
               std::map<std::string, std::string>& renamed) {
    if (const char* id = element.Attribute("id")) {
        renamed["#" + std::string(id)] = "#" + prefix + id;
        element.SetAttribute("id", (prefix + id).c_str());
    }
    for (XMLElement* child = element.FirstChildElement(); child != nullptr;
         child = child->NextSiblingElement())
        prefixIds(*child, prefix, renamed);
}

void renameReferences(XMLElement& element, const std::map<std::string, std::string>& renamed) {
    if (const char* source = element.Attribute("source"))
        if (const auto found = renamed.find(source); found != renamed.end())
            element.SetAttribute("source", found->second.c_str());
    for (XMLElement* child = element.FirstChildElement(); child != nullptr;
         child = child->NextSiblingElement())
        renameReferences(*child, renamed);
}

// Assimp 5.2.5 names an animation's sources after the node alone
// ("Pelvis_matrix-input"), so a file with several animations repeats every
// id, and readers (Assimp's own) take one animation's keys for all of them.
void makeAnimationIdsUnique(XMLElement& root) {
    XMLElement* animations = root.FirstChildElement("library_animations");
    if (animations == nullptr)
        return;
    for (XMLElement* animation = animations->FirstChildElement("animation"); animation != nullptr;
         animation = animation->NextSiblingElement("animation")) {
        const std::string id = attribute(*animation, "id");
        if (id.empty())
            continue;
        std::map<std::string, std::string> renamed;
        for (XMLElement* child = animation->FirstChildElement(); child != nullptr;
             child = child->NextSiblingElement())
            prefixIds(*child, id + "-", renamed);
        renameReferences(*animation, renamed);
    }
}

void addAnimationClips(XMLElement& root) {
    XMLElement* animations = root.FirstChildElement("library_animations");
    if (animations == nullptr || root.FirstChildElement("library_animation_clips") != nullptr)
        return;
    XMLElement* clips = root.GetDocument()->NewElement("library_animation_clips");
    for (const XMLElement* animation = animations->FirstChildElement("animation");
         animation != nullptr; animation = animation->NextSiblingElement("animation")) {
        const std::string id = attribute(*animation, "id");
        if (id.empty())
            continue;
        const std::string name = attribute(*animation, "name");
        const auto [start, end] = keyTimeRange(*animation);
        XMLElement* clip = clips->InsertNewChildElement("animation_clip");
        clip->SetAttribute("id", (id + "-clip").c_str());
        clip->SetAttribute("name", (name.empty() ? id : name).c_str());
        clip->SetAttribute("start", colladaNumber(start).c_str());
        clip->SetAttribute("end", colladaNumber(end).c_str());
        clip->InsertNewChildElement("instance_animation")->SetAttribute("url", ("#" + id).c_str());
    }
    if (clips->NoChildren())
        root.GetDocument()->DeleteNode(clips);
    else
        root.InsertAfterChild(animations, clips);
}

}  // namespace

std::string withColladaSkinRootsAndClips(const std::string& dae) {
    return editColladaXml(dae, [](XMLElement& root) {
        nameSkinSkeletons(root);
        makeAnimationIdsUnique(root);
        addAnimationClips(root);
    });
}

}  // namespace rigmesh
