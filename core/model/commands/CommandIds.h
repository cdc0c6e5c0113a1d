// QUndoCommand::id() values of the commands that merge (mergeWith).
#pragma once

namespace rigmesh::model {

enum CommandId : int {
    MovePartCommandId = 1001,
    SetPoseCommandId = 1002,
};

// Whether a command merges with the one before it of the same kind (recipe
// steps, scripted moves) or stands alone (a whole interactive drag, a typed
// value: model/preview/PartPreview.h), so two drags are two undo steps.
enum class CommandMerging { Consecutive, Never };

}  // namespace rigmesh::model
