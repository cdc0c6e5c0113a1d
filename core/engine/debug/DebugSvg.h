// A picture of what the engine decided for a sketch, so a person can check
// it: the outline, the CDT by triangle kind, the chordal axis before and after
// pruning, and the regions and cross sections the surface was built on (they
// differ from the rig's where the surface-only steps of ARCHITECTURE section 2 apply).
#pragma once

#include <string>

#include "pipeline/SketchToSurface.h"

namespace rigmesh {

// Extra drawing a later stage adds on top (e.g. the skeleton), in sketch
// coordinates: line segments and points.
struct DebugOverlay {
    std::vector<std::array<Vec2, 2>> segments;
    std::vector<Vec2> points;
    std::string colour = "#d62728";
};

std::string debugSvg(const SketchToSurfaceResult& result,
                     const std::vector<DebugOverlay>& overlays = {});

}  // namespace rigmesh
