// QUndoCommand::id() values of the commands that merge (mergeWith).
#pragma once

namespace rigmesh::model {

enum CommandId : int {
    MovePartCommandId = 1001,
    SetPoseCommandId = 1002,
};

}  // namespace rigmesh::model
