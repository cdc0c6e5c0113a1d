#include "pipeline/SketchToSurface.h"

#include <chrono>
#include <cmath>
#include <limits>
#include <optional>

#include "base/Error.h"
#include "geometry/ConstrainedTriangulation.h"
#include "pipeline/LocalFrame.h"
#include "pipeline/RigRegionOrigins.h"
#include "pipeline/SurfaceLimits.h"
#include "sketch/ConcaveCorners.h"
#include "sketch/ThinPartRefinement.h"
#include "surface/CapBases.h"
#include "surface/CapPatches.h"
#include "surface/EndSectionSnap.h"

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

    // Every stage runs in the stroke's local frame; lengths given in world
    // units are converted there and everything is moved back at the end.
    const LocalFrame frame = localFrameOf(stroke);
    StrokeCleanOptions cleanOptions = options.stroke;
    cleanOptions.spacing /= frame.scale;
    result.polygon = cleanStroke(toLocal(frame, stroke), cleanOptions);
    // The surface is built on the outline with its concave corners rounded
    // (sketch/ConcaveCorners.h); the rig, and the part's outline, keep the
    // outline as drawn.
    std::vector<Vec2> builtOutline = surfaceOutline(result.polygon.points, result.polygon.spacing);
    const bool rounded = builtOutline != result.polygon.points;
    result.polygon.points = refineThinParts(result.polygon.points, result.polygon.spacing);
    builtOutline =
        rounded ? refineThinParts(builtOutline, result.polygon.spacing) : result.polygon.points;
    SurfaceOptions surfaceOptions = options.surface;
    if (!(std::isfinite(surfaceOptions.targetEdgeLength) && surfaceOptions.targetEdgeLength >= 0))
        throw Error(MessageId::EdgeLengthNotPositive);

    surfaceOptions.targetEdgeLength = surfaceOptions.targetEdgeLength > 0
                                          ? surfaceOptions.targetEdgeLength / frame.scale
                                          : result.polygon.spacing;
    // Size and position first: the vertex estimate needs a finite outline.
    checkOutlineScale(frame, result.polygon, result.polygon.spacing);
    checkEdgeLengthBudget(frame, result.polygon, surfaceOptions.targetEdgeLength);
    result.targetEdgeLength = surfaceOptions.targetEdgeLength;
    ms.clean = clock.lap();

    PolygonTriangulation cdt = triangulatePolygon(result.polygon.points);
    std::optional<PolygonTriangulation> builtCdt;
    if (rounded)
        builtCdt = triangulatePolygon(builtOutline);
    ms.triangulate = clock.lap();
    ChordalAxis axis = computeChordalAxis(std::move(cdt), options.decomposition.axis);
    std::optional<ChordalAxis> builtAxis;
    if (rounded)
        builtAxis = computeChordalAxis(std::move(*builtCdt), options.decomposition.axis);
    ms.chordalAxis = clock.lap();
    // The rig's regions leave pruned bumps out (2.1); the surface's take in
    // those off bodies (RigRegionOrigins.h).
    DecompositionOptions rigOptions = options.decomposition;
    rigOptions.bumpHeightFactor = std::numeric_limits<double>::infinity();
    result.decomposition = decompose(axis, rigOptions);
    Decomposition surfaceRegions =
        decompose(rounded ? std::move(*builtAxis) : std::move(axis), options.decomposition);
    // The surface's caps begin at chords square to their limbs (CapBases.h);
    // the rig's keep the paper's end chords.
    bool capBasesMoved = false;
    for (std::size_t c = 0; c < surfaceRegions.cylinders.size(); ++c) {
        CylinderRegion moved = withCapBases(surfaceRegions, static_cast<int>(c));
        if (moved.chords.size() != surfaceRegions.cylinders[c].chords.size()) {
            surfaceRegions.cylinders[c] = std::move(moved);
            capBasesMoved = true;
        }
    }
    bool split = rounded || capBasesMoved || !sameRegions(surfaceRegions, result.decomposition);
    ms.decompose = clock.lap();
    auto sectionsOf = [&](const Decomposition& decomposition) {
        std::vector<CylinderSections> cylinders;
        for (std::size_t c = 0; c < decomposition.cylinders.size(); ++c)
            cylinders.push_back(buildCrossSections(decomposition, static_cast<int>(c),
                                                   surfaceOptions.targetEdgeLength,
                                                   options.sections));
        return cylinders;
    };
    result.cylinders = sectionsOf(result.decomposition);
    std::vector<CylinderSections> surfaceCylinders =
        split ? sectionsOf(surfaceRegions) : result.cylinders;
    // A cap whose slices cannot follow its outline is a patch on the
    // surface (CapPatches.h); the rig keeps the cap.
    if (patchCapsWithGaps(surfaceRegions, surfaceCylinders, surfaceOptions.targetEdgeLength,
                          options.sections))
        split = true;
    const Decomposition& builtRegions = split ? surfaceRegions : result.decomposition;
    // The surface's sections near fixed end chords follow the outline
    // (EndSectionSnap.h); the rig's stay as smoothed, so its joints do.
    snapSectionsNearEndsToOutline(surfaceCylinders, builtRegions);
    const std::vector<CylinderSections>& builtCylinders = surfaceCylinders;
    ms.crossSections = clock.lap();
    SurfaceOptions unsmoothed = surfaceOptions;
    unsmoothed.smooth = false;
    result.surface = buildSurface(builtRegions, builtCylinders, unsmoothed);
    ms.surface = clock.lap();
    if (surfaceOptions.smooth)
        smoothSurface(result.surface, builtRegions, builtCylinders, surfaceOptions);
    if (rounded)
        mapOriginsByNearestSection(result.surface, surfaceRegions, surfaceCylinders,
                                   result.decomposition, result.cylinders);
    else if (split)
        mapOriginsToRigRegions(result.surface, surfaceRegions, surfaceCylinders,
                               result.decomposition, result.cylinders);
    if (split)
        result.surfaceRegions = std::move(surfaceRegions);
    result.surfaceCylinders = std::move(surfaceCylinders);
    ms.smoothing = clock.lap();

    mapToWorld(frame, result);
    checkBuiltMesh(result.surface.mesh, result.surface.mirror);
    ms.checks = clock.lap();
    ms.total = ms.clean + ms.triangulate + ms.chordalAxis + ms.decompose + ms.crossSections +
               ms.surface + ms.smoothing + ms.checks;
    return result;
}

}  // namespace rigmesh
