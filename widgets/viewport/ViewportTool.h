// A tool the viewport hands its left-button mouse events to (sketch, select,
// pose). Camera navigation (middle button, wheel) stays with the viewport.
#pragma once

#include <QMouseEvent>
#include <QString>

namespace rigmesh::widgets {

class Viewport;

class ViewportTool {
  public:
    virtual ~ViewportTool() = default;
    virtual QString name() const = 0;
    // A one-line hint for the status bar.
    virtual QString hint() const = 0;
    virtual void press(Viewport& viewport, QMouseEvent* event) = 0;
    virtual void move(Viewport& viewport, QMouseEvent* event) = 0;
    virtual void release(Viewport& viewport, QMouseEvent* event) = 0;
    // Called when the tool stops being the active one.
    virtual void cancel(Viewport&) {}
};

}  // namespace rigmesh::widgets
