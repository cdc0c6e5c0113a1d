#include "io/FbxClusterOrder.h"

#include <algorithm>
#include <cstring>
#include <map>
#include <set>
#include <string>

#include "io/FbxRecords.h"

namespace rigmesh {
namespace {

std::int64_t idAt(const FbxRecord& record, const FbxProperty& property) {
    std::int64_t id = 0;
    std::memcpy(&id, record.body.data() + property.at, sizeof id);  // little-endian, as we are
    return id;
}

// An object-to-object connection: C "OO", child id, parent id.
struct Link {
    std::int64_t child = 0;
    std::int64_t parent = 0;
};

bool readLink(const FbxRecord& record, bool wide, Link& link) {
    if (record.name != "C")
        return false;
    const std::vector<FbxProperty> properties = fbxProperties(record, wide);
    if (properties.size() < 3 || properties[0].type != 'S' || properties[1].type != 'L' ||
        properties[2].type != 'L' || fbxStringAt(record, properties[0]) != "OO")
        return false;
    link = {idAt(record, properties[1]), idAt(record, properties[2])};
    return true;
}

}  // namespace

void listFbxClustersParentsFirst(FbxFile& fbx) {
    std::set<std::int64_t> models, clusters, skins;
    for (const FbxRecord& objects : fbx.top) {
        if (objects.name != "Objects")
            continue;
        for (const FbxRecord& object : objects.children) {
            const std::vector<FbxProperty> properties = fbxProperties(object, fbx.wide);
            if (properties.size() < 3 || properties[0].type != 'L' || properties[2].type != 'S')
                continue;
            const std::int64_t id = idAt(object, properties[0]);
            if (object.name == "Model")
                models.insert(id);
            else if (object.name == "Deformer" && fbxStringAt(object, properties[2]) == "Cluster")
                clusters.insert(id);
            else if (object.name == "Deformer" && fbxStringAt(object, properties[2]) == "Skin")
                skins.insert(id);
        }
    }
    // The node tree (model to parent model) and each cluster's bone (the
    // model connected to it).
    std::map<std::int64_t, std::int64_t> parentOf, boneOf;
    for (const FbxRecord& connections : fbx.top) {
        if (connections.name != "Connections")
            continue;
        for (const FbxRecord& record : connections.children) {
            Link link;
            if (!readLink(record, fbx.wide, link) || !models.contains(link.child))
                continue;
            if (models.contains(link.parent))
                parentOf[link.child] = link.parent;
            else if (clusters.contains(link.parent))
                boneOf[link.parent] = link.child;
        }
    }
    auto depthOf = [&](std::int64_t model) {
        std::size_t depth = 0;
        for (auto up = parentOf.find(model); up != parentOf.end() && depth <= parentOf.size();
             up = parentOf.find(up->second))
            ++depth;  // bounded: a cycle (a broken file) cannot loop for ever
        return depth;
    };
    auto clusterDepth = [&](std::int64_t cluster) {
        const auto bone = boneOf.find(cluster);
        return bone == boneOf.end() ? std::size_t(0) : depthOf(bone->second);
    };
    for (FbxRecord& connections : fbx.top) {
        if (connections.name != "Connections")
            continue;
        // The cluster-to-skin connections, sorted by their bones' depth
        // (stable: siblings keep their order), back into the same slots.
        std::vector<std::size_t> slots;
        std::vector<std::pair<std::size_t, FbxRecord>> moved;
        for (std::size_t i = 0; i < connections.children.size(); ++i) {
            Link link;
            if (readLink(connections.children[i], fbx.wide, link) &&
                clusters.contains(link.child) && skins.contains(link.parent)) {
                slots.push_back(i);
                moved.emplace_back(clusterDepth(link.child), connections.children[i]);
            }
        }
        std::stable_sort(moved.begin(), moved.end(),
                         [](const auto& a, const auto& b) { return a.first < b.first; });
        for (std::size_t k = 0; k < slots.size(); ++k)
            connections.children[slots[k]] = std::move(moved[k].second);
    }
}

std::vector<std::uint8_t> withFbxClustersParentsFirst(const std::vector<std::uint8_t>& file) {
    FbxFile fbx = parseFbx(file);
    listFbxClustersParentsFirst(fbx);
    return writeFbx(file, fbx);
}

}  // namespace rigmesh
