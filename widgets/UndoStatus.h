// The status bar after an undo or redo: a message about what was done (a
// cut's "Cut biped in 20 ms") must not outlive its undo, so an undo shows
// "Undone: <step>" and a redo "Redone: <step>" in its place, whichever way
// the step was undone (Edit menu, keys, the History dock).
//
// Only the stack's index and count are compared, never a command's
// address: a command can be deleted (a new step replaces the steps that
// could be redone) and its address reused.
#pragma once

#include <QObject>
#include <QPointer>
#include <functional>
#include <optional>

class QAction;
class QAbstractItemView;
class QUndoGroup;
class QUndoStack;

namespace rigmesh::widgets {

class UndoStatus : public QObject {
    Q_OBJECT
  public:
    // `show` puts a message in the status bar (for a few seconds). `redo`
    // (the Redo action) and `history` (the History dock's view) are the
    // ways a user redoes a step.
    UndoStatus(QUndoGroup& group, QAction* redo, QAbstractItemView* history,
               std::function<void(const QString&)> show, QObject* parent);

  private:
    void follow(QUndoStack* stack);
    void indexChanged(int index);
    void remember();
    void redoRequested();

    std::function<void(const QString&)> show_;
    QPointer<QUndoStack> stack_;
    int index_ = 0;
    int count_ = 0;
    // The index a forward move reached that was a redo or a new step
    // replacing the one step that could be redone (the stack looks the same
    // after both); a redo request in the same event makes it a redo.
    std::optional<int> ambiguousForward_;
};

}  // namespace rigmesh::widgets
