#include "jobs/JobStatus.h"

#include <QApplication>
#include <QKeyEvent>
#include <QLabel>
#include <QMainWindow>
#include <QMouseEvent>
#include <QPushButton>
#include <QStatusBar>

#include "jobs/BusyBar.h"
#include "jobs/JobRunner.h"
#include "viewport/Viewport.h"

namespace rigmesh::widgets {

namespace {

// How long a job runs before its progress shows (shorter ones just happen).
constexpr int kShowAfterMs = 100;
// How often the busy bar moves and the elapsed time updates.
constexpr int kStepMs = 150;

}  // namespace

JobStatus::JobStatus(QMainWindow* window, JobRunner* runner)
    : QObject(window), window_(window), runner_(runner) {
    label_ = new QLabel(window);
    bar_ = new BusyBar(window);
    bar_->setObjectName(QStringLiteral("jobBusyBar"));
    cancel_ = new QPushButton(tr("Cancel"), window);
    cancel_->setObjectName(QStringLiteral("jobCancel"));
    cancel_->setToolTip(tr("Stop waiting: the document stays as it was (Esc)"));
    for (QWidget* widget : {static_cast<QWidget*>(label_), static_cast<QWidget*>(bar_),
                            static_cast<QWidget*>(cancel_)}) {
        window->statusBar()->addPermanentWidget(widget);
        widget->hide();
    }
    delay_.setSingleShot(true);
    delay_.setInterval(kShowAfterMs);
    tick_.setInterval(kStepMs);
    connect(&delay_, &QTimer::timeout, this, &JobStatus::showProgress);
    connect(&tick_, &QTimer::timeout, this, &JobStatus::showProgress);
    connect(cancel_, &QPushButton::clicked, runner_, &JobRunner::cancel);
    connect(runner_, &JobRunner::busyChanged, this, &JobStatus::busyChanged);
}

bool JobStatus::progressShown() const {
    return bar_->isVisible();
}

void JobStatus::busyChanged(bool busy) {
    if (busy && !filtering_) {
        qApp->installEventFilter(this);
        filtering_ = true;
        delay_.start();
        return;
    }
    if (!busy) {
        if (filtering_)
            qApp->removeEventFilter(this);
        filtering_ = false;
        delay_.stop();
        tick_.stop();
        label_->hide();
        bar_->hide();
        cancel_->hide();
        if (QApplication::overrideCursor())
            QApplication::restoreOverrideCursor();
    }
}

void JobStatus::showProgress() {
    if (!runner_->busy())
        return;
    label_->setText(tr("%1… %2 s")
                        .arg(runner_->title())
                        .arg(runner_->elapsedMilliseconds() / 1000.0, 0, 'f', 1));
    if (bar_->isVisible()) {
        bar_->step();
    } else {
        bar_->reset();
        label_->show();
        bar_->show();
        cancel_->show();
        QApplication::setOverrideCursor(Qt::BusyCursor);
        tick_.start();
    }
}

bool JobStatus::allowed(QObject* watched, QEvent* event) const {
    auto* widget = qobject_cast<QWidget*>(watched);
    if (widget && (widget == cancel_ || cancel_->isAncestorOf(widget)))
        return true;
    // The 3D view navigates with the chosen mouse bindings (Blender's
    // middle button, Maya's Alt + any button) and the wheel; moves without
    // the left button and every move of a navigating drag go through.
    if (auto* viewport = qobject_cast<Viewport*>(watched)) {
        if (event->type() == QEvent::Wheel)
            return true;
        if (auto* mouse = dynamic_cast<QMouseEvent*>(event)) {
            if (event->type() == QEvent::MouseButtonPress ||
                event->type() == QEvent::MouseButtonDblClick)
                return navigationFor(viewport->mouseBindings(), mouse->button(),
                                     mouse->modifiers()) != Navigation::None;
            return viewport->navigating() ||
                   (event->type() == QEvent::MouseMove && !(mouse->buttons() & Qt::LeftButton));
        }
    }
    return false;
}

bool JobStatus::eventFilter(QObject* watched, QEvent* event) {
    switch (event->type()) {
        case QEvent::ShortcutOverride:
        case QEvent::KeyPress:
        case QEvent::KeyRelease: {
            // Esc cancels; every other key (and so every shortcut) waits.
            auto* key = static_cast<QKeyEvent*>(event);
            if (event->type() == QEvent::KeyPress && key->key() == Qt::Key_Escape) {
                runner_->cancel();
                return true;
            }
            event->accept();  // an accepted override keeps shortcuts from firing
            return true;
        }
        case QEvent::MouseButtonPress:
        case QEvent::MouseButtonRelease:
        case QEvent::MouseButtonDblClick:
        case QEvent::MouseMove:
        case QEvent::Wheel:
        case QEvent::ContextMenu:
            return !allowed(watched, event);
        default:
            return false;
    }
}

}  // namespace rigmesh::widgets
