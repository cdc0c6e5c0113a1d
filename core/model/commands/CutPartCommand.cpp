#include "model/commands/CutPartCommand.h"

#include <nlohmann/json.hpp>

#include "base/Error.h"
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
        throw Error("The part has no surface to cut.");
    // The plane in the part's own frame.
    CutRequest request;
    const Placement& placement = original_.placement;
    request.point = placement.rotation.conjugate() * (spec.point - placement.translation);
    request.normal = placement.rotation.conjugate() * spec.normal;
    request.style = spec.style;
    request.edgeLength = original_.options.targetEdgeLength;
    CutResult cut = cutPart(*original_.part, request);
    milliseconds_ = cut.milliseconds;
    for (int k = 0; k < 2; ++k) {
        const QString name = !spec.names[k].isEmpty() ? spec.names[k]
                             : k == 0                 ? original_.name
                                                      : tr("%1 2").arg(original_.name);
        cut.pieces[k].name = name.toStdString();
        pieces_[k] = editedNode(original_, std::make_shared<const Part>(std::move(cut.pieces[k])));
        pieces_[k].name = name;
    }
    pieces_[1].id = document.allocatePartId();
    spec_.names[0] = pieces_[0].name;
    spec_.names[1] = pieces_[1].name;
    setText(tr("Cut %1").arg(original_.name));
}

void CutPartCommand::redo() {
    document_.removePart(id_);
    document_.insertPart(index_, pieces_[0]);
    document_.insertPart(index_ + 1, pieces_[1]);
}

void CutPartCommand::undo() {
    document_.removePart(pieces_[1].id);
    document_.removePart(id_);
    document_.insertPart(index_, original_);
    document_.releasePartId(pieces_[1].id);
}

nlohmann::json CutPartCommand::recipeStep() const {
    return {{"command", "cut"},
            {"part", index_},
            {"plane",
             {{"point", {spec_.point.x(), spec_.point.y(), spec_.point.z()}},
              {"normal", {spec_.normal.x(), spec_.normal.y(), spec_.normal.z()}}}},
            {"style", spec_.style == CutStyle::Smooth ? "smooth" : "sharp"},
            {"names", {spec_.names[0].toStdString(), spec_.names[1].toStdString()}}};
}

}  // namespace rigmesh::model
