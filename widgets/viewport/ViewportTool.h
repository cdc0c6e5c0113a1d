// A tool the viewport hands its left-button mouse events to (select, sketch,
// pose, merge, cut, paint), in the manner of Krita's tool base: press, move
// and release for a drag (previewed live, one command pushed on release),
// hover for mouse moves without a button, the wheel (before the camera), overlay lines drawn
// over the 3D view and an options widget. Camera navigation (middle button,
// the wheel a tool leaves) stays with the viewport.
#pragma once

#include <QMouseEvent>
#include <QObject>
#include <QString>
#include <QWheelEvent>
#include <cstdint>
#include <optional>
#include <vector>

#include "base/Types.h"

class QWidget;

namespace rigmesh::widgets {

class Viewport;
struct ColouredVertices;

enum class WeightView;  // viewport/RenderScene.h

class ViewportTool : public QObject {
    Q_OBJECT
  public:
    using QObject::QObject;
    ~ViewportTool() override = default;
    virtual QString name() const = 0;
    // A one-line hint for the status bar.
    virtual QString hint() const = 0;
    virtual void press(Viewport& viewport, QMouseEvent* event) = 0;
    virtual void move(Viewport& viewport, QMouseEvent* event) = 0;
    virtual void release(Viewport& viewport, QMouseEvent* event) = 0;
    // Called when the tool stops being the active one.
    virtual void cancel(Viewport&) {}
    // The mouse moved with no button held.
    virtual void hover(Viewport&, QMouseEvent*) {}
    // True if the tool used the wheel (then the camera does not zoom).
    virtual bool wheel(Viewport&, QWheelEvent*) { return false; }
    // Handles, rings and guides drawn over the 3D view with the skeleton:
    // world-space line segments (pairs of points) added to `lines`.
    virtual void addOverlay(const Viewport&, ColouredVertices&) const {}
    // The tool's settings, shown while it is active; none by default.
    virtual QWidget* optionsWidget() { return nullptr; }
    // The weight view the tool shows when it becomes active (the paint tool
    // shows the weights it paints); none by default.
    virtual std::optional<WeightView> weightView() const { return std::nullopt; }
    // A part the tool shows see-through in front of everything (a part
    // dragged into another, which would hide inside it) and, if the tool's
    // action would move it, a second see-through copy moved by resultOffset
    // (world coordinates).
    struct PartInFront {
        std::uint32_t part = 0;  // a model::PartId
        std::optional<Vec3> resultOffset;
    };
    virtual std::vector<PartInFront> partsInFront(const Viewport&) const { return {}; }

  signals:
    // The tool's one way to the status bar: what it did, refused or needs.
    // A timeout of 0 keeps the message until the next one.
    void status(const QString& message, int timeoutMs = 0);
};

}  // namespace rigmesh::widgets
