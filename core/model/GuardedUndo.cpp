#include "model/GuardedUndo.h"

#include <QSignalBlocker>
#include <algorithm>

namespace rigmesh::model {

namespace detail {

DocumentSnapshot::DocumentSnapshot(const Document& document)
    : contents_(document.contents()), selection_(document.selection()) {}

void DocumentSnapshot::restore(Document& document) const {
    document.restoreContents(contents_, selection_);
}

}  // namespace detail

namespace {

// Whether the stack holds `command` (a pointer compared, never read: after a
// merge QUndoStack::push has deleted it).
bool stackHolds(const QUndoStack& stack, const QUndoCommand* command) {
    for (int i = 0; i < stack.count(); ++i)
        if (stack.command(i) == command)
            return true;
    return false;
}

// Clears the history and keeps the document's modified state. For a
// modified document without a word of "clean" in between: clear() alone
// would announce a clean stack and resetClean() a modified one again (an
// Autosave discards its recovery file on clean).
void forgetHistory(Document& document) {
    QUndoStack& stack = *document.undoStack();
    if (!document.isModified()) {
        stack.clear();
        return;
    }
    {
        const QSignalBlocker quiet(&stack);
        stack.clear();
        stack.resetClean();
    }
    // What clear() announces, but the clean state.
    emit stack.indexChanged(0);
    emit stack.canUndoChanged(false);
    emit stack.undoTextChanged(QString());
    emit stack.canRedoChanged(false);
    emit stack.redoTextChanged(QString());
}

}  // namespace

namespace detail {

void abandonMacro(Document& document) {
    QUndoStack& stack = *document.undoStack();
    stack.endMacro();
    try {
        stack.undo();
    } catch (...) {
        forgetHistory(document);  // the caller puts the document back
        return;
    }
    dropRedoHistory(stack);
}

}  // namespace detail

// QUndoStack has no call for it: a push deletes the redo tail (and keeps
// the clean state only if it lies before), and an undo of an obsolete
// command deletes it without running its undo(). Both announce the new
// index, count and texts, so the actions and the History follow. (A push
// of an obsolete command would delete it and the tail silently.)
void dropRedoHistory(QUndoStack& stack) {
    if (stack.index() == stack.count())
        return;
    auto* marker = new QUndoCommand;
    stack.push(marker);
    marker->setObsolete(true);
    stack.undo();
}

void pushCommand(Document& document, std::unique_ptr<QUndoCommand> command) {
    QUndoStack& stack = *document.undoStack();
    const detail::DocumentSnapshot before(document);
    QUndoCommand* raw = command.release();
    try {
        stack.push(raw);
    } catch (...) {
        // push() keeps the command only after its redo() (and a merge) ran.
        if (!stackHolds(stack, raw))
            delete raw;
        before.restore(document);
        throw;
    }
}

void pushCommand(Document& document, QUndoCommand* command) {
    pushCommand(document, std::unique_ptr<QUndoCommand>(command));
}

namespace {

// One step of the stack (`step`: QUndoStack::undo or redo, which move the
// index only after the command's undo() or redo() returned). When the
// command throws, the document goes back to that index's state and
// `afterFailure` makes the stack fit it.
template <typename Step, typename AfterFailure>
void guardedStep(Document& document, Step step, AfterFailure afterFailure) {
    const detail::DocumentSnapshot before(document);
    try {
        step(*document.undoStack());
    } catch (...) {
        before.restore(document);
        afterFailure();
        throw;
    }
}

}  // namespace

void undoCommand(Document& document) {
    if (document.undoStack()->canUndo())
        guardedStep(
            document, [](QUndoStack& stack) { stack.undo(); }, [&] { forgetHistory(document); });
}

void redoCommand(Document& document) {
    if (document.undoStack()->canRedo())
        guardedStep(
            document, [](QUndoStack& stack) { stack.redo(); },
            [&] { dropRedoHistory(*document.undoStack()); });
}

void moveToUndoIndex(Document& document, int index) {
    const QUndoStack& stack = *document.undoStack();
    index = std::clamp(index, 0, stack.count());
    while (stack.index() != index) {
        const int from = stack.index();
        if (from < index)
            redoCommand(document);
        else
            undoCommand(document);
        if (stack.index() == from)
            break;  // an obsolete command went instead: nothing more to move
    }
}

}  // namespace rigmesh::model
