#include "io/GltfAnimations.h"

#include <assimp/anim.h>

#include <Eigen/Geometry>
#include <algorithm>
#include <cstring>
#include <limits>
#include <map>
#include <nlohmann/json.hpp>

#include "base/Error.h"

namespace rigmesh {
namespace {

using nlohmann::json;

constexpr int kFloat = 5126;  // glTF componentType FLOAT

// Appends accessors to the JSON's lists and their floats to the buffer.
class AccessorWriter {
  public:
    AccessorWriter(json& gltf, std::string& bin) : gltf_(gltf), bin_(bin) {
        for (const char* list : {"accessors", "bufferViews"})
            if (!gltf_.contains(list))
                gltf_[list] = json::array();
    }

    // One accessor of `values` in groups of `components`; min and max for
    // an animation's input, which glTF requires.
    int add(const std::vector<float>& values, int components, const char* type, bool bounds) {
        while (bin_.size() % 4 != 0)
            bin_.push_back('\0');
        const std::size_t offset = bin_.size();
        const std::size_t bytes = values.size() * sizeof(float);
        bin_.resize(offset + bytes);
        if (bytes > 0)
            std::memcpy(bin_.data() + offset, values.data(), bytes);
        json& views = gltf_["bufferViews"];
        views.push_back({{"buffer", 0}, {"byteOffset", offset}, {"byteLength", bytes}});
        json accessor = {{"bufferView", views.size() - 1},
                         {"byteOffset", 0},
                         {"componentType", kFloat},
                         {"count", values.size() / static_cast<std::size_t>(components)},
                         {"type", type}};
        if (bounds) {
            std::vector<float> low(components, std::numeric_limits<float>::max());
            std::vector<float> high(components, std::numeric_limits<float>::lowest());
            for (std::size_t i = 0; i < values.size(); ++i) {
                const std::size_t c = i % static_cast<std::size_t>(components);
                low[c] = std::min(low[c], values[i]);
                high[c] = std::max(high[c], values[i]);
            }
            accessor["min"] = low;
            accessor["max"] = high;
        }
        json& accessors = gltf_["accessors"];
        accessors.push_back(std::move(accessor));
        return static_cast<int>(accessors.size()) - 1;
    }

