// What `rigmesh build` reports: statistics as JSON and as a short summary.
#pragma once

#include <nlohmann/json.hpp>
#include <string>

#include "mesh/MeshChecks.h"
#include "pipeline/SketchToPart.h"

namespace rigmesh::cli {

nlohmann::json buildStatistics(const std::string& name, const SketchToPartResult& rigged,
                               const MeshReport& report);

// A few human-readable lines for the terminal.
std::string buildSummary(const nlohmann::json& statistics);

}  // namespace rigmesh::cli
