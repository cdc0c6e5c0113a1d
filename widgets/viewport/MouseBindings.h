// Which mouse gestures move the view (Preferences > Mouse bindings):
// Blender's (middle drag orbits, Shift + middle drag pans, Ctrl + middle
// drag zooms) or Maya's (Alt + left / middle / right drag orbits / pans /
// zooms). The wheel zooms in both; everything else goes to the active tool.
#pragma once

#include <QString>
#include <Qt>

namespace rigmesh::widgets {

enum class MouseBindings { Blender, Maya };
enum class Navigation { None, Orbit, Pan, Zoom };

// What a drag started with `button` and `modifiers` does to the view.
Navigation navigationFor(MouseBindings bindings, Qt::MouseButton button,
                         Qt::KeyboardModifiers modifiers);

// Blender's middle drag follows Shift and Ctrl as they change during the
// drag, as Blender does; Maya's drag keeps what its button started.
Navigation navigationDuring(MouseBindings bindings, Navigation started,
                            Qt::KeyboardModifiers modifiers);

// One line for the status bar and the first-run card: how to orbit, pan
// and zoom with these bindings (translated).
QString navigationHint(MouseBindings bindings);

// "blender" / "maya" in settings; anything else reads as Blender.
QString mouseBindingsKey(MouseBindings bindings);
MouseBindings mouseBindingsFromKey(const QString& key);

}  // namespace rigmesh::widgets