  private:
    json& gltf_;
    std::string& bin_;
};

template <typename Key>
std::vector<float> timesOf(const Key* keys, unsigned count, double ticksPerSecond) {
    std::vector<float> times(count);
    for (unsigned k = 0; k < count; ++k)
        times[k] = static_cast<float>(keys[k].mTime / ticksPerSecond);
    return times;
}

std::vector<float> vectorsOf(const aiVectorKey* keys, unsigned count) {
    std::vector<float> values;
    values.reserve(3 * std::size_t{count});
    for (unsigned k = 0; k < count; ++k)
        values.insert(values.end(), {keys[k].mValue.x, keys[k].mValue.y, keys[k].mValue.z});
    return values;
}

// glTF stores quaternions as x, y, z, w.
std::vector<float> rotationsOf(const aiQuatKey* keys, unsigned count) {
    std::vector<float> values;
    values.reserve(4 * std::size_t{count});
    for (unsigned k = 0; k < count; ++k)
        values.insert(values.end(),
                      {keys[k].mValue.x, keys[k].mValue.y, keys[k].mValue.z, keys[k].mValue.w});
    return values;
}

// A node an animation targets must not have a `matrix` (glTF 2.0, 5.25:
// the validator's ANIMATION_CHANNEL_TARGET_NODE_MATRIX). Assimp writes
// `matrix` when the scene it exports has no animation, as ours does while
// we write them (SceneExport.cpp): the matrix becomes translation,
// rotation and scale.
void matrixToTrs(json& node) {
    if (!node.contains("matrix") || !node["matrix"].is_array() || node["matrix"].size() != 16)
        return;
    Eigen::Matrix4d m;
    for (int k = 0; k < 16; ++k)  // column-major
        m(k % 4, k / 4) = node["matrix"][static_cast<std::size_t>(k)].get<double>();
    Eigen::Matrix3d linear = m.topLeftCorner<3, 3>();
    const Eigen::Vector3d scale(linear.col(0).norm(), linear.col(1).norm(), linear.col(2).norm());
    for (int k = 0; k < 3; ++k)
        if (scale[k] > 0)
            linear.col(k) /= scale[k];
    const Eigen::Quaterniond rotation = Eigen::Quaterniond(linear).normalized();
    node.erase("matrix");
    node["translation"] = {m(0, 3), m(1, 3), m(2, 3)};
    node["rotation"] = {rotation.x(), rotation.y(), rotation.z(), rotation.w()};
    if (!scale.isApprox(Eigen::Vector3d::Ones(), 1e-9))
        node["scale"] = {scale.x(), scale.y(), scale.z()};
}

}  // namespace

std::string withGltfAnimations(const std::string& gltfJson, std::string& bin,
                               const std::vector<const aiAnimation*>& animations) {
    if (animations.empty())
        return gltfJson;
    json gltf = json::parse(gltfJson, nullptr, false);
    if (gltf.is_discarded() || !gltf.is_object() || !gltf.contains("nodes") ||
        !gltf["nodes"].is_array())
        throw Error(MessageId::ExportGltfInvalidJson);
    std::map<std::string, int> nodeNamed;
    for (std::size_t n = 0; n < gltf["nodes"].size(); ++n) {
        const json& node = gltf["nodes"][n];
        if (node.contains("name") && node["name"].is_string())
            nodeNamed.emplace(node["name"].get<std::string>(), static_cast<int>(n));
    }
    AccessorWriter writer(gltf, bin);
    if (!gltf.contains("animations"))
        gltf["animations"] = json::array();
    for (const aiAnimation* animation : animations) {
        const double ticksPerSecond =
            animation->mTicksPerSecond > 0 ? animation->mTicksPerSecond : 1.0;
        json channels = json::array(), samplers = json::array();
        for (unsigned c = 0; c < animation->mNumChannels; ++c) {
            const aiNodeAnim& channel = *animation->mChannels[c];
            const auto node = nodeNamed.find(channel.mNodeName.C_Str());
            if (node == nodeNamed.end())
                throw Error(MessageId::ExportAnimationNoNode,
                            std::string(channel.mNodeName.C_Str()));
            matrixToTrs(gltf["nodes"][static_cast<std::size_t>(node->second)]);
            // The three paths share one input when their keys share times
            // (AssimpAnimationBuilder writes them so), else each has its own.
            const std::vector<float> rotationTimes =
                timesOf(channel.mRotationKeys, channel.mNumRotationKeys, ticksPerSecond);
            const int shared =
                rotationTimes.empty() ? -1 : writer.add(rotationTimes, 1, "SCALAR", true);
            auto inputFor = [&](const std::vector<float>& times) {
                return shared >= 0 && times == rotationTimes ? shared
                                                             : writer.add(times, 1, "SCALAR", true);
            };
            auto sample = [&](int input, int output, const char* path) {
                samplers.push_back(
                    {{"input", input}, {"output", output}, {"interpolation", "LINEAR"}});
                channels.push_back({{"sampler", samplers.size() - 1},
                                    {"target", {{"node", node->second}, {"path", path}}}});
            };
            if (channel.mNumPositionKeys > 0)
                sample(inputFor(timesOf(channel.mPositionKeys, channel.mNumPositionKeys,
                                        ticksPerSecond)),
                       writer.add(vectorsOf(channel.mPositionKeys, channel.mNumPositionKeys), 3,
                                  "VEC3", true),
                       "translation");
            if (channel.mNumRotationKeys > 0)
                sample(shared,
                       writer.add(rotationsOf(channel.mRotationKeys, channel.mNumRotationKeys), 4,
                                  "VEC4", true),
                       "rotation");
            if (channel.mNumScalingKeys > 0)
                sample(inputFor(
                           timesOf(channel.mScalingKeys, channel.mNumScalingKeys, ticksPerSecond)),
                       writer.add(vectorsOf(channel.mScalingKeys, channel.mNumScalingKeys), 3,
                                  "VEC3", true),
                       "scale");
        }
        json written = {{"channels", std::move(channels)}, {"samplers", std::move(samplers)}};
        if (animation->mName.length > 0)
            written["name"] = animation->mName.C_Str();
        gltf["animations"].push_back(std::move(written));
    }
    while (bin.size() % 4 != 0)
        bin.push_back('\0');
    if (!gltf.contains("buffers") || !gltf["buffers"].is_array() || gltf["buffers"].empty())
        gltf["buffers"] = json::array({json::object()});
    gltf["buffers"][0]["byteLength"] = bin.size();
    return gltf.dump();
}

}  // namespace rigmesh
