#include "viewport/OrbitCamera.h"

#include <QtMath>
#include <algorithm>
#include <cmath>

namespace rigmesh::widgets {

QVector3D OrbitCamera::forward() const {
    const double yaw = qDegreesToRadians(yawDegrees_), pitch = qDegreesToRadians(pitchDegrees_);
    // Yaw 0, pitch 0 looks down -z, the sketch plane seen from the front.
    return QVector3D(-std::sin(yaw) * std::cos(pitch), -std::sin(pitch),
                     -std::cos(yaw) * std::cos(pitch))
        .normalized();
}

QVector3D OrbitCamera::right() const {
    // Horizontal, from the yaw alone: defined straight above and below too
    // (the top and bottom views).
    const double yaw = qDegreesToRadians(yawDegrees_);
    return QVector3D(std::cos(yaw), 0.0, -std::sin(yaw));
}

QVector3D OrbitCamera::up() const {
    return QVector3D::crossProduct(right(), forward()).normalized();
}

QVector3D OrbitCamera::eye() const {
    return target_ - forward() * static_cast<float>(distance_);
}

QMatrix4x4 OrbitCamera::viewMatrix() const {
    QMatrix4x4 view;
    view.lookAt(eye(), target_, up());
    return view;
}

QMatrix4x4 OrbitCamera::projectionMatrix(const QSizeF& viewport) const {
    QMatrix4x4 projection;
    const double aspect = viewport.height() > 0 ? viewport.width() / viewport.height() : 1.0;
    if (orthographic_) {
        // Depth reaches behind the eye too: nothing is clipped away by
        // zooming in.
        const double h = halfHeightAtTarget();
        projection.ortho(static_cast<float>(-h * aspect), static_cast<float>(h * aspect),
                         static_cast<float>(-h), static_cast<float>(h),
                         static_cast<float>(-distance_ * 100.0),
                         static_cast<float>(distance_ * 100.0));
        return projection;
    }
    projection.perspective(static_cast<float>(fieldOfViewDegrees_), static_cast<float>(aspect),
                           static_cast<float>(distance_ * 0.01),
                           static_cast<float>(distance_ * 100.0));
    return projection;
}

double OrbitCamera::halfHeightAtTarget() const {
    return distance_ * std::tan(qDegreesToRadians(fieldOfViewDegrees_) / 2.0);
}

void OrbitCamera::orbit(const QPointF& delta) {
    yawDegrees_ = std::remainder(yawDegrees_ - delta.x() * kDegreesPerPixel, 360.0);
    pitchDegrees_ = std::clamp(pitchDegrees_ + delta.y() * kDegreesPerPixel, -90.0, 90.0);
}

void OrbitCamera::setAxisView(AxisView view) {
    switch (view) {
        case AxisView::Front:
            setView(0.0, 0.0);
            break;
        case AxisView::Back:
            setView(180.0, 0.0);
            break;
        case AxisView::Right:
            setView(90.0, 0.0);
            break;
        case AxisView::Left:
            setView(-90.0, 0.0);
            break;
        case AxisView::Top:
            setView(0.0, 90.0);
            break;
        case AxisView::Bottom:
            setView(0.0, -90.0);
            break;
    }
}

std::optional<AxisView> OrbitCamera::axisView() const {
    for (AxisView view : {AxisView::Front, AxisView::Back, AxisView::Right, AxisView::Left,
                          AxisView::Top, AxisView::Bottom}) {
        OrbitCamera axis = *this;
        axis.setAxisView(view);
        if ((axis.forward() - forward()).length() < 1e-6f && (axis.up() - up()).length() < 1e-6f)
            return view;
    }
    return std::nullopt;
}

void OrbitCamera::pan(const QPointF& delta, const QSizeF& viewport) {
    const double worldPerPixel = 2.0 * halfHeightAtTarget() / std::max(1.0, viewport.height());
    target_ += (-right() * static_cast<float>(delta.x()) + up() * static_cast<float>(delta.y())) *
               static_cast<float>(worldPerPixel);
}

void OrbitCamera::dolly(double steps) {
    distance_ = std::clamp(distance_ * std::pow(0.85, steps), 1e-6, 1e9);
}

void OrbitCamera::frame(const QVector3D& centre, double radius) {
    target_ = centre;
    const double halfAngle = qDegreesToRadians(fieldOfViewDegrees_) / 2.0;
    distance_ = std::max(radius, 1e-9) / std::sin(halfAngle) * 1.1;
}

void OrbitCamera::setView(double yawDegrees, double pitchDegrees) {
    yawDegrees_ = std::remainder(yawDegrees, 360.0);
    pitchDegrees_ = std::clamp(pitchDegrees, -90.0, 90.0);
}

Ray OrbitCamera::rayThrough(const QPointF& pixel, const QSizeF& viewport) const {
    const QMatrix4x4 inverse = (projectionMatrix(viewport) * viewMatrix()).inverted();
    const float x = static_cast<float>(2.0 * pixel.x() / viewport.width() - 1.0);
    const float y = static_cast<float>(1.0 - 2.0 * pixel.y() / viewport.height());
    const QVector3D nearPoint = inverse.map(QVector3D(x, y, -1.0f));
    const QVector3D farPoint = inverse.map(QVector3D(x, y, 1.0f));
    // Orthographic rays are parallel, each from its own point of the near
    // plane (behind the eye); perspective ones start at the eye.
    return {orthographic_ ? nearPoint : eye(), (farPoint - nearPoint).normalized()};
}

QVector3D OrbitCamera::pointOnViewPlane(const QPointF& pixel, const QSizeF& viewport,
                                        const QVector3D& planePoint) const {
    const Ray ray = rayThrough(pixel, viewport);
    const QVector3D normal = forward();
    const float t = QVector3D::dotProduct(planePoint - ray.origin, normal) /
                    QVector3D::dotProduct(ray.direction, normal);
    return ray.origin + ray.direction * t;
}

QVector3D OrbitCamera::project(const QVector3D& world, const QSizeF& viewport) const {
    const QVector3D ndc = (projectionMatrix(viewport) * viewMatrix()).map(world);
    return QVector3D(static_cast<float>((ndc.x() + 1.0) / 2.0 * viewport.width()),
                     static_cast<float>((1.0 - ndc.y()) / 2.0 * viewport.height()),
                     (ndc.z() + 1.0f) / 2.0f);
}

}  // namespace rigmesh::widgets
