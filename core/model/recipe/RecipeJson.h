// The values of recipe steps in JSON, both ways: vectors, quaternions
// [w, x, y, z], placements, build options, stroke points and pose rotations.
// Writers give exact values (doubles print with round-trip precision);
// readers throw rigmesh::Error with the reason only (the runner adds the
// step).
#pragma once

#include <Eigen/Geometry>
#include <map>
#include <nlohmann/json.hpp>
#include <string>
#include <vector>

#include "base/Types.h"
#include "model/PartNode.h"
#include "pose/Pose.h"

namespace rigmesh::model::recipe {

nlohmann::json vec3Json(const Vec3& v);
nlohmann::json quaternionJson(const Eigen::Quaterniond& q);
// {"translation": [x, y, z], "rotation": [w, x, y, z]}
nlohmann::json placementJson(const Placement& placement);
// {"edgeLength": L, "smoothing": bool}
nlohmann::json optionsJson(const BuildOptions& options);
// [[x, y], ...]
nlohmann::json pointsJson(const std::vector<Vec2>& points);
// {"<joint id>": [w, x, y, z], ...}
nlohmann::json rotationsJson(const rigmesh::Pose& pose);

// `what` names the value in messages by its place in the recipe, in the
// recipe's own words ("\"target\"", "\"points\" [2]", "\"plane\" \"point\""), so
// a message reads the same in every language.
double readNumber(const nlohmann::json& value, const std::string& what);
bool readBool(const nlohmann::json& value, const std::string& what);
std::string readText(const nlohmann::json& value, const std::string& what);
Vec3 readVec3(const nlohmann::json& value, const std::string& what);
// A finite, non-zero quaternion; used exactly as given when its norm is 1
// within 1e-12, normalised otherwise.
Eigen::Quaterniond readQuaternion(const nlohmann::json& value, const std::string& what);
// The fields given replace those of `base`; unknown fields are errors.
Placement readPlacement(const nlohmann::json& value, const Placement& base);
BuildOptions readOptions(const nlohmann::json& value, const BuildOptions& base);
std::vector<Vec2> readPoints(const nlohmann::json& value);
// Joint ids (decimal strings) to rotations; the ids are not checked against
// a skeleton here.
std::map<JointId, Eigen::Quaterniond> readRotations(const nlohmann::json& value);
JointId readJointId(const nlohmann::json& value, const std::string& what);

}  // namespace rigmesh::model::recipe
