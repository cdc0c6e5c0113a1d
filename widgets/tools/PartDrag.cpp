#include "tools/PartDrag.h"

#include <Eigen/Geometry>

#include "mesh/MeshChecks.h"
#include "viewport/ViewMath.h"
#include "viewport/Viewport.h"

namespace rigmesh::widgets {

PartDrag::PartDrag(Viewport& viewport, model::PartId part, const QPointF& pixel, bool turning)
    : preview_(*viewport.document(), part),
      grabPoint_(viewport.sketchPlanePoint(pixel)),
      grabPixel_(pixel),
      turning_(turning) {}

void PartDrag::dragTo(const Viewport& viewport, const QPointF& pixel) {
    const model::Document& document = *viewport.document();
    if (!document.contains(part()))
        return;
    const model::Placement& start = preview_.original();
    model::Placement target = start;
    if (turning_) {
        const Vec3 centre = start.toWorld(boundingBox(document.part(part()).part->mesh).center());
        const QVector3D screen = viewport.camera().project(toQt(centre), QSizeF(viewport.size()));
        const double sweep = screenSweep(QPointF(screen.x(), screen.y()), grabPixel_, pixel);
        const Eigen::Quaterniond turn(
            Eigen::AngleAxisd(sweep, toEigen(viewport.camera().forward())));
        target.rotation = (turn * start.rotation).normalized();
        target.translation = turn * (start.translation - centre) + centre;
    } else {
        target.translation += toEigen(viewport.viewPlanePoint(pixel, grabPoint_) - grabPoint_);
    }
    preview_.preview(target);
}

std::vector<model::PartId> PartDrag::overlapping(const model::Document& document) const {
    std::vector<model::PartId> parts;
    if (!document.contains(part()))
        return parts;
    const Eigen::AlignedBox3d box = model::worldBounds(document.part(part()));
    for (const model::PartNode& node : document.parts())
        if (node.id != part() && node.visible && node.part &&
            model::worldBounds(node).intersects(box))
            parts.push_back(node.id);
    return parts;
}

}  // namespace rigmesh::widgets
