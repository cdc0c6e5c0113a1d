// View > Viewpoint, as Blender's numpad: 1 front, 3 right, 7 top, Ctrl for
// the opposite side (back, left, bottom), 5 orthographic / perspective, 2 4 6
// 8 orbit by 15 degrees. An axis view turns orthographic (Blender's Auto
// Perspective) and orbiting out of it turns perspective again, unless 5 chose
// the projection. The keys work with Num Lock on or off.
#pragma once

#include <functional>

class QMenu;
class QKeyEvent;

namespace rigmesh::widgets {

class Viewport;

// Adds the Viewpoint submenu to `menu`; `current` gives the view the actions
// act on (none: they do nothing).
void addViewpointMenu(QMenu* menu, const std::function<Viewport*()>& current);

// The viewpoint keys pressed in the view itself, which takes them before the
// window's shortcuts (the numpad without Num Lock sends End, Page Down, Home,
// Clear and arrows, which are other shortcuts' keys): whether `event` is one,
// and doing what it says (true if it was one).
bool isViewpointKey(const QKeyEvent& event);
bool handleViewpointKey(Viewport& viewport, const QKeyEvent& event);

}  // namespace rigmesh::widgets
