#include "GuardedUndoActions.h"

#include <QAction>
#include <QUndoGroup>
#include <utility>

#include "model/Document.h"
#include "model/GuardedUndo.h"

namespace rigmesh::widgets {

void guardUndoActions(QUndoGroup& group, QAction* undo, const QString& undoName, QAction* redo,
                      const QString& redoName, std::function<model::Document*()> document,
                      ReportFailure report) {
    // Every connection from the actions to the group: their trigger.
    undo->disconnect(&group);
    redo->disconnect(&group);
    const auto step = [document = std::move(document), report = std::move(report)](
                          const QString& name, void (*move)(model::Document&)) {
        model::Document* current = document();
        if (current)
            runUserAction(name, report, [&] { move(*current); });
    };
    QObject::connect(undo, &QAction::triggered, undo,
                     [step, undoName] { step(undoName, model::undoCommand); });
    QObject::connect(redo, &QAction::triggered, redo,
                     [step, redoName] { step(redoName, model::redoCommand); });
}

}  // namespace rigmesh::widgets
