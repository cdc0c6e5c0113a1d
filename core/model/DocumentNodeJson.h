// The writing half of the .rigmesh format (DocumentFile.h describes it):
// one part node as the JSON value that is stored as CBOR. Every double is
// written as is, so it round-trips bit for bit.
#pragma once

#include <nlohmann/json.hpp>

#include "model/PartNode.h"

namespace rigmesh::model {

nlohmann::json documentNodeJson(const PartNode& node);

}  // namespace rigmesh::model
