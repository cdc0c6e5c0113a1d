// An activity bar for work of unknown length: a block that slides along a
// track, moved a step at a time by its owner. QProgressBar's busy mode
// animates at the style's 60 frames a second, and every frame recomposes the
// whole window around the OpenGL viewport; with software OpenGL that alone
// stalled the event loop for tens of milliseconds. A few steps a second show
// the same "still working" at a fraction of the cost.
#pragma once

#include <QWidget>

namespace rigmesh::widgets {

class BusyBar : public QWidget {
    Q_OBJECT
  public:
    explicit BusyBar(QWidget* parent = nullptr);

    // Moves the block one step along (and back at the ends).
    void step();
    // Puts the block back at the start.
    void reset();
    QSize sizeHint() const override;

  protected:
    void paintEvent(QPaintEvent* event) override;

  private:
    int position_ = 0;  // the block's step along the track
    int direction_ = 1;
};

}  // namespace rigmesh::widgets
