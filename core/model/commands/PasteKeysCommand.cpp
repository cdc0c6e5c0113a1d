#include "model/commands/PasteKeysCommand.h"

#include <nlohmann/json.hpp>

#include "base/Error.h"
#include "model/recipe/RecipeJson.h"

namespace rigmesh::model {

namespace {

ClipEdit pasted(const PartNode& node, const std::map<double, rigmesh::Pose>& keys) {
    if (keys.empty())
        throw Error(MessageId::NoKeysToPaste);
    std::vector<double> times;
    for (const auto& [time, pose] : keys)
        times.push_back(time);
    return localClipEdit(node.clip, times, [&](rigmesh::Clip& clip) {
        for (const auto& [time, pose] : keys)
            clip.setKey(time, pose);
    });
}

}  // namespace

PasteKeysCommand::PasteKeysCommand(Document& document, PartId id,
                                   std::map<double, rigmesh::Pose> keys, QUndoCommand* parent)
    : ClipCommand(document, id, pasted(document.part(id), keys), parent), keys_(std::move(keys)) {
    setText(tr("Paste %n key(s) into %1", nullptr, static_cast<int>(keys_.size()))
                .arg(document.part(id).name));
}

bool PasteKeysCommand::fitsSkeleton(const PartNode& node,
                                    const std::map<double, rigmesh::Pose>& keys) {
    for (const auto& [time, pose] : keys)
        for (const auto& [joint, rotation] : pose.rotations)
            if (!node.part || !node.part->skeleton.hasJoint(joint))
                return false;
    return true;
}

nlohmann::json PasteKeysCommand::recipeStep() const {
    nlohmann::json keys = nlohmann::json::array();
    for (const auto& [time, pose] : keys_)
        keys.push_back({{"time", time},
                        {"rotations", recipe::rotationsJson(pose)},
                        {"rootTranslation", recipe::vec3Json(pose.rootTranslation)}});
    return {{"command", "paste_keys"}, {"part", partIndex()}, {"keys", std::move(keys)}};
}

}  // namespace rigmesh::model
