#include "model/PartBuilder.h"

#include <cmath>

#include "base/Error.h"

namespace rigmesh::model {

SketchToPartOptions engineOptions(const BuildOptions& options) {
    SketchToPartOptions engine;
    engine.surface.surface.targetEdgeLength = options.targetEdgeLength;
    engine.surface.surface.smooth = options.smoothing;
    return engine;
}

std::shared_ptr<const Part> buildPart(const std::vector<Vec2>& stroke, const QString& name,
                                      const BuildOptions& options) {
    if (!std::isfinite(options.targetEdgeLength) || options.targetEdgeLength < 0)
        throw Error("The target edge length must be 0 (automatic) or a positive length.");
    SketchToPartResult result = sketchToPart(stroke, name.toStdString(), engineOptions(options));
    return std::make_shared<const Part>(std::move(result.part));
}

}  // namespace rigmesh::model
