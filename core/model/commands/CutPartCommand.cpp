#include "model/commands/CutPartCommand.h"

#include <Eigen/Geometry>
#include <nlohmann/json.hpp>

#include "base/Error.h"
#include "mesh/MeshChecks.h"
#include "model/RigCarryOver.h"

namespace rigmesh::model {

std::unique_ptr<CutPartCommand> CutPartCommand::create(Document& document, PartId part,
                                                       const CutSpec& spec) {
    return std::unique_ptr<CutPartCommand>(new CutPartCommand(document, part, spec));
}

CutPartCommand::CutPartCommand(Document& document, PartId part, const CutSpec& spec)
    : document_(document),
      id_(part),
      index_(document.indexOf(part)),
      spec_(spec),
      original_(document.part(part)) {
    if (!original_.part)
        throw Error(MessageId::CutNoSurface);
    // The plane or the swept stroke in the part's own frame.
    CutRequest request;
    const Placement& placement = original_.placement;
    request.point = placement.toLocal(spec.point);
    request.normal = placement.directionToLocal(spec.normal);
    if (!spec.viewStroke.empty()) {
        const Vec3 direction = spec.viewDirection.normalized();
        const Vec3 right = direction.cross(spec.viewUp).normalized();
        const Vec3 up = right.cross(direction);
        if (!right.allFinite() || !direction.allFinite())
            throw Error(MessageId::CutViewInvalid);
        // The view plane through the part's centre.
        const Vec3 centre = placement.toWorld(boundingBox(original_.part->mesh).center());
        for (const Vec2& p : spec.viewStroke)
            request.stroke.push_back(placement.toLocal(centre + p.x() * right + p.y() * up));
        request.sweep = placement.directionToLocal(direction);
    }
    request.style = spec.style;
    request.edgeLength = original_.options.targetEdgeLength;
    CutResult cut = cutPart(*original_.part, request);
    milliseconds_ = cut.milliseconds;
    // The larger piece stays the part (its id, name, place in the list and
    // the selection); the other is new, "<name> cut". Names given (the
    // recipe's) go by the engine's order: behind the cut, then in front.
    const int kept = cut.larger();
    for (int k = 0; k < 2; ++k) {
        const QString name = !spec.names[k].isEmpty() ? spec.names[k]
                             : k == kept              ? original_.name
                                                      : tr("%1 cut").arg(original_.name);
        spec_.names[k] = name;
        cut.pieces[k].name = name.toStdString();
        PartNode& node = pieces_[k == kept ? 0 : 1];
        node = editedNode(original_, std::make_shared<const Part>(std::move(cut.pieces[k])));
        node.name = name;
    }
    pieces_[1].id = document.allocatePartId();
    setText(tr("Cut %1").arg(original_.name));
}

void CutPartCommand::redo() {
    document_.replaceNode(id_, pieces_[0]);
    document_.insertPart(document_.indexOf(id_) + 1, pieces_[1]);
}

void CutPartCommand::undo() {
    document_.removePart(pieces_[1].id);
    document_.replaceNode(id_, original_);
    document_.releasePartId(pieces_[1].id);
}

nlohmann::json CutPartCommand::recipeStep() const {
    auto vec3 = [](const Vec3& v) { return nlohmann::json{v.x(), v.y(), v.z()}; };
    nlohmann::json step = {{"command", "cut"},
                           {"part", index_},
                           {"style", spec_.style == CutStyle::Smooth ? "smooth" : "sharp"},
                           {"names", {spec_.names[0].toStdString(), spec_.names[1].toStdString()}}};
    if (spec_.viewStroke.empty()) {
        step["plane"] = {{"point", vec3(spec_.point)}, {"normal", vec3(spec_.normal)}};
    } else {
        nlohmann::json stroke = nlohmann::json::array();
        for (const Vec2& p : spec_.viewStroke)
            stroke.push_back({p.x(), p.y()});
        step["stroke"] = std::move(stroke);
        step["view"] = {{"direction", vec3(spec_.viewDirection)}, {"up", vec3(spec_.viewUp)}};
    }
    return step;
}

}  // namespace rigmesh::model
