#include "pipeline/LocalFrame.h"

#include <cmath>

#include <Eigen/Geometry>

#include "pipeline/SketchToSurface.h"

namespace rigmesh {

LocalFrame localFrameOf(const std::vector<Vec2>& stroke) {
    Eigen::AlignedBox2d box;
    for (const Vec2& p : stroke)
        if (p.allFinite())
            box.extend(p);
    LocalFrame frame;
    if (box.isEmpty())
        return frame;
    // Half the sum, not the sum halved: the sum of two huge coordinates may overflow.
    frame.centre = 0.5 * box.min() + 0.5 * box.max();
    const Vec2 size = 0.5 * box.max() - 0.5 * box.min();  // halves first: no overflow
    const double diagonal = 2.0 * std::hypot(size.x(), size.y());
    if (std::isfinite(diagonal) && diagonal > 0)
        frame.scale = std::ldexp(1.0, std::ilogb(diagonal));
    return frame;
}

std::vector<Vec2> toLocal(const LocalFrame& frame, const std::vector<Vec2>& stroke) {
    std::vector<Vec2> local;
    local.reserve(stroke.size());
    for (const Vec2& p : stroke)
        local.push_back(frame.toLocal(p));
    return local;
}

void mapToWorld(const LocalFrame& frame, SketchToSurfaceResult& result) {
    auto move = [&](Vec2& p) { p = frame.toWorld(p); };
    for (Vec2& p : result.polygon.points)
        move(p);
    result.polygon.spacing *= frame.scale;
    for (Vec2& p : result.decomposition.axis.cdt.points)
        move(p);
    auto moveSections = [&](std::vector<CylinderSections>& cylinders) {
        for (CylinderSections& cylinder : cylinders) {
            for (CrossSection& section : cylinder.sections) {
                move(section.left);
                move(section.right);
                section.spacing *= frame.scale;
            }
            for (CrossSection& chord : cylinder.axisChords) {
                move(chord.left);
                move(chord.right);
            }
            if (cylinder.startTip)
                move(*cylinder.startTip);
            if (cylinder.endTip)
                move(*cylinder.endTip);
            for (double& position : cylinder.axisPosition)
                position *= frame.scale;
            cylinder.startTipPosition *= frame.scale;
            cylinder.endTipPosition *= frame.scale;
        }
    };
    moveSections(result.cylinders);
    moveSections(result.surfaceCylinders);
    if (result.surfaceRegions)
        for (Vec2& p : result.surfaceRegions->axis.cdt.points)
            move(p);
    for (Vec3& v : result.surface.mesh.vertices)
        v = frame.toWorld(v);
    for (VertexOrigin& origin : result.surface.origins)
        origin.axisPosition *= frame.scale;
    result.targetEdgeLength *= frame.scale;
}

}  // namespace rigmesh
