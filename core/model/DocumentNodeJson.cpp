#include "model/DocumentNodeJson.h"

#include "model/ClipModes.h"

namespace rigmesh::model {

using nlohmann::json;

namespace {

json vec2s(const std::vector<Vec2>& points) {
    json flat = json::array();
    for (const Vec2& p : points) {
        flat.push_back(p.x());
        flat.push_back(p.y());
    }
    return flat;
}

json vec3(const Vec3& p) {
    return json::array({p.x(), p.y(), p.z()});
}

json pairs(const std::vector<std::vector<std::pair<int, double>>>& lists) {
    json out = json::array();
    for (const auto& list : lists) {
        json flat = json::array();
        for (const auto& [index, value] : list) {
            flat.push_back(index);
            flat.push_back(value);
        }
        out.push_back(std::move(flat));
    }
    return out;
}

// boneNames: [[bone id, name], ...] in bone id order.
json boneNamesJson(const std::map<BoneId, std::string>& names) {
    json out = json::array();
    for (const auto& [bone, name] : names)
        out.push_back(json::array({bone, name}));
    return out;
}

json partJson(const Part& part) {
    json mesh;
    mesh["vertices"] = json::array();
    for (const Vec3& v : part.mesh.vertices)
        for (int k = 0; k < 3; ++k)
            mesh["vertices"].push_back(v[k]);
    mesh["faces"] = json::array();
    for (const auto& f : part.mesh.faces)
        for (int k = 0; k < 3; ++k)
            mesh["faces"].push_back(f[k]);

    json origins = {{"kind", json::array()},
                    {"region", json::array()},
                    {"section", json::array()},
                    {"axisPosition", json::array()},
                    {"onOutline", json::array()}};
    for (const VertexOrigin& o : part.origins) {
        origins["kind"].push_back(static_cast<int>(o.kind));
        origins["region"].push_back(o.region);
        origins["section"].push_back(o.section);
        origins["axisPosition"].push_back(o.axisPosition);
        origins["onOutline"].push_back(o.onOutline);
    }

    json joints = {{"ids", json::array()}, {"positions", json::array()}};
    for (const Joint& j : part.skeleton.joints()) {
        joints["ids"].push_back(j.id);
        for (int k = 0; k < 3; ++k)
            joints["positions"].push_back(j.position[k]);
    }
    json bones = {{"ids", json::array()}, {"heads", json::array()}, {"tails", json::array()}};
    for (const Bone& b : part.skeleton.bones()) {
        bones["ids"].push_back(b.id);
        bones["heads"].push_back(b.head);
        bones["tails"].push_back(b.tail);
    }

    return {
        {"name", part.name},
        {"outline", vec2s(part.outline)},
        {"mesh", std::move(mesh)},
        {"origins", std::move(origins)},
        {"mirror", part.mirror},
        {"skeleton",
         {{"joints", std::move(joints)},
          {"bones", std::move(bones)},
          {"root", part.skeleton.root()}}},
        {"weights",
         {{"perVertex", pairs(part.weights.perVertex)},
          {"failedBones", part.weights.failedBones},
          {"warning", part.weights.warning}}},
        {"knownClosestBones", pairs(part.knownClosestBones)},
        {"boneNames", boneNamesJson(part.boneNames)},
    };
}

// rotations: [[joint, w, x, y, z], ...] in joint id order (std::map).
json poseJson(const rigmesh::Pose& pose) {
    json rotations = json::array();
    for (const auto& [joint, q] : pose.rotations)
        rotations.push_back(json::array({joint, q.w(), q.x(), q.y(), q.z()}));
    return {{"rotations", std::move(rotations)}, {"rootTranslation", vec3(pose.rootTranslation)}};
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
         {{"translation", vec3(node.placement.translation)},
          {"rotation", json::array({q.w(), q.x(), q.y(), q.z()})}}},
        {"stroke", vec2s(node.stroke)},
        {"options",
         {{"targetEdgeLength", node.options.targetEdgeLength},
          {"smoothing", node.options.smoothing}}},
    };
    if (node.part)
        out["part"] = partJson(*node.part);
    out["pose"] = poseJson(node.pose);
    out["pinned"] = json::array();
    for (const JointId joint : node.pinnedJoints)
        out["pinned"].push_back(joint);
    out["clip"] = clipJson(node.clip);
    return out;
}

}  // namespace rigmesh::model
