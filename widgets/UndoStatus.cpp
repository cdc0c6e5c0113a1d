#include "UndoStatus.h"

#include <QAbstractItemView>
#include <QAction>
#include <QTimer>
#include <QUndoGroup>
#include <QUndoStack>

namespace rigmesh::widgets {

UndoStatus::UndoStatus(QUndoGroup& group, QAction* redo, QAbstractItemView* history,
                       std::function<void(const QString&)> show, QObject* parent)
    : QObject(parent), show_(std::move(show)) {
    connect(&group, &QUndoGroup::activeStackChanged, this, &UndoStatus::follow);
    connect(&group, &QUndoGroup::indexChanged, this, &UndoStatus::indexChanged);
    // Both are connected after the group's own handlers (the action's redo,
    // the view's move of the index), so they run after the index moved.
    if (redo)
        connect(redo, &QAction::triggered, this, &UndoStatus::redoRequested);
    if (history)
        connect(history, &QAbstractItemView::pressed, this, &UndoStatus::redoRequested);
    follow(group.activeStack());
}

void UndoStatus::follow(QUndoStack* stack) {
    stack_ = stack;
    ambiguousForward_.reset();
    remember();
}

void UndoStatus::remember() {
    index_ = stack_ ? stack_->index() : 0;
    count_ = stack_ ? stack_->count() : 0;
}

void UndoStatus::indexChanged(int index) {
    if (!stack_)
        return;
    ambiguousForward_.reset();
    const int count = stack_->count();
    // An undo moves the index back over the same commands; a new step
    // never moves it back (it deletes the steps after the index, appends
    // itself and moves forward onto it: the count becomes the new index).
    if (index < index_ && count == count_) {
        show_(tr("Undone: %1").arg(stack_->text(index)));
    } else if (index > index_ && count == count_) {
        if (count_ > index_ + 1) {
            // More than one step could be redone: a new step would have
            // dropped them, so the count unchanged means a redo.
            show_(tr("Redone: %1").arg(stack_->text(index - 1)));
        } else {
            // One step could be redone: a redo and a new step in its place
            // leave the same index and count. The redo request (the Redo
            // action, a History row), handled right after, decides.
            ambiguousForward_ = index;
            QTimer::singleShot(0, this, [this] { ambiguousForward_.reset(); });
        }
    }
    remember();
}

void UndoStatus::redoRequested() {
    if (!stack_ || !ambiguousForward_ || *ambiguousForward_ != stack_->index())
        return;
    ambiguousForward_.reset();
    show_(tr("Redone: %1").arg(stack_->text(stack_->index() - 1)));
}

}  // namespace rigmesh::widgets
