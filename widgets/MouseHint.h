// The first-run hint: a translucent card over the bottom of
// the view with the three mouse gestures a newcomer needs (left-drag does the
// tool's work, middle-drag orbits, the wheel zooms). It shows until it is
// clicked or the first part is made, once per user (QSettings
// `hints/mouseShown`); Help > Mouse Gestures shows it again.
#pragma once

#include <QFrame>

#include "viewport/MouseBindings.h"

class QLabel;

namespace rigmesh::widgets {

class MouseHint : public QFrame {
    Q_OBJECT
  public:
    // Over `area` (kept at its bottom centre as it resizes).
    explicit MouseHint(QWidget* area);
    // Shows the card unless the user has dismissed it before.
    void showOnFirstRun();
    // Hides it and remembers that the user has seen it.
    void dismiss();
    // The view gestures the card names follow the bindings.
    void setMouseBindings(MouseBindings bindings);

  protected:
    bool eventFilter(QObject* watched, QEvent* event) override;
    void mousePressEvent(QMouseEvent* event) override;

  private:
    void place();
    QWidget* area_;
    QLabel* text_;
};

}  // namespace rigmesh::widgets
