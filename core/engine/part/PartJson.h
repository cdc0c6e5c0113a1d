// A Part as JSON and back (documents, the import worker's parts): every
// field of the engine value, so that writing and reading give it back bit
// for bit. Reading trusts nothing: types, index ranges, finite numbers,
// weights non-negative and summing to 1, a skeleton that is a tree; it
// throws rigmesh::Error naming what is wrong.
#pragma once

#include <nlohmann/json.hpp>

#include "part/Part.h"

namespace rigmesh {

nlohmann::json partToJson(const Part& part);
Part partFromJson(const nlohmann::json& object);

}  // namespace rigmesh
