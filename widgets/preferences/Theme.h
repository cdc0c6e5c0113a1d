// Light or dark: Qt's Fusion style with its own light palette or a dark one
// close to Blender's greys, applied to the whole application at once.
#pragma once

#include <QIcon>
#include <QPalette>

#include "preferences/StudioPreferences.h"

namespace rigmesh::widgets {

QPalette themePalette(Theme theme);
// Sets the palette on the whole application, the open windows included, and
// polishes widgets with their own style sheet again so that they take it.
void applyTheme(Theme theme);

// `icon` in one colour (its shape, by alpha): style icons drawn for a light
// palette made readable on the dark one.
QIcon tintedIcon(const QIcon& icon, const QColor& colour);

// The style sheet a window of the studio takes for `theme` (set on the
// window, not the application, so the application's style stays Fusion):
// on the dark palette, check boxes in lists and tables with light outlines.
QString themeStyleSheet(Theme theme);

// The studio's own icon at `path` (resources/icons, drawn in dark grey
// lines for a light palette) for `theme`: on the dark one its dark grey
// lines are light grey, its colours kept.
QIcon themedIcon(const QString& path, Theme theme);

}  // namespace rigmesh::widgets
