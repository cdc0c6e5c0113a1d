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

// The target edge length, relative to the stroke's bounding-box diagonal d:
// 0 (automatic, d / 60) or between d / 250 (about 17 times the automatic
// triangle count) and d / 4 (a few sections per limb). Finer would let one
// number ask for millions of triangles.
inline constexpr double kFinestEdgeFraction = 1.0 / 250.0;
inline constexpr double kCoarsestEdgeFraction = 1.0 / 4.0;
// Throws rigmesh::Error when options.targetEdgeLength is not 0 or in those
// bounds. A stroke without points (an imported part) only needs a finite
// length >= 0.
void checkBuildOptions(const std::vector<Vec2>& stroke, const BuildOptions& options);

// Throws rigmesh::Error with a user-readable reason on a bad stroke or options.
std::shared_ptr<const Part> buildPart(const std::vector<Vec2>& stroke, const QString& name,
                                      const BuildOptions& options);

}  // namespace rigmesh::model
