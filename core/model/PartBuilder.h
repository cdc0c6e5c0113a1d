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

// Throws rigmesh::Error with a user-readable reason on a bad stroke or options.
std::shared_ptr<const Part> buildPart(const std::vector<Vec2>& stroke, const QString& name,
                                      const BuildOptions& options);

}  // namespace rigmesh::model
