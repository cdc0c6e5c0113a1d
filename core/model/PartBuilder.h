// Builds the engine Part of a sketch with a part's build options. Runs
// before any command is pushed: a bad stroke throws rigmesh::Error (a user
// message) and the document is never touched.
#pragma once

#include <QString>
#include <memory>
#include <vector>

#include "base/Types.h"
#include "model/PartNode.h"
#include "pipeline/SketchToPart.h"

namespace rigmesh::model {

SketchToPartOptions engineOptions(const BuildOptions& options);

// Throws rigmesh::Error when options.targetEdgeLength is not finite and >= 0
// (0 = automatic). How fine a length a sketch allows is the engine's call
// (pipeline/SurfaceLimits.h: at most kMaxSurfaceVertices vertices), checked
// when the part is built.
void checkBuildOptions(const std::vector<Vec2>& stroke, const BuildOptions& options);

// Throws rigmesh::Error with a user-readable reason on a bad stroke or options.
std::shared_ptr<const Part> buildPart(const std::vector<Vec2>& stroke, const QString& name,
                                      const BuildOptions& options);

}  // namespace rigmesh::model
