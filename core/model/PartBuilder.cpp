#include "model/PartBuilder.h"

#include <Eigen/Geometry>
#include <cmath>
#include <cstdio>
#include <string>

#include "base/Error.h"

namespace rigmesh::model {
namespace {

std::string shortNumber(double value) {
    char text[32];
    std::snprintf(text, sizeof text, "%.4g", value);
    return text;
}

}  // namespace

SketchToPartOptions engineOptions(const BuildOptions& options) {
    SketchToPartOptions engine;
    engine.surface.surface.targetEdgeLength = options.targetEdgeLength;
    engine.surface.surface.smooth = options.smoothing;
    return engine;
}

void checkBuildOptions(const std::vector<Vec2>& stroke, const BuildOptions& options) {
    const double length = options.targetEdgeLength;
    if (!std::isfinite(length) || length < 0)
        throw Error("The target edge length must be 0 (automatic) or a positive length.");
    if (length == 0 || stroke.empty())
        return;
    Eigen::AlignedBox2d box;
    for (const Vec2& p : stroke)
        box.extend(p);
    const double diagonal = box.diagonal().norm();
    if (!std::isfinite(diagonal))
        return;  // the stroke itself is rejected by the engine with its own reason
    if (length < kFinestEdgeFraction * diagonal || length > kCoarsestEdgeFraction * diagonal)
        throw Error("The target edge length " + shortNumber(length) +
                    " is out of range for this sketch: use 0 (automatic) or a length between " +
                    shortNumber(kFinestEdgeFraction * diagonal) + " and " +
                    shortNumber(kCoarsestEdgeFraction * diagonal) +
                    " (1/250 to 1/4 of the sketch's size).");
}

std::shared_ptr<const Part> buildPart(const std::vector<Vec2>& stroke, const QString& name,
                                      const BuildOptions& options) {
    checkBuildOptions(stroke, options);
    SketchToPartResult result = sketchToPart(stroke, name.toStdString(), engineOptions(options));
    return std::make_shared<const Part>(std::move(result.part));
}

}  // namespace rigmesh::model
