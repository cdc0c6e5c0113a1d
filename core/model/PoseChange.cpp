#include "model/PoseChange.h"

#include <QCoreApplication>
#include <memory>

#include "model/GuardedUndo.h"
#include "model/commands/KeyPoseCommand.h"

namespace rigmesh::model {

void pushPoseChange(Document& document, PartId id, QUndoCommand* command) {
    std::unique_ptr<QUndoCommand> owned(command);
    if (!document.autoKey()) {
        pushCommand(document, std::move(owned));
        return;
    }
    const QString text = QCoreApplication::translate("rigmesh::model::PoseChange", "%1 and key")
                             .arg(command->text());
    // A key that cannot be made takes the pose change with it: the pose
    // change alone is not what was asked for.
    pushMacro(document, text, [&] {
        pushCommand(document, std::move(owned));
        // Made after the pose command ran, so it keys the new pose.
        pushCommand(document,
                    std::make_unique<KeyPoseCommand>(document, id, document.currentTime()));
    });
}

}  // namespace rigmesh::model
