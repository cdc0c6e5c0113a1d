#include "UndoStatus.h"

#include <QUndoGroup>
#include <QUndoStack>

namespace rigmesh::widgets {

UndoStatus::UndoStatus(QUndoGroup& group, std::function<void(const QString&)> show, QObject* parent)
    : QObject(parent), show_(std::move(show)) {
    connect(&group, &QUndoGroup::activeStackChanged, this, &UndoStatus::follow);
    connect(&group, &QUndoGroup::indexChanged, this, &UndoStatus::indexChanged);
    follow(group.activeStack());
}

void UndoStatus::follow(QUndoStack* stack) {
    stack_ = stack;
    remember();
}

void UndoStatus::remember() {
    index_ = stack_ ? stack_->index() : 0;
    count_ = stack_ ? stack_->count() : 0;
    next_ = stack_ && index_ < count_ ? stack_->command(index_) : nullptr;
}

void UndoStatus::indexChanged(int index) {
    if (!stack_)
        return;
    // An undo moves the index back over the same commands (a push never
    // does); a redo moves it forward over the command that was next (a push
    // puts a new command there).
    if (index < index_ && stack_->count() == count_)
        show_(tr("Undone: %1").arg(stack_->text(index)));
    else if (index > index_ && next_ && stack_->command(index_) == next_)
        show_(tr("Redone: %1").arg(stack_->text(index - 1)));
    remember();
}

}  // namespace rigmesh::widgets
