// Edit > Undo and Redo through model/GuardedUndo: the undo group's own
// actions keep their "Undo <step>" text and enabled state, but a trigger
// runs model::undoCommand / redoCommand on the current document inside
// runUserAction instead of QUndoGroup::undo / redo, so a step that throws
// is reported and the document is left as it was.
#pragma once

#include <QString>
#include <functional>

#include "UserAction.h"

class QAction;
class QUndoGroup;

namespace rigmesh::model {
class Document;
}

namespace rigmesh::widgets {

// `undo` and `redo` are `group`'s createUndoAction / createRedoAction;
// `undoName` and `redoName` name them in a failure's text; `document` gives
// the current document (none: nothing happens).
void guardUndoActions(QUndoGroup& group, QAction* undo, const QString& undoName, QAction* redo,
                      const QString& redoName, std::function<model::Document*()> document,
                      ReportFailure report);

}  // namespace rigmesh::widgets
