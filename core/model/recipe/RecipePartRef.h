// How recipe steps name parts: "part": <index> (0-based, in document order)
// or "part": "<name>" (must name exactly one part).
#pragma once

#include <nlohmann/json.hpp>
#include <string>

#include "model/Document.h"

namespace rigmesh::model::recipe {

// The part a step's "part" value refers to. Throws rigmesh::Error with the
// reason ("there is no part \"arm\"").
PartId resolvePart(const Document& document, const nlohmann::json& reference);

// "part \"arm\"": how messages name a part.
std::string partLabel(const PartNode& node);

}  // namespace rigmesh::model::recipe
