#include "jobs/BusyBar.h"

#include <QPainter>
#include <QPalette>

namespace rigmesh::widgets {

namespace {

// The track holds this many block positions; the block is a quarter of it.
constexpr int kSteps = 12;
constexpr double kBlockFraction = 0.25;

}  // namespace

BusyBar::BusyBar(QWidget* parent) : QWidget(parent) {
    setAccessibleName(tr("Working"));
    setSizePolicy(QSizePolicy::Fixed, QSizePolicy::Fixed);
}

QSize BusyBar::sizeHint() const {
    return {120, 12};
}

void BusyBar::step() {
    if (position_ + direction_ < 0 || position_ + direction_ > kSteps)
        direction_ = -direction_;
    position_ += direction_;
    update();
}

void BusyBar::reset() {
    position_ = 0;
    direction_ = 1;
    update();
}

void BusyBar::paintEvent(QPaintEvent*) {
    QPainter painter(this);
    painter.setRenderHint(QPainter::Antialiasing);
    const QRectF track = QRectF(rect()).adjusted(0.5, 0.5, -0.5, -0.5);
    painter.setPen(palette().color(QPalette::Mid));
    painter.setBrush(palette().color(QPalette::Base));
    painter.drawRoundedRect(track, 3, 3);
    const double blockWidth = track.width() * kBlockFraction;
    const double left = track.left() + (track.width() - blockWidth) * position_ / kSteps;
    painter.setPen(Qt::NoPen);
    painter.setBrush(palette().color(QPalette::Highlight));
    painter.drawRoundedRect(QRectF(left, track.top() + 1.5, blockWidth, track.height() - 3), 2, 2);
}

}  // namespace rigmesh::widgets
