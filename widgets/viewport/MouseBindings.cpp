#include "viewport/MouseBindings.h"

#include <QCoreApplication>

namespace rigmesh::widgets {

Navigation navigationFor(MouseBindings bindings, Qt::MouseButton button,
                         Qt::KeyboardModifiers modifiers) {
    if (bindings == MouseBindings::Blender)
        return button == Qt::MiddleButton ? navigationDuring(bindings, Navigation::Orbit, modifiers)
                                          : Navigation::None;
    if (!(modifiers & Qt::AltModifier))
        return Navigation::None;
    switch (button) {
        case Qt::LeftButton:
            return Navigation::Orbit;
        case Qt::MiddleButton:
            return Navigation::Pan;
        case Qt::RightButton:
            return Navigation::Zoom;
        default:
            return Navigation::None;
    }
}

Navigation navigationDuring(MouseBindings bindings, Navigation started,
                            Qt::KeyboardModifiers modifiers) {
    if (bindings == MouseBindings::Maya || started == Navigation::None)
        return started;
    if (modifiers & Qt::ShiftModifier)
        return Navigation::Pan;
    if (modifiers & Qt::ControlModifier)
        return Navigation::Zoom;
    return Navigation::Orbit;
}

QString navigationHint(MouseBindings bindings) {
    return bindings == MouseBindings::Maya
               ? QCoreApplication::translate(
                     "rigmesh::widgets::MouseBindings",
                     "Alt + left drag orbits, Alt + middle drag pans, Alt + right drag or the "
                     "wheel zooms")
               : QCoreApplication::translate(
                     "rigmesh::widgets::MouseBindings",
                     "middle drag orbits, Shift + middle drag pans, Ctrl + middle drag or the "
                     "wheel zooms");
}

QString mouseBindingsKey(MouseBindings bindings) {
    return bindings == MouseBindings::Maya ? QStringLiteral("maya") : QStringLiteral("blender");
}

MouseBindings mouseBindingsFromKey(const QString& key) {
    return key == QLatin1String("maya") ? MouseBindings::Maya : MouseBindings::Blender;
}

}  // namespace rigmesh::widgets
