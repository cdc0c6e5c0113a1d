#include "model/preview/PlacementPreview.h"

#include "model/GuardedUndo.h"
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
    // Guarded (model/GuardedUndo.h): a redo() that throws leaves the previewed
    // state on the document and the preview open, for the tool to revert.
    pushCommand(*document_,
                new MovePartCommand(*document_, id_, original(), current(), CommandMerging::Never));
    committed();
    return true;
}

}  // namespace rigmesh::model
