#include "model/commands/ClipCommand.h"

#include "model/ClipLimits.h"

namespace rigmesh::model {

ClipCommand::ClipCommand(Document& document, PartId id, rigmesh::Clip to, QUndoCommand* parent)
    : QUndoCommand(parent),
      document_(document),
      id_(id),
      index_(document.indexOf(id)),
      from_(document.part(id).clip),
      to_(std::move(to)) {
    // Throws before anything is pushed: a clip too long to bake or save.
    checkClipSpan(to_, "\"" + document.part(id).name.toStdString() + "\"");
    setObsolete(identicalClips(from_, to_));
}

void ClipCommand::redo() {
    document_.setClip(id_, to_);
}

void ClipCommand::undo() {
    document_.setClip(id_, from_);
}

}  // namespace rigmesh::model
