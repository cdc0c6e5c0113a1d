// How the studio pushes a pose change (a pose drag, a typed rotation, Reset
// Pose): on its own, or with auto-key on (Document::autoKey) as
// one undo step "<change> and key" that also keys the new pose at the
// current frame, as Blender's auto keying does.
#pragma once

#include <QUndoCommand>

#include "model/Document.h"

namespace rigmesh::model {

// Takes ownership of `command`, which poses part `id`. Throws rigmesh::Error
// (nothing pushed) when the key cannot be made.
void pushPoseChange(Document& document, PartId id, QUndoCommand* command);

}  // namespace rigmesh::model
