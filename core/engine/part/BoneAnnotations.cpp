#include "part/BoneAnnotations.h"

#include <optional>

namespace rigmesh {

void carryBoneAnnotations(const Part& from, Part& to, const std::map<BoneId, BoneId>* renamed) {
    const auto survivor = [&](BoneId bone) -> std::optional<BoneId> {
        BoneId id = bone;
        if (renamed) {
            const auto it = renamed->find(bone);
            if (it == renamed->end())
                return std::nullopt;
            id = it->second;
        }
        if (!to.skeleton.hasBone(id))
            return std::nullopt;
        return id;
    };
    for (const auto& [bone, name] : from.boneNames)
        if (const std::optional<BoneId> id = survivor(bone))
            to.boneNames[*id] = name;
    for (const BoneId bone : from.lockedBones)
        if (const std::optional<BoneId> id = survivor(bone))
            to.lockedBones.insert(*id);
    to.weightsPainted = to.weightsPainted || from.weightsPainted;
}

}  // namespace rigmesh
