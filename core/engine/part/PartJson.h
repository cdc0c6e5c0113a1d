// A Part as JSON and back (documents, the import worker's parts): every
// field of the engine value, so that writing and reading give it back bit
// for bit. Reading trusts nothing: types, index ranges, finite numbers,
// weights non-negative and summing to 1 over bones the skeleton has, a
// skeleton that is a tree; it throws rigmesh::Error naming what is wrong.
//
// Skin weights, failed bones and known closest bones name bones by stable id
// (keys "byBoneId", "failedBoneIds", "knownClosestByBoneId"). Documents of
// format version 1 named them by position in the bone list ("perVertex",
// "failedBones", "knownClosestBones"); partFromJson reads those too and
// converts them to ids against the part's skeleton.
#pragma once

#include <nlohmann/json.hpp>

#include "part/Part.h"

namespace rigmesh {

nlohmann::json partToJson(const Part& part);
Part partFromJson(const nlohmann::json& object);

}  // namespace rigmesh
