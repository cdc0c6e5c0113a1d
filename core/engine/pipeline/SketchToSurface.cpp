#include "pipeline/SketchToSurface.h"

#include <chrono>

#include "geometry/ConstrainedTriangulation.h"

namespace rigmesh {
namespace {

class StageClock {
  public:
    double lap() {
        auto now = std::chrono::steady_clock::now();
        double ms = std::chrono::duration<double, std::milli>(now - last_).count();
        last_ = now;
        return ms;
    }

  private:
    std::chrono::steady_clock::time_point last_ = std::chrono::steady_clock::now();
};

}  // namespace

SketchToSurfaceResult sketchToSurface(const std::vector<Vec2>& stroke,
                                      const SketchToSurfaceOptions& options) {
    SketchToSurfaceResult result;
    StageClock clock;
    auto& ms = result.milliseconds;

    result.polygon = cleanStroke(stroke, options.stroke);
    ms.clean = clock.lap();
    PolygonTriangulation cdt = triangulatePolygon(result.polygon.points);
    ms.triangulate = clock.lap();
    ChordalAxis axis = computeChordalAxis(std::move(cdt), options.decomposition.axis);
    ms.chordalAxis = clock.lap();
    result.decomposition = decompose(std::move(axis), options.decomposition);
    ms.decompose = clock.lap();

    SurfaceOptions surfaceOptions = options.surface;
    if (!(surfaceOptions.targetEdgeLength > 0))
        surfaceOptions.targetEdgeLength = result.polygon.spacing;
    result.targetEdgeLength = surfaceOptions.targetEdgeLength;
    for (std::size_t c = 0; c < result.decomposition.cylinders.size(); ++c)
        result.cylinders.push_back(buildCrossSections(result.decomposition, static_cast<int>(c),
                                                      surfaceOptions.targetEdgeLength,
                                                      options.sections));
    ms.crossSections = clock.lap();
    result.surface = buildSurface(result.decomposition, result.cylinders, surfaceOptions);
    ms.surface = clock.lap();
    ms.total =
        ms.clean + ms.triangulate + ms.chordalAxis + ms.decompose + ms.crossSections + ms.surface;
    return result;
}

}  // namespace rigmesh
