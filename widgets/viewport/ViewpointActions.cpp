#include "viewport/ViewpointActions.h"

#include <QAction>
#include <QCoreApplication>
#include <QKeyEvent>
#include <QMenu>

#include "viewport/Viewport.h"

namespace rigmesh::widgets {

// ---- The view's part (Viewport.h) ----

void Viewport::lookAlong(AxisView view) {
    camera_.setAxisView(view);
    // Blender's Auto Perspective: an axis view is orthographic.
    if (!camera_.orthographic()) {
        camera_.setOrthographic(true);
        autoOrthographic_ = true;
    }
    update();
    emit viewChanged();
}

void Viewport::setOrthographic(bool on) {
    camera_.setOrthographic(on);
    autoOrthographic_ = false;
    update();
    emit viewChanged();
}

void Viewport::orbitBy(double yawDegrees, double pitchDegrees) {
    camera_.orbit(QPointF(-yawDegrees / OrbitCamera::kDegreesPerPixel,
                          pitchDegrees / OrbitCamera::kDegreesPerPixel));
    leaveAutoOrthographic();
    update();
    emit viewChanged();
}

void Viewport::leaveAutoOrthographic() {
    // Orbiting out of an axis view the camera turned orthographic by itself
    // brings perspective back (Auto Perspective).
    if (autoOrthographic_ && !camera_.axisView()) {
        camera_.setOrthographic(false);
        autoOrthographic_ = false;
    }
}

// ---- The menu and keys ----

namespace {

struct Viewpoint {
    const char* text;
    Qt::Key key;
    Qt::Key numLockOff;  // what the same numpad key sends without Num Lock
    bool opposite;       // with Ctrl
    AxisView view;
};

constexpr Viewpoint kViewpoints[] = {
    {QT_TRANSLATE_NOOP("rigmesh::widgets::Viewpoint", "&Front"), Qt::Key_1, Qt::Key_End, false,
     AxisView::Front},
    {QT_TRANSLATE_NOOP("rigmesh::widgets::Viewpoint", "&Back"), Qt::Key_1, Qt::Key_End, true,
     AxisView::Back},
    {QT_TRANSLATE_NOOP("rigmesh::widgets::Viewpoint", "&Right"), Qt::Key_3, Qt::Key_PageDown, false,
     AxisView::Right},
    {QT_TRANSLATE_NOOP("rigmesh::widgets::Viewpoint", "&Left"), Qt::Key_3, Qt::Key_PageDown, true,
     AxisView::Left},
    {QT_TRANSLATE_NOOP("rigmesh::widgets::Viewpoint", "&Top"), Qt::Key_7, Qt::Key_Home, false,
     AxisView::Top},
    {QT_TRANSLATE_NOOP("rigmesh::widgets::Viewpoint", "B&ottom"), Qt::Key_7, Qt::Key_Home, true,
     AxisView::Bottom},
};

// Numpad 4 6 8 2: orbit by this many degrees.
constexpr double kOrbitStep = 15.0;

QString text(const char* source) {
    return QCoreApplication::translate("rigmesh::widgets::Viewpoint", source);
}

}  // namespace

void addViewpointMenu(QMenu* menu, const std::function<Viewport*()>& current) {
    QMenu* viewpoints =
        menu->addMenu(text(QT_TRANSLATE_NOOP("rigmesh::widgets::Viewpoint", "View&point")));
    for (const Viewpoint& v : kViewpoints) {
        QAction* action = viewpoints->addAction(text(v.text));
        Qt::KeyboardModifiers modifiers = Qt::KeypadModifier;
        if (v.opposite)
            modifiers |= Qt::ControlModifier;
        action->setShortcut(QKeySequence(QKeyCombination(modifiers, v.key)));
        QObject::connect(action, &QAction::triggered, menu, [current, view = v.view] {
            if (Viewport* viewport = current())
                viewport->lookAlong(view);
        });
    }
    viewpoints->addSeparator();
    QAction* orthographic = viewpoints->addAction(
        text(QT_TRANSLATE_NOOP("rigmesh::widgets::Viewpoint", "&Orthographic / Perspective")));
    orthographic->setShortcut(QKeySequence(Qt::KeypadModifier | Qt::Key_5));
    QObject::connect(orthographic, &QAction::triggered, menu, [current] {
        if (Viewport* viewport = current())
            viewport->setOrthographic(!viewport->camera().orthographic());
    });
}

namespace {

// Whether a numpad key is a viewpoint key, and with a viewport, doing what
// it says there.
bool viewpointKey(Viewport* viewport, const QKeyEvent& event) {
    if (!(event.modifiers() & Qt::KeypadModifier))
        return false;
    const bool ctrl = event.modifiers() & Qt::ControlModifier;
    for (const Viewpoint& v : kViewpoints)
        if ((event.key() == v.key || event.key() == v.numLockOff) && ctrl == v.opposite) {
            if (viewport)
                viewport->lookAlong(v.view);
            return true;
        }
    double yaw = 0.0, pitch = 0.0;
    switch (event.key()) {
        case Qt::Key_5:
        case Qt::Key_Clear:
            if (viewport)
                viewport->setOrthographic(!viewport->camera().orthographic());
            return true;
        case Qt::Key_4:
        case Qt::Key_Left:
            yaw = -kOrbitStep;
            break;
        case Qt::Key_6:
        case Qt::Key_Right:
            yaw = kOrbitStep;
            break;
        case Qt::Key_8:
        case Qt::Key_Up:
            pitch = kOrbitStep;
            break;
        case Qt::Key_2:
        case Qt::Key_Down:
            pitch = -kOrbitStep;
            break;
        default:
            return false;
    }
    if (viewport)
        viewport->orbitBy(yaw, pitch);
    return true;
}

}  // namespace

bool isViewpointKey(const QKeyEvent& event) {
    return viewpointKey(nullptr, event);
}

bool handleViewpointKey(Viewport& viewport, const QKeyEvent& event) {
    return viewpointKey(&viewport, event);
}

}  // namespace rigmesh::widgets
