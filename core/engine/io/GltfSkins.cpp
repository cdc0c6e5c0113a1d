#include "io/GltfSkins.h"

#include <nlohmann/json.hpp>

#include <algorithm>
#include <cstdint>
#include <cstring>
#include <map>
#include <set>
#include <vector>

#include "base/Error.h"

namespace rigmesh {
namespace {

using nlohmann::json;

constexpr int kUnsignedByte = 5121, kUnsignedShort = 5123, kFloat = 5126;

std::size_t componentSize(int type) {
    switch (type) {
        case 5120:
        case kUnsignedByte:
            return 1;
        case 5122:
        case kUnsignedShort:
            return 2;
        case 5125:
        case kFloat:
            return 4;
        default:
            throw Error(MessageId::ExportGltfUnknownComponentType);
    }
}

std::size_t componentsOf(const std::string& type) {
    if (type == "SCALAR")
        return 1;
    if (type == "VEC4")
        return 4;
    if (type == "MAT4")
        return 16;
    return type == "VEC3" ? 3 : type == "VEC2" ? 2 : 0;
}

// Where an accessor's elements lie in buffer 0.
struct Elements {
    std::size_t offset = 0, stride = 0, count = 0, size = 0;  // size: bytes per element
    int componentType = 0;

    std::size_t at(std::size_t element, std::size_t component) const {
        return offset + element * stride + component * (size / components());
    }
    std::size_t components() const { return size / componentSize(componentType); }
};

Elements elementsOf(const json& gltf, int accessor, std::size_t binSize) {
    const json& a = gltf.at("accessors").at(static_cast<std::size_t>(accessor));
    const json& view = gltf.at("bufferViews").at(a.at("bufferView").get<std::size_t>());
    Elements e;
    e.componentType = a.at("componentType").get<int>();
    e.size = componentSize(e.componentType) * componentsOf(a.at("type").get<std::string>());
    e.stride = view.value("byteStride", e.size);
    e.offset = view.value("byteOffset", std::size_t{0}) + a.value("byteOffset", std::size_t{0});
    e.count = a.at("count").get<std::size_t>();
    if (view.value("buffer", 0) != 0 || e.size == 0 ||
        (e.count > 0 && e.offset + (e.count - 1) * e.stride + e.size > binSize))
        throw Error(MessageId::ExportGltfAccessorOutside);
    return e;
}

std::uint32_t readUnsigned(const std::string& bin, std::size_t at, int type) {
    if (type == kUnsignedByte)
        return static_cast<unsigned char>(bin[at]);
    std::uint16_t value = 0;
    std::memcpy(&value, bin.data() + at, 2);  // little-endian, as the host
    return value;
}

void writeUnsigned(std::string& bin, std::size_t at, int type, std::uint32_t value) {
    if (type == kUnsignedByte) {
        bin[at] = static_cast<char>(value);
        return;
    }
    const auto narrow = static_cast<std::uint16_t>(value);
    std::memcpy(bin.data() + at, &narrow, 2);
}

double readWeight(const std::string& bin, std::size_t at, int type) {
    if (type == kFloat) {
        float value = 0;
        std::memcpy(&value, bin.data() + at, 4);
        return value;
    }
    return readUnsigned(bin, at, type);  // normalised integers: > 0 is all we ask
}

struct SkinnedPrimitive {
    int jointsAccessor = -1;
    Elements joints, weights;
};

}  // namespace

std::string withOneSkinPerArmature(const std::string& gltfJson, std::string& bin) {
    json gltf = json::parse(gltfJson, nullptr, false);
    if (gltf.is_discarded() || !gltf.is_object())
        throw Error(MessageId::ExportGltfInvalidJson);
    if (!gltf.contains("skins") || gltf["skins"].size() != 1 || !gltf.contains("nodes"))
        return gltfJson;
    const json& skin = gltf["skins"][0];
    const std::vector<int> joints = skin.value("joints", std::vector<int>());
    if (joints.empty() || !skin.contains("inverseBindMatrices"))
        return gltfJson;

    // Each joint's group: its nearest ancestor that is no joint.
    std::map<int, int> parent;
    for (std::size_t n = 0; n < gltf["nodes"].size(); ++n)
        for (const json& child : gltf["nodes"][n].value("children", json::array()))
            parent[child.get<int>()] = static_cast<int>(n);
    const std::set<int> jointNodes(joints.begin(), joints.end());
    auto groupOf = [&](int node) {
        int up = parent.contains(node) ? parent[node] : -1;
        while (up >= 0 && jointNodes.contains(up))
            up = parent.contains(up) ? parent[up] : -1;
        return up;
    };
    std::map<int, std::vector<std::size_t>> groups;  // group node -> skin indices
    for (std::size_t k = 0; k < joints.size(); ++k)
        groups[groupOf(joints[k])].push_back(k);
    if (groups.size() < 2)
        return gltfJson;

    // Each skinned mesh node's group, from the joints it is weighted to.
    std::map<std::size_t, int> groupOfNode;
    std::map<std::size_t, std::vector<SkinnedPrimitive>> primitivesOfNode;
    for (std::size_t n = 0; n < gltf["nodes"].size(); ++n) {
        const json& node = gltf["nodes"][n];
        if (!node.contains("skin") || !node.contains("mesh"))
            continue;
        std::set<int> used;
        const json& mesh = gltf.at("meshes").at(node["mesh"].get<std::size_t>());
        for (const json& primitive : mesh.value("primitives", json::array())) {
            const json& attributes = primitive.value("attributes", json::object());
            if (!attributes.contains("JOINTS_0") || !attributes.contains("WEIGHTS_0") ||
                attributes.contains("JOINTS_1"))
                return gltfJson;
            SkinnedPrimitive p{attributes["JOINTS_0"].get<int>(),
                               elementsOf(gltf, attributes["JOINTS_0"].get<int>(), bin.size()),
                               elementsOf(gltf, attributes["WEIGHTS_0"].get<int>(), bin.size())};
            if ((p.joints.componentType != kUnsignedByte &&
                 p.joints.componentType != kUnsignedShort) ||
                p.joints.count != p.weights.count)
                return gltfJson;
            for (std::size_t v = 0; v < p.joints.count; ++v)
                for (std::size_t c = 0; c < 4; ++c)
                    if (readWeight(bin, p.weights.at(v, c), p.weights.componentType) > 0) {
                        const std::uint32_t k =
                            readUnsigned(bin, p.joints.at(v, c), p.joints.componentType);
                        if (k >= joints.size())
                            return gltfJson;
                        used.insert(groupOf(joints[k]));
                    }
            primitivesOfNode[n].push_back(p);
        }
        if (used.size() != 1)
            return gltfJson;
        groupOfNode[n] = *used.begin();
    }
    std::set<int> usedGroups;
    for (const auto& [node, group] : groupOfNode)
        usedGroups.insert(group);
    if (usedGroups.size() != groups.size())
        return gltfJson;  // joints no mesh uses would become stray objects

    // New skins: joints and inverse bind matrices per group, the matrices
    // copied into one new buffer view at the end of the buffer.
    const Elements matrices = elementsOf(gltf, skin["inverseBindMatrices"].get<int>(), bin.size());
    if (matrices.size != 64 || matrices.count != joints.size())
        return gltfJson;
    bin.append((4 - bin.size() % 4) % 4, '\0');
    const std::size_t viewStart = bin.size();
    const std::size_t viewIndex = gltf["bufferViews"].size();
    json skins = json::array();
    std::map<int, std::size_t> skinOfGroup;
    std::map<int, std::map<std::uint32_t, std::uint32_t>> localIndex;
    for (const auto& [group, members] : groups) {
        json newSkin = {{"joints", json::array()}};
        if (group >= 0 && gltf["nodes"][static_cast<std::size_t>(group)].contains("name"))
            newSkin["name"] = gltf["nodes"][static_cast<std::size_t>(group)]["name"];
        const std::size_t byteOffset = bin.size() - viewStart;
        for (std::size_t i = 0; i < members.size(); ++i) {
            newSkin["joints"].push_back(joints[members[i]]);
            bin.append(bin, matrices.at(members[i], 0), 64);
            localIndex[group][static_cast<std::uint32_t>(members[i])] =
                static_cast<std::uint32_t>(i);
        }
        newSkin["inverseBindMatrices"] = gltf["accessors"].size();
        gltf["accessors"].push_back({{"bufferView", viewIndex},
                                     {"byteOffset", byteOffset},
                                     {"componentType", kFloat},
                                     {"count", members.size()},
                                     {"type", "MAT4"}});
        skinOfGroup[group] = skins.size();
        skins.push_back(std::move(newSkin));
    }
    gltf["bufferViews"].push_back(
        {{"buffer", 0}, {"byteOffset", viewStart}, {"byteLength", bin.size() - viewStart}});
    gltf["buffers"][0]["byteLength"] = bin.size();

    // Each mesh's joint indices into its own skin (unweighted slots: 0).
    std::set<std::size_t> renumbered;
    for (const auto& [n, group] : groupOfNode) {
        gltf["nodes"][n]["skin"] = skinOfGroup[group];
        for (const SkinnedPrimitive& p : primitivesOfNode[n]) {
            if (!renumbered.insert(p.joints.offset).second)
                continue;  // an accessor shared by two nodes: done once
            const auto& local = localIndex[group];
            std::vector<std::uint32_t> lowest(4, UINT32_MAX), highest(4, 0);
            for (std::size_t v = 0; v < p.joints.count; ++v)
                for (std::size_t c = 0; c < 4; ++c) {
                    const std::size_t at = p.joints.at(v, c);
                    const auto found = local.find(readUnsigned(bin, at, p.joints.componentType));
                    const std::uint32_t value = found == local.end() ? 0 : found->second;
                    writeUnsigned(bin, at, p.joints.componentType, value);
                    lowest[c] = std::min(lowest[c], value);
                    highest[c] = std::max(highest[c], value);
                }
            // The accessor's declared bounds follow its new values.
            json& accessor = gltf["accessors"][static_cast<std::size_t>(p.jointsAccessor)];
            if (p.joints.count > 0 && accessor.contains("min"))
                accessor["min"] = lowest;
            if (p.joints.count > 0 && accessor.contains("max"))
                accessor["max"] = highest;
        }
    }
    gltf["skins"] = std::move(skins);
    return gltf.dump();
}

}  // namespace rigmesh
