#include "MouseHint.h"

#include <QEvent>
#include <QLabel>
#include <QMouseEvent>
#include <QSettings>
#include <QVBoxLayout>
#include <algorithm>

namespace rigmesh::widgets {
namespace {

const char* kShownKey = "hints/mouseShown";

}  // namespace

MouseHint::MouseHint(QWidget* area) : QFrame(area), area_(area) {
    setObjectName(QStringLiteral("MouseHint"));
    setStyleSheet(
        QStringLiteral("#MouseHint { background: rgba(20, 20, 24, 200); border-radius: 8px; }"
                       "QLabel { color: #f0f0f0; }"));
    auto* layout = new QVBoxLayout(this);
    layout->setContentsMargins(16, 10, 16, 10);
    text_ = new QLabel(this);
    text_->setTextFormat(Qt::RichText);
    text_->setWordWrap(true);
    layout->addWidget(text_);
    setMouseBindings(MouseBindings::Blender);
    area_->installEventFilter(this);
    hide();
}

void MouseHint::setMouseBindings(MouseBindings bindings) {
    const QString view =
        bindings == MouseBindings::Maya
            ? tr("<b>Alt + left-drag</b> orbits the view, <b>Alt + middle-drag</b> pans, "
                 "<b>Alt + right-drag</b> zooms<br>")
            : tr("<b>Middle-drag</b> orbits the view, <b>Shift + middle-drag</b> pans<br>");
    text_->setText(
        tr("<b>Left-drag</b> draws a part with the Sketch tool (S), moves it with Select (Q), "
           "bends a joint or bone with Pose (P)<br>") +
        view +
        tr("<b>Wheel</b> zooms, <b>Home</b> frames everything"
           "<br><small>Click to close; Help &gt; Mouse Gestures shows this again</small>"));
    if (isVisible())
        place();
}

void MouseHint::showOnFirstRun() {
    if (QSettings().value(QString::fromLatin1(kShownKey), false).toBool())
        return;
    place();
    show();
    raise();
}

void MouseHint::dismiss() {
    QSettings().setValue(QString::fromLatin1(kShownKey), true);
    hide();
}

bool MouseHint::eventFilter(QObject* watched, QEvent* event) {
    if (watched == area_ && (event->type() == QEvent::Resize || event->type() == QEvent::Show))
        place();
    return QFrame::eventFilter(watched, event);
}

void MouseHint::mousePressEvent(QMouseEvent* event) {
    dismiss();
    event->accept();
}

void MouseHint::place() {
    // At most 560 pixels wide, and 20 pixels inside the area on each side.
    const int width = std::max(200, std::min(560, area_->width() - 40));
    setFixedWidth(width);
    const int height = heightForWidth(width) > 0 ? heightForWidth(width) : sizeHint().height();
    setFixedHeight(height);
    move((area_->width() - width) / 2, area_->height() - height - 24);
}

}  // namespace rigmesh::widgets
