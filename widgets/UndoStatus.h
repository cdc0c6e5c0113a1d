// The status bar after an undo or redo: a message about what was done (a
// cut's "Cut biped in 20 ms") must not outlive its undo, so an undo shows
// "Undone: <step>" and a redo "Redone: <step>" in its place, whichever way
// the step was undone (Edit menu, keys, the History dock).
#pragma once

#include <QObject>
#include <QPointer>
#include <functional>

class QUndoGroup;
class QUndoStack;
class QUndoCommand;

namespace rigmesh::widgets {

class UndoStatus : public QObject {
    Q_OBJECT
  public:
    // `show` puts a message in the status bar (for a few seconds).
    UndoStatus(QUndoGroup& group, std::function<void(const QString&)> show, QObject* parent);

  private:
    void follow(QUndoStack* stack);
    void indexChanged(int index);
    void remember();

    std::function<void(const QString&)> show_;
    QPointer<QUndoStack> stack_;
    int index_ = 0;
    int count_ = 0;
    const QUndoCommand* next_ = nullptr;  // the command a redo would redo
};

}  // namespace rigmesh::widgets
