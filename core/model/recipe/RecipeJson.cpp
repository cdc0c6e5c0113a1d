#include "model/recipe/RecipeJson.h"

#include <cmath>
#include <limits>
#include <set>

#include "base/Error.h"

namespace rigmesh::model::recipe {

using nlohmann::json;

namespace {

const json& arrayOf(const json& value, std::size_t size, const std::string& what) {
    if (!value.is_array() || value.size() != size)
        throw Error(MessageId::RecipeFieldNumberList, what, size);
    return value;
}

void checkFields(const json& value, const std::set<std::string>& known, const std::string& what) {
    if (!value.is_object())
        throw Error(MessageId::RecipeFieldObject, what);
    for (const auto& [key, field] : value.items()) {
        if (!known.contains(key))
            throw Error(MessageId::RecipeFieldUnknown, what, key);
    }
}

}  // namespace

json vec3Json(const Vec3& v) {
    return json::array({v.x(), v.y(), v.z()});
}

json quaternionJson(const Eigen::Quaterniond& q) {
    return json::array({q.w(), q.x(), q.y(), q.z()});
}

json placementJson(const Placement& placement) {
    return {{"translation", vec3Json(placement.translation)},
            {"rotation", quaternionJson(placement.rotation)}};
}

json optionsJson(const BuildOptions& options) {
    return {{"edgeLength", options.targetEdgeLength},
            {"smoothing", options.smoothing},
            {"mirrorJoints", options.mirrorJoints}};
}

json pointsJson(const std::vector<Vec2>& points) {
    json out = json::array();
    for (const Vec2& p : points)
        out.push_back(json::array({p.x(), p.y()}));
    return out;
}

json rotationsJson(const rigmesh::Pose& pose) {
    json out = json::object();
    for (const auto& [joint, q] : pose.rotations)
        out[std::to_string(joint)] = quaternionJson(q);
    return out;
}

double readNumber(const json& value, const std::string& what) {
    if (!value.is_number())
        throw Error(MessageId::RecipeFieldNumber, what);
    const double number = value.get<double>();
    if (!std::isfinite(number))
        throw Error(MessageId::RecipeFieldFiniteNumber, what);
    return number;
}

bool readBool(const json& value, const std::string& what) {
    if (!value.is_boolean())
        throw Error(MessageId::RecipeFieldTrueOrFalse, what);
    return value.get<bool>();
}

std::string readText(const json& value, const std::string& what) {
    if (!value.is_string())
        throw Error(MessageId::RecipeFieldText, what);
    return value.get<std::string>();
}

Vec3 readVec3(const json& value, const std::string& what) {
    const json& list = arrayOf(value, 3, what);
    return Vec3(readNumber(list[0], what), readNumber(list[1], what), readNumber(list[2], what));
}

Eigen::Quaterniond readQuaternion(const json& value, const std::string& what) {
    if (!value.is_array() || value.size() != 4)
        throw Error(MessageId::RecipeFieldQuaternionList, what);
    const json& list = value;
    const Eigen::Quaterniond q(readNumber(list[0], what), readNumber(list[1], what),
                               readNumber(list[2], what), readNumber(list[3], what));
    const double norm = q.norm();
    if (!(norm > 0))
        throw Error(MessageId::RecipeFieldZeroQuaternion, what);
    return std::abs(norm - 1.0) <= 1e-12 ? q : q.normalized();
}

Placement readPlacement(const json& value, const Placement& base) {
    checkFields(value, {"translation", "rotation"}, "\"placement\"");
    Placement out = base;
    if (value.contains("translation"))
        out.translation = readVec3(value["translation"], "\"placement\" \"translation\"");
    if (value.contains("rotation"))
        out.rotation = readQuaternion(value["rotation"], "\"placement\" \"rotation\"");
    return out;
}

BuildOptions readOptions(const json& value, const BuildOptions& base) {
    checkFields(value, {"edgeLength", "smoothing", "mirrorJoints"}, "\"options\"");
    BuildOptions out = base;
    if (value.contains("edgeLength")) {
        out.targetEdgeLength = readNumber(value["edgeLength"], "\"edgeLength\"");
        if (out.targetEdgeLength < 0)
            throw Error(MessageId::RecipeEdgeLength);
    }
    if (value.contains("smoothing"))
        out.smoothing = readBool(value["smoothing"], "\"smoothing\"");
    if (value.contains("mirrorJoints"))
        out.mirrorJoints = readBool(value["mirrorJoints"], "\"mirrorJoints\"");
    return out;
}

std::vector<Vec2> readPoints(const json& value) {
    if (!value.is_array())
        throw Error(MessageId::RecipePointsList);
    std::vector<Vec2> out;
    out.reserve(value.size());
    for (const json& point : value) {
        const std::string what = "\"points\" [" + std::to_string(out.size() + 1) + "]";
        const json& xy = arrayOf(point, 2, what);
        out.emplace_back(readNumber(xy[0], what), readNumber(xy[1], what));
    }
    return out;
}

std::map<JointId, Eigen::Quaterniond> readRotations(const json& value) {
    if (!value.is_object())
        throw Error(MessageId::RecipeRotationsObject);
    std::map<JointId, Eigen::Quaterniond> out;
    for (const auto& [key, rotation] : value.items()) {
        const JointId joint = readJointId(json(key), "\"rotations\" \"" + key + "\"");
        if (!out.emplace(joint, readQuaternion(rotation, "\"rotations\" \"" + key + "\"")).second)
            throw Error(MessageId::RecipeRotationsJointTwice, key);
    }
    return out;
}

JointId readJointId(const json& value, const std::string& what) {
    std::uint64_t id = 0;
    if (value.is_number_integer()) {
        if (value.get<std::int64_t>() < 0)
            throw Error(MessageId::RecipeFieldNotJointId, what);
        id = value.get<std::uint64_t>();
    } else if (value.is_string()) {
        const std::string text = value.get<std::string>();
        if (text.empty() || text.size() > 10 ||
            text.find_first_not_of("0123456789") != std::string::npos)
            throw Error(MessageId::RecipeFieldNotJointId, what);
        id = std::stoull(text);
    } else {
        throw Error(MessageId::RecipeFieldJointIdType, what);
    }
    if (id >= std::numeric_limits<JointId>::max())
        throw Error(MessageId::RecipeFieldNotJointId, what);
    return static_cast<JointId>(id);
}

}  // namespace rigmesh::model::recipe
