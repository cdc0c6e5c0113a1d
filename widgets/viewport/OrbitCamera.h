// A Blender-like orbit camera: it turns around a target point (middle mouse
// drag), pans the target in the view plane (Shift + middle drag) and dollies
// towards it (wheel). Pure math on Qt Gui types, no widget.
#pragma once

#include <QMatrix4x4>
#include <QPointF>
#include <QSizeF>
#include <QVector3D>

namespace rigmesh::widgets {

struct Ray {
    QVector3D origin;
    QVector3D direction;  // unit length
};

class OrbitCamera {
  public:
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
    double pitchDegrees_ = 0.0;  // up/down
    double fieldOfViewDegrees_ = 40.0;
};

}  // namespace rigmesh::widgets
