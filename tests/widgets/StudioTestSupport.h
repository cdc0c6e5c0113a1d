// Helpers to drive the studio like a person: mouse strokes in the viewport.
#pragma once

#include <QApplication>
#include <QElapsedTimer>
#include <QMouseEvent>
#include <QTest>
#include <cmath>
#include <ctime>
#include <vector>

#include "jobs/JobRunner.h"
#include "viewport/Viewport.h"

namespace rigmesh::test {

inline void sendMouse(QWidget* widget, QEvent::Type type, const QPointF& at, Qt::MouseButton button,
                      Qt::MouseButtons buttons, Qt::KeyboardModifiers modifiers = Qt::NoModifier) {
    QMouseEvent event(type, at, widget->mapToGlobal(at), button, buttons, modifiers);
    QApplication::sendEvent(widget, &event);
}

// CPU time the calling thread has used, in milliseconds: the GUI thread's
// own work, which other programs on the same cores do not lengthen.
inline double threadCpuMilliseconds() {
    timespec now{};
    clock_gettime(CLOCK_THREAD_CPUTIME_ID, &now);
    return now.tv_sec * 1e3 + now.tv_nsec / 1e6;
}

// Runs the event loop while `busy` says so (at most `timeoutMs`).
template <typename Busy>
void waitWhile(Busy&& busy, int timeoutMs) {
    QElapsedTimer clock;
    clock.start();
    while (busy() && clock.elapsed() < timeoutMs)
        QTest::qWait(5);
    QApplication::processEvents();
}

// Lets background jobs (a sketch's build, a rebuild, an import; widgets/
// jobs) finish and apply, as a person waits for the progress bar to go.
inline void waitForJobs(int timeoutMs = 120000) {
    waitWhile([] { return widgets::JobRunner::anyBusy(); }, timeoutMs);
}

// Lets the Difference from Global Weights view's solve finish and show.
inline void waitForGlobalDifferences(widgets::Viewport* viewport, int timeoutMs = 120000) {
    viewport->update();
    QTest::qWait(20);  // a paint asks for the differences
    waitWhile([viewport] { return viewport->globalDifferencePending(); }, timeoutMs);
    viewport->update();
    QTest::qWait(20);
}

// A straight drag with `button` from `from` to `to`, in one move, without
// waiting for background jobs (view navigation: orbit, pan, zoom).
inline void buttonDrag(QWidget* widget, Qt::MouseButton button, const QPointF& from,
                       const QPointF& to, Qt::KeyboardModifiers modifiers = Qt::NoModifier) {
    sendMouse(widget, QEvent::MouseButtonPress, from, button, button, modifiers);
    sendMouse(widget, QEvent::MouseMove, to, Qt::NoButton, button, modifiers);
    sendMouse(widget, QEvent::MouseButtonRelease, to, button, Qt::NoButton, modifiers);
}

// A left-button drag through `points` (pixels in the widget).
inline void drag(QWidget* widget, const std::vector<QPointF>& points,
                 Qt::KeyboardModifiers modifiers = Qt::NoModifier) {
    widget->setFocus(Qt::MouseFocusReason);  // as a real click does
    sendMouse(widget, QEvent::MouseButtonPress, points.front(), Qt::LeftButton, Qt::LeftButton,
              modifiers);
    for (std::size_t i = 1; i < points.size(); ++i)
        sendMouse(widget, QEvent::MouseMove, points[i], Qt::NoButton, Qt::LeftButton, modifiers);
    sendMouse(widget, QEvent::MouseButtonRelease, points.back(), Qt::LeftButton, Qt::NoButton,
              modifiers);
    waitForJobs();
}

// A closed ellipse-like outline around `centre`, as a mouse would draw it.
inline std::vector<QPointF> ellipseStroke(const QPointF& centre, double rx, double ry,
                                          int count = 80) {
    std::vector<QPointF> points;
    for (int i = 0; i <= count; ++i) {
        const double t = 2.0 * M_PI * i / count;
        points.emplace_back(centre.x() + rx * std::cos(t), centre.y() + ry * std::sin(t));
    }
    return points;
}

// Lets the window show and the GL widget paint.
inline void settle(QWidget* window) {
    window->show();
    // No window manager under Xvfb: activate by hand so shortcuts reach it.
    QApplication::setActiveWindow(window);
    if (!QTest::qWaitForWindowExposed(window))
        QTest::qWait(500);
    if (!QTest::qWaitForWindowActive(window, 300))
        QTest::qWait(50);
    QTest::qWait(50);
}

}  // namespace rigmesh::test
