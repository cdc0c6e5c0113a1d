#include "model/preview/PlacementPreview.h"

#include "model/commands/MovePartCommand.h"

namespace rigmesh::model {

PlacementPreview::PlacementPreview(Document& document, PartId id)
    : PartPreview(document, id, document.part(id).placement) {}

void PlacementPreview::put(const Placement& placement) {
    document_->setPlacement(id_, placement);
}

bool PlacementPreview::commit() {
    if (!previewing() || current() == original())
        return false;
    document_->undoStack()->push(
        new MovePartCommand(*document_, id_, original(), current(), CommandMerging::Never));
    committed();
    return true;
}

}  // namespace rigmesh::model
