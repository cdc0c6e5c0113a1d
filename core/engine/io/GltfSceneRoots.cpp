#include "io/GltfSceneRoots.h"

#include <nlohmann/json.hpp>

#include "base/Error.h"

namespace rigmesh {
namespace {

using nlohmann::json;

bool isIdentityRoot(const json& node) {
    for (const char* key : {"mesh", "skin", "camera", "matrix", "translation", "rotation", "scale"})
        if (node.contains(key))
            return false;
    return true;
}

// Renumbers one node index after `removed` is gone.
void renumber(json& index, int removed) {
    if (index.is_number_integer() && index.get<int>() > removed)
        index = index.get<int>() - 1;
}

// Whether anything but the scene names node `root` (a joint, a skeleton, an
// animation target): then it cannot go.
bool refersTo(const json& gltf, int root) {
    if (gltf.contains("skins"))
        for (const json& skin : gltf["skins"]) {
            if (skin.value("skeleton", -1) == root)
                return true;
            for (const json& joint : skin.value("joints", json::array()))
                if (joint == root)
                    return true;
        }
    if (gltf.contains("animations"))
        for (const json& animation : gltf["animations"])
            for (const json& channel : animation.value("channels", json::array()))
                if (channel.contains("target") && channel["target"].value("node", -1) == root)
                    return true;
    return false;
}

}  // namespace

std::string withRootChildrenAsSceneRoots(const std::string& gltfJson) {
    json gltf = json::parse(gltfJson, nullptr, false);
    if (gltf.is_discarded() || !gltf.is_object())
        throw Error(MessageId::ExportGltfInvalidJson);
    if (!gltf.contains("scenes") || !gltf["scenes"].is_array() || gltf["scenes"].size() != 1 ||
        !gltf.contains("nodes") || !gltf["nodes"].is_array())
        return gltfJson;
    json& scene = gltf["scenes"][0];
    if (!scene.contains("nodes") || scene["nodes"].size() != 1 ||
        !scene["nodes"][0].is_number_integer())
        return gltfJson;
    const int root = scene["nodes"][0].get<int>();
    json& nodes = gltf["nodes"];
    if (root < 0 || root >= static_cast<int>(nodes.size()) || !isIdentityRoot(nodes[root]))
        return gltfJson;

    if (refersTo(gltf, root))
        return gltfJson;

    scene["nodes"] = nodes[root].value("children", json::array());
    nodes.erase(static_cast<std::size_t>(root));
    for (json& index : scene["nodes"])
        renumber(index, root);
    for (json& node : nodes)
        if (node.contains("children"))
            for (json& child : node["children"])
                renumber(child, root);
    if (gltf.contains("skins"))
        for (json& skin : gltf["skins"]) {
            if (skin.contains("joints"))
                for (json& joint : skin["joints"])
                    renumber(joint, root);
            if (skin.contains("skeleton"))
                renumber(skin["skeleton"], root);
        }
    if (gltf.contains("animations"))
        for (json& animation : gltf["animations"])
            if (animation.contains("channels"))
                for (json& channel : animation["channels"])
                    if (channel.contains("target") && channel["target"].contains("node"))
                        renumber(channel["target"]["node"], root);
    return gltf.dump();
}

}  // namespace rigmesh
