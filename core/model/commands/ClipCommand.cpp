#include "model/commands/ClipCommand.h"

namespace rigmesh::model {

ClipCommand::ClipCommand(Document& document, PartId id, ClipEdit edit, QUndoCommand* parent)
    : QUndoCommand(parent),
      document_(document),
      id_(id),
      index_(document.indexOf(id)),
      edit_(std::move(edit)) {
    setObsolete(edit_.changesNothing());
}

void ClipCommand::redo() {
    document_.editClip(id_, edit_);
}

void ClipCommand::undo() {
    document_.editClip(id_, edit_.inverse());
}

}  // namespace rigmesh::model
