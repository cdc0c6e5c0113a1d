#include "model/DocumentNodeJson.h"

#include "base/JsonWrite.h"
#include "model/ClipModes.h"
#include "part/PartJson.h"

namespace rigmesh::model {

using nlohmann::json;

namespace {

// rotations: [[joint, w, x, y, z], ...] in joint id order (std::map).
json poseJson(const rigmesh::Pose& pose) {
    json rotations = json::array();
    for (const auto& [joint, q] : pose.rotations)
        rotations.push_back(json::array({joint, q.w(), q.x(), q.y(), q.z()}));
    return {{"rotations", std::move(rotations)},
            {"rootTranslation", jsonwrite::vec3(pose.rootTranslation)}};
}

// keys: [{time, pose}, ...] in time order.
json clipJson(const rigmesh::Clip& clip) {
    json keys = json::array();
    for (const auto& [time, pose] : clip.keys())
        keys.push_back({{"time", time}, {"pose", poseJson(pose)}});
    return {{"name", clip.name},
            {"framesPerSecond", clip.framesPerSecond()},
            {"interpolation", interpolationName(clip.interpolation)},
            {"playback", playbackName(clip.mode)},
            {"keys", std::move(keys)}};
}

}  // namespace

json documentNodeJson(const PartNode& node) {
    const Eigen::Quaterniond& q = node.placement.rotation;
    json out = {
        {"id", node.id},
        {"name", node.name.toStdString()},
        {"visible", node.visible},
        {"placement",
         {{"translation", jsonwrite::vec3(node.placement.translation)},
          {"rotation", json::array({q.w(), q.x(), q.y(), q.z()})}}},
        {"stroke", jsonwrite::flatVec2s(node.stroke)},
        {"options",
         {{"targetEdgeLength", node.options.targetEdgeLength},
          {"smoothing", node.options.smoothing},
          {"mirrorJoints", node.options.mirrorJoints}}},
    };
    if (node.part)
        out["part"] = partToJson(*node.part);
    out["pose"] = poseJson(node.pose);
    out["pinned"] = json::array();
    for (const JointId joint : node.pinnedJoints)
        out["pinned"].push_back(joint);
    out["clip"] = clipJson(node.clip);
    out["otherClips"] = json::array();
    for (const rigmesh::Clip& clip : node.otherClips)
        out["otherClips"].push_back(clipJson(clip));
    return out;
}

}  // namespace rigmesh::model
