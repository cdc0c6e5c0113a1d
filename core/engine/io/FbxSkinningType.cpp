#include "io/FbxSkinningType.h"

#include <algorithm>

#include "io/FbxRecords.h"

namespace rigmesh {
namespace {

// A Deformer record whose class (third property) is "Skin"; Clusters are
// Deformers too (class "Cluster").
bool isSkin(const FbxRecord& record, bool wide) {
    if (record.name != "Deformer")
        return false;
    const std::vector<FbxProperty> properties = fbxProperties(record, wide);
    return properties.size() >= 3 && fbxStringAt(record, properties[2]) == "Skin";
}

// A record `name: "value"` without children.
FbxRecord stringRecord(const std::string& name, const std::string& value, bool wide) {
    FbxRecord record;
    record.name = name;
    const std::size_t fieldSize = wide ? 8 : 4;
    putFbxLittleEndian(record.body, 1, fieldSize);
    putFbxLittleEndian(record.body, 5 + value.size(), fieldSize);
    record.body.push_back(static_cast<std::uint8_t>(name.size()));
    record.body.insert(record.body.end(), name.begin(), name.end());
    record.body.push_back('S');
    putFbxLittleEndian(record.body, value.size(), 4);
    record.body.insert(record.body.end(), value.begin(), value.end());
    return record;
}

template <typename Visit>
void forEachSkin(FbxFile& fbx, Visit&& visit) {
    for (FbxRecord& objects : fbx.top)
        if (objects.name == "Objects")
            for (FbxRecord& record : objects.children)
                if (isSkin(record, fbx.wide))
                    visit(record);
}

}  // namespace

const char* fbxSkinningTypeName(SkinningMethod method) {
    return method == SkinningMethod::DualQuaternion ? "DualQuaternion" : "Linear";
}

void setFbxSkinningType(FbxFile& fbx, SkinningMethod method) {
    const FbxRecord type = stringRecord("SkinningType", fbxSkinningTypeName(method), fbx.wide);
    forEachSkin(fbx, [&](FbxRecord& skin) {
        auto old = std::find_if(skin.children.begin(), skin.children.end(),
                                [](const FbxRecord& r) { return r.name == "SkinningType"; });
        if (old != skin.children.end()) {
            *old = type;
        } else {
            skin.children.push_back(type);
            skin.nested = true;
        }
    });
}

std::vector<std::uint8_t> withFbxSkinningType(const std::vector<std::uint8_t>& file,
                                              SkinningMethod method) {
    FbxFile fbx = parseFbx(file);
    setFbxSkinningType(fbx, method);
    return writeFbx(file, fbx);
}

std::vector<std::string> fbxSkinningTypes(const std::vector<std::uint8_t>& file) {
    FbxFile fbx = parseFbx(file);
    std::vector<std::string> types;
    forEachSkin(fbx, [&](FbxRecord& skin) {
        const auto type = std::find_if(skin.children.begin(), skin.children.end(),
                                       [](const FbxRecord& r) { return r.name == "SkinningType"; });
        std::string value;
        if (type != skin.children.end()) {
            const std::vector<FbxProperty> properties = fbxProperties(*type, fbx.wide);
            if (!properties.empty())
                value = fbxStringAt(*type, properties[0]);
        }
        types.push_back(value);
    });
    return types;
}

}  // namespace rigmesh
