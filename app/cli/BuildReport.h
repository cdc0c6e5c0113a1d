// What `rigmesh build` reports: statistics as JSON and as a short summary.
#pragma once

#include <nlohmann/json.hpp>
#include <string>

#include "mesh/MeshChecks.h"
#include "pipeline/SketchToPart.h"

namespace rigmesh::cli {

// `meshChecksMilliseconds` is the time analyseMesh took to make `report`; it
// is a stage of its own and part of "ms_total".
nlohmann::json buildStatistics(const std::string& name, const SketchToPartResult& rigged,
                               const MeshReport& report, double meshChecksMilliseconds);

// A few human-readable lines for the terminal.
std::string buildSummary(const nlohmann::json& statistics);

}  // namespace rigmesh::cli
