// Tooltips that name the key, as Blender's and Krita's do: every action of
// a window with a shortcut gets "<what it does> (<key>)" as its tooltip, so a
// toolbar button teaches its key.
#pragma once

class QWidget;

namespace rigmesh::widgets {

void showShortcutsInToolTips(QWidget* window);

}  // namespace rigmesh::widgets
