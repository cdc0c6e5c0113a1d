// Light or dark: Qt's Fusion style with its own light palette or a dark one
// close to Blender's greys, applied to the whole application at once.
#pragma once

#include <QPalette>

#include "preferences/StudioPreferences.h"

namespace rigmesh::widgets {

QPalette themePalette(Theme theme);
void applyTheme(Theme theme);

}  // namespace rigmesh::widgets
