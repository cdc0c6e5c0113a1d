#include "model/PoseChange.h"

#include <QCoreApplication>
#include <memory>

#include "model/commands/KeyPoseCommand.h"

namespace rigmesh::model {

void pushPoseChange(Document& document, PartId id, QUndoCommand* command) {
    std::unique_ptr<QUndoCommand> owned(command);
    QUndoStack& stack = *document.undoStack();
    if (!document.autoKey()) {
        stack.push(owned.release());
        return;
    }
    const QString text = QCoreApplication::translate("rigmesh::model::PoseChange", "%1 and key")
                             .arg(command->text());
    stack.beginMacro(text);
    stack.push(owned.release());
    try {
        // Made after the pose command ran, so it keys the new pose.
        stack.push(new KeyPoseCommand(document, id, document.currentTime()));
    } catch (...) {
        stack.endMacro();
        stack.undo();  // the pose change alone is not what was asked for
        throw;
    }
    stack.endMacro();
}

}  // namespace rigmesh::model
