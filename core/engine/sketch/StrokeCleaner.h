// Cleaning a raw sketched stroke into the closed, simple, uniformly sampled
// polygon that the decomposition (paper section 2.1) starts from.
#pragma once

#include <vector>

#include "base/Types.h"

namespace rigmesh {

struct StrokeCleanOptions {
    double relativeSpacing =
        1.0 / 60.0;        // resample spacing as a fraction of the bounding-box diagonal
    double spacing = 0.0;  // absolute spacing; overrides relativeSpacing when > 0
    int smoothingIterations =
        2;  // light Laplacian smoothing of the resampled closed polygon (removes mouse jitter)
};

struct CleanPolygon {
    std::vector<Vec2>
        points;      // closed implicitly (last != first), counter-clockwise, uniform spacing
    double spacing;  // the spacing actually used
};

// Validates, closes, resamples, smooths and orients `raw`. Every step works
// relative to the stroke's size, so scaling the input scales the result.
// Throws rigmesh::Error with a message for the user when the stroke has
// non-finite or too few distinct points, encloses no area, or crosses itself.
CleanPolygon cleanStroke(const std::vector<Vec2>& raw, const StrokeCleanOptions& options = {});

}  // namespace rigmesh
