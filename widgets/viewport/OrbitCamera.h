// A Blender-like orbit camera: it turns around a target point (middle mouse
// drag), pans the target in the view plane (Shift + middle drag) and dollies
// towards it (wheel); it looks along an axis (Blender's numpad 1, 3, 7 and
// with Ctrl the opposite sides) and projects in perspective or
// orthographically (numpad 5), the orthographic view as wide at the target
// as the perspective one. Pure math on Qt Gui types, no widget.
#pragma once

#include <QMatrix4x4>
#include <QPointF>
#include <QSizeF>
#include <QVector3D>
#include <optional>

namespace rigmesh::widgets {

struct Ray {
    QVector3D origin;
    QVector3D direction;  // unit length
};

// The axis views, as Blender names them (y up here, the sketch plane z = 0
// seen from the front).
enum class AxisView { Front, Back, Right, Left, Top, Bottom };

class OrbitCamera {
  public:
    // Orbiting turns the view this many degrees per pixel of drag.
    static constexpr double kDegreesPerPixel = 0.4;

    QMatrix4x4 viewMatrix() const;
    QMatrix4x4 projectionMatrix(const QSizeF& viewport) const;
    QVector3D eye() const;
    QVector3D target() const { return target_; }
    QVector3D forward() const;  // from the eye towards the target
    QVector3D up() const;
    QVector3D right() const;
    double distance() const { return distance_; }

    // Mouse motion in pixels; the viewport height sets the speed.
    void orbit(const QPointF& deltaPixels);
    void pan(const QPointF& deltaPixels, const QSizeF& viewport);
    void dolly(double wheelSteps);  // positive = closer
    // Looks at the sphere around `centre` so it fills the view.
    void frame(const QVector3D& centre, double radius);
    void setView(double yawDegrees, double pitchDegrees);
    // Looks along an axis (keeping the target and distance).
    void setAxisView(AxisView view);
    // The axis the camera looks along, if it looks exactly along one.
    std::optional<AxisView> axisView() const;
    bool orthographic() const { return orthographic_; }
    void setOrthographic(bool on) { orthographic_ = on; }
    // Half the view's height at the target: what the orthographic view shows.
    double halfHeightAtTarget() const;

    // The ray through a pixel (origin at the eye).
    Ray rayThrough(const QPointF& pixel, const QSizeF& viewport) const;
    // A pixel's point on the plane through `planePoint` facing the camera.
    QVector3D pointOnViewPlane(const QPointF& pixel, const QSizeF& viewport,
                               const QVector3D& planePoint) const;
    // Projects a world point to pixels (y down) and its depth in [0, 1].
    QVector3D project(const QVector3D& world, const QSizeF& viewport) const;

  private:
    QVector3D target_{0, 0, 0};
    double distance_ = 5.0;
    double yawDegrees_ = 0.0;    // around the world y axis
    double pitchDegrees_ = 0.0;  // up/down, -90 (from below) to 90 (from above)
    double fieldOfViewDegrees_ = 40.0;
    bool orthographic_ = false;
};

}  // namespace rigmesh::widgets
