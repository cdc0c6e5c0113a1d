#include "io/RigJson.h"

#include <cmath>
#include <nlohmann/json.hpp>

#include "base/Error.h"

namespace rigmesh {

namespace {

// JSON has no Infinity or NaN (nlohmann would write null): refuse them.
void checkRigIsFinite(const Part& part) {
    for (std::size_t v = 0; v < part.mesh.vertices.size(); ++v)
        if (!part.mesh.vertices[v].allFinite())
            throw Error(MessageId::RigJsonVertexNotFinite, v);
    for (const Joint& joint : part.skeleton.joints())
        if (!joint.position.allFinite())
            throw Error(MessageId::RigJsonJointNotFinite, joint.id);
    for (std::size_t v = 0; v < part.weights.perVertex.size(); ++v)
        for (const auto& [bone, weight] : part.weights.perVertex[v])
            if (!std::isfinite(weight))
                throw Error(MessageId::RigJsonWeightNotFinite, v);
}

}  // namespace

std::string rigToJson(const Part& part, const std::string& meshFile) {
    checkRigIsFinite(part);
    const Skeleton& skeleton = part.skeleton;
    nlohmann::json rig;
    rig["about"] =
        "head, tail, parent, root, weights and failed_bones name joints and bones by their "
        "position in joints and bones (from 0); id, head_id, tail_id, parent_id and root_id "
        "are the stable ids documents and recipes use";
    rig["joints"] = nlohmann::json::array();
    for (const Joint& joint : skeleton.joints())
        rig["joints"].push_back(
            {{"id", joint.id},
             {"position", {joint.position.x(), joint.position.y(), joint.position.z()}}});
    rig["root"] = skeleton.indexOfJoint(skeleton.root());
    rig["root_id"] = skeleton.root();
    rig["bones"] = nlohmann::json::array();
    for (const Bone& bone : skeleton.bones()) {
        auto parent = skeleton.parentBone(bone.id);
        rig["bones"].push_back({{"id", bone.id},
                                {"head", skeleton.indexOfJoint(bone.head)},
                                {"tail", skeleton.indexOfJoint(bone.tail)},
                                {"parent", parent ? skeleton.indexOfBone(*parent) : -1},
                                {"head_id", bone.head},
                                {"tail_id", bone.tail},
                                {"parent_id", parent ? nlohmann::json(*parent) : nlohmann::json()},
                                {"length", skeleton.boneLength(bone.id)}});
    }
    if (!meshFile.empty())
        rig["mesh"] = meshFile;
    rig["vertex_count"] = part.mesh.vertices.size();
    rig["vertices"] = nlohmann::json::array();
    for (const Vec3& p : part.mesh.vertices)
        rig["vertices"].push_back({p.x(), p.y(), p.z()});
    // The file names bones by their place in "bones", as glTF's skins do.
    const SkinWeights byIndex = weightsByIndex(skeleton, part.weights);
    rig["weights"] = nlohmann::json::array();
    for (const auto& vertex : byIndex.perVertex) {
        nlohmann::json influences = nlohmann::json::array();
        for (const auto& [bone, weight] : vertex)
            influences.push_back({bone, weight});
        rig["weights"].push_back(std::move(influences));
    }
    rig["failed_bones"] = byIndex.failedBones;
    // One English line, as the command line prints it (the file is for tools).
    rig["warning"] = englishText(byIndex.warnings);
    return rig.dump(1) + "\n";
}

std::vector<std::array<std::uint8_t, 3>> dominantBoneColours(const Part& part) {
    auto colourOf = [](int bone) {
        // Golden-ratio hue steps keep neighbouring bone indices apart.
        double hue = std::fmod(0.13 + 0.618033988749895 * bone, 1.0) * 6.0;
        double x = 1.0 - std::abs(std::fmod(hue, 2.0) - 1.0);
        std::array<double, 3> rgb{};
        switch (static_cast<int>(hue)) {
            case 0:
                rgb = {1, x, 0};
                break;
            case 1:
                rgb = {x, 1, 0};
                break;
            case 2:
                rgb = {0, 1, x};
                break;
            case 3:
                rgb = {0, x, 1};
                break;
            case 4:
                rgb = {x, 0, 1};
                break;
            default:
                rgb = {1, 0, x};
                break;
        }
        return std::array<std::uint8_t, 3>{static_cast<std::uint8_t>(60 + 180 * rgb[0]),
                                           static_cast<std::uint8_t>(60 + 180 * rgb[1]),
                                           static_cast<std::uint8_t>(60 + 180 * rgb[2])};
    };
    std::vector<std::array<std::uint8_t, 3>> colours;
    colours.reserve(part.weights.perVertex.size());
    const BoneIndexTable index(part.skeleton);
    for (const auto& vertex : part.weights.perVertex)
        colours.push_back(colourOf(vertex.empty() ? 0 : std::max(index[leadingBone(vertex)], 0)));
    return colours;
}

}  // namespace rigmesh
