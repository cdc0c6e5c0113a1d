// Every change of a document through its undo stack that can go wrong: a
// push (QUndoStack::push runs the command's redo() before it keeps the
// command), an undo, a redo or a jump in the history. A command's redo() or
// undo() may throw: a rigmesh::Error for input it refuses, or a
// std::logic_error from a programming error. Either way these functions
// leave the document as it was before the call (its parts, part-id counter,
// timeline, current frame and selection, put back through the mutation API
// of Document so that every view hears of it) and the stack consistent with
// it, and let the exception go on to the caller, which reports it
// (widgets/UserAction.h in the studio).
//
// After a failed push the command is deleted and the stack is as it was.
// After a failed redo (Redo, a click further down the History) the command
// that failed and the ones after it leave the history: a command that threw
// half-way may hold half-changed state of its own. After a failed undo the
// history is cleared for the same reason (the command that failed is below
// everything else left); the document keeps its modified state.
#pragma once

#include <QString>
#include <QUndoCommand>
#include <memory>
#include <utility>

#include "model/Document.h"

namespace rigmesh::model {

// Pushes `command` onto the document's stack (it may merge with the last
// command, as QUndoStack::push does).
void pushCommand(Document& document, std::unique_ptr<QUndoCommand> command);
// Takes ownership of `command`.
void pushCommand(Document& document, QUndoCommand* command);

// QUndoStack::undo() and redo() of the document's stack.
void undoCommand(Document& document);
void redoCommand(Document& document);

// Moves the stack to `index` (0 = before the first command) one command at
// a time, as a click in the History does (QUndoStack::setIndex); stops at
// the first command that throws, with the commands before it done.
void moveToUndoIndex(Document& document, int index);

// Deletes the commands after the stack's index (what Redo would redo) and
// nothing else.
void dropRedoHistory(QUndoStack& stack);

// Runs `change`, which changes the document only through its undo stack,
// and puts the document back as it was if it throws (then rethrows). Not
// for changes that leave a macro open: pushMacro closes its macro.
template <typename Change>
void changeOrRestore(Document& document, Change&& change);

// Runs `pushes` (pushCommand calls) inside one macro `text`: one undo step.
// If it throws, the macro is closed, undone and dropped from the history,
// the document is put back as it was, and the exception goes on.
template <typename Pushes>
void pushMacro(Document& document, const QString& text, Pushes&& pushes);

namespace detail {

// What a document held before a change: the contents and selection.
class DocumentSnapshot {
  public:
    explicit DocumentSnapshot(const Document& document);
    // Puts the document back to the snapshot's contents and selection.
    void restore(Document& document) const;

  private:
    DocumentContents contents_;
    Selection selection_;
};

// Closes the open macro after a failure inside it and takes it off the
// stack (its undo(); if that throws too, the whole history goes).
void abandonMacro(Document& document);

}  // namespace detail

template <typename Change>
void changeOrRestore(Document& document, Change&& change) {
    const detail::DocumentSnapshot before(document);
    try {
        std::forward<Change>(change)();
    } catch (...) {
        before.restore(document);
        throw;
    }
}

template <typename Pushes>
void pushMacro(Document& document, const QString& text, Pushes&& pushes) {
    changeOrRestore(document, [&] {
        QUndoStack& stack = *document.undoStack();
        stack.beginMacro(text);
        try {
            std::forward<Pushes>(pushes)();
        } catch (...) {
            detail::abandonMacro(document);
            throw;
        }
        stack.endMacro();
    });
}

}  // namespace rigmesh::model
