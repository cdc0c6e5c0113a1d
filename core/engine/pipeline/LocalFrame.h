// The frame the pipeline works in: centred on the stroke's bounding box and
// scaled by the power of two nearest its diagonal, so every stage sees
// coordinates of order one whatever the sketch's position and size. A sketch
// translated to 1e15 keeps all the precision its own coordinates have, and no
// constant of the algorithms meets a number of 1e-30 or 1e40. Scaling by a
// power of two is exact; only the translation back to the world rounds.
#pragma once

#include <vector>

#include "base/Types.h"

namespace rigmesh {

struct SketchToSurfaceResult;

struct LocalFrame {
    Vec2 centre = Vec2::Zero();
    double scale = 1.0;  // world length of one local unit, a power of two

    Vec2 toLocal(const Vec2& world) const { return (world - centre) / scale; }
    Vec2 toWorld(const Vec2& local) const { return centre + scale * local; }
    Vec3 toWorld(const Vec3& local) const {
        return Vec3(centre.x() + scale * local.x(), centre.y() + scale * local.y(),
                    scale * local.z());
    }
};

// The frame of a stroke's finite points (the identity when it has none, or
// only one distinct point: the cleaner rejects those with a message).
LocalFrame localFrameOf(const std::vector<Vec2>& stroke);

std::vector<Vec2> toLocal(const LocalFrame& frame, const std::vector<Vec2>& stroke);

// Moves every position and length of a result built in `frame` to the world.
void mapToWorld(const LocalFrame& frame, SketchToSurfaceResult& result);

}  // namespace rigmesh
