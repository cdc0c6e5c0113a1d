// Parses CBOR into a json value with a limit on nesting: nlohmann's CBOR
// reader recurses once per level, so a few kilobytes of nested arrays would
// otherwise overflow the stack before any content check runs.
#pragma once

#include <cstdint>
#include <nlohmann/json.hpp>

namespace rigmesh::model {

// Throws nlohmann::json::exception on malformed or truncated CBOR and
// rigmesh::Error when arrays and maps nest deeper than maxDepth.
nlohmann::json parseBoundedCbor(const std::uint8_t* begin, const std::uint8_t* end, int maxDepth);

}  // namespace rigmesh::model
