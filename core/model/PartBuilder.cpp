#include "model/PartBuilder.h"

#include <Eigen/Geometry>
#include <cmath>
#include <cstdio>
#include <string>

#include "base/Error.h"

namespace rigmesh::model {
namespace {}  // namespace

SketchToPartOptions engineOptions(const BuildOptions& options) {
    SketchToPartOptions engine;
    engine.surface.surface.targetEdgeLength = options.targetEdgeLength;
    engine.surface.surface.smooth = options.smoothing;
    engine.mirrorJoints = options.mirrorJoints;
    return engine;
}

void checkBuildOptions(const std::vector<Vec2>&, const BuildOptions& options) {
    const double length = options.targetEdgeLength;
    if (!std::isfinite(length) || length < 0)
        throw Error(MessageId::PartEdgeLengthNotPositive);
}

std::shared_ptr<const Part> buildPart(const std::vector<Vec2>& stroke, const QString& name,
                                      const BuildOptions& options) {
    checkBuildOptions(stroke, options);
    SketchToPartResult result = sketchToPart(stroke, name.toStdString(), engineOptions(options));
    return std::make_shared<const Part>(std::move(result.part));
}

BuiltPart buildPartForDocument(const Document& document, const std::vector<Vec2>& stroke,
                               const QString& name, const BuildOptions& options) {
    return buildPartAtDocumentLength(documentEdgeLength(document), stroke, name, options);
}

BuiltPart buildPartAtDocumentLength(double documentLength, const std::vector<Vec2>& stroke,
                                    const QString& name, const BuildOptions& options) {
    checkBuildOptions(stroke, options);
    BuildOptions used = options;
    if (used.targetEdgeLength == 0.0)
        used.targetEdgeLength = documentLength;
    auto build = [&](const BuildOptions& o) {
        SketchToPartResult result = sketchToPart(stroke, name.toStdString(), engineOptions(o));
        used.targetEdgeLength = result.surface.targetEdgeLength;
        return std::make_shared<const Part>(std::move(result.part));
    };
    if (options.targetEdgeLength == 0.0 && used.targetEdgeLength > 0.0) {
        try {
            return {build(used), used};
        } catch (const Error&) {
            // Too coarse (or too fine) for this sketch: its own length.
            used.targetEdgeLength = 0.0;
        }
    }
    std::shared_ptr<const Part> part = build(used);
    return {std::move(part), used};
}

double documentEdgeLength(const Document& document, PartId ignored) {
    for (const PartNode& node : document.parts())
        if (!node.stroke.empty() && node.id != ignored)
            return node.options.targetEdgeLength;
    return 0.0;
}

}  // namespace rigmesh::model
