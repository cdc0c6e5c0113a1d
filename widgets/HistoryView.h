// The History dock: QUndoView, whose clicks and keys move the undo stack
// through model/GuardedUndo instead of QUndoStack::setIndex, so that a
// command whose undo() or redo() throws is reported (widgets/UserAction.h)
// with the document as it was, never thrown into Qt's event loop. A click
// on a row goes to that step; Up, Down, Page Up, Page Down, Home and End
// move through the steps as QUndoView's own keys do.
#pragma once

#include <QUndoView>
#include <functional>

#include "UserAction.h"

namespace rigmesh::model {
class Document;
}

namespace rigmesh::widgets {

class HistoryView : public QUndoView {
    Q_OBJECT
  public:
    // `document` gives the document whose stack is the group's active one;
    // `report` shows a failure (the status bar).
    HistoryView(QUndoGroup* group, std::function<model::Document*()> document, ReportFailure report,
                QWidget* parent = nullptr);

  protected:
    void mousePressEvent(QMouseEvent* event) override;
    void mouseMoveEvent(QMouseEvent* event) override;
    void mouseReleaseEvent(QMouseEvent* event) override;
    void mouseDoubleClickEvent(QMouseEvent* event) override;
    void keyPressEvent(QKeyEvent* event) override;

  private:
    // Moves the stack to `index` (0 = before the first step; row r of the
    // view is index r). False when a step threw (reported).
    bool moveTo(int index);

    std::function<model::Document*()> document_;
    ReportFailure report_;
};

}  // namespace rigmesh::widgets
