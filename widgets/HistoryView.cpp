#include "HistoryView.h"

#include <QKeyEvent>
#include <QMouseEvent>
#include <QUndoStack>
#include <algorithm>

#include "model/Document.h"
#include "model/GuardedUndo.h"

namespace rigmesh::widgets {

HistoryView::HistoryView(QUndoGroup* group, std::function<model::Document*()> document,
                         ReportFailure report, QWidget* parent)
    : QUndoView(group, parent), document_(std::move(document)), report_(std::move(report)) {}

bool HistoryView::moveTo(int index) {
    model::Document* document = document_ ? document_() : nullptr;
    if (!document)
        return false;
    return runUserAction(tr("History"), report_, [&] { model::moveToUndoIndex(*document, index); });
}

// QAbstractItemView's own press sets the current row, which QUndoView turns
// into QUndoStack::setIndex: unguarded. The press is handled here instead.
void HistoryView::mousePressEvent(QMouseEvent* event) {
    event->accept();
    setFocus(Qt::MouseFocusReason);
    if (event->button() != Qt::LeftButton)
        return;
    const QModelIndex index = indexAt(event->position().toPoint());
    if (!index.isValid())
        return;
    // After the move, as a press in QAbstractItemView says it (UndoStatus
    // tells a redo from a new step by it); not after a failure, whose
    // message stays.
    if (moveTo(index.row()))
        emit pressed(index);
}

void HistoryView::mouseMoveEvent(QMouseEvent* event) {
    // A drag with a button held would move the current row: only hovering
    // goes to the view.
    if (event->buttons() != Qt::NoButton) {
        event->accept();
        return;
    }
    QUndoView::mouseMoveEvent(event);
}

void HistoryView::mouseReleaseEvent(QMouseEvent* event) {
    event->accept();
}

void HistoryView::mouseDoubleClickEvent(QMouseEvent* event) {
    event->accept();
}

void HistoryView::keyPressEvent(QKeyEvent* event) {
    const QUndoStack* stack = this->stack();
    if (!stack) {
        event->ignore();
        return;
    }
    const int index = stack->index();
    const int page = std::max(1, viewport()->height() / std::max(1, sizeHintForRow(0)));
    int target = index;
    switch (event->key()) {
        case Qt::Key_Up:
            target = index - 1;
            break;
        case Qt::Key_Down:
            target = index + 1;
            break;
        case Qt::Key_PageUp:
            target = index - page;
            break;
        case Qt::Key_PageDown:
            target = index + page;
            break;
        case Qt::Key_Home:
            target = 0;
            break;
        case Qt::Key_End:
            target = stack->count();
            break;
        default:
            // Typing would search the rows and move the current one: the
            // keys go on to the window (its shortcuts) instead.
            event->ignore();
            return;
    }
    event->accept();
    moveTo(std::clamp(target, 0, stack->count()));
}

}  // namespace rigmesh::widgets
