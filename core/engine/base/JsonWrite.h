// The JSON shapes documents use for geometry: a list of 2D points as one
// flat list [x0, y0, x1, y1, ...], a 3D point as [x, y, z].
#pragma once

#include <nlohmann/json.hpp>
#include <vector>

#include "base/Types.h"

namespace rigmesh::jsonwrite {

inline nlohmann::json flatVec2s(const std::vector<Vec2>& points) {
    nlohmann::json flat = nlohmann::json::array();
    for (const Vec2& p : points) {
        flat.push_back(p.x());
        flat.push_back(p.y());
    }
    return flat;
}

inline nlohmann::json vec3(const Vec3& p) {
    return nlohmann::json::array({p.x(), p.y(), p.z()});
}

}  // namespace rigmesh::jsonwrite
