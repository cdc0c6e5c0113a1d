// The studio's preferences (Edit > Preferences), kept in QSettings under
// "preferences/": language, default edge length of new sketches, the
// default skinning, the autosave interval, mouse bindings and theme. The
// window layout is kept beside them under "window/" by MainWindow.
#pragma once

#include <QString>

#include "viewport/MouseBindings.h"

namespace rigmesh::widgets {

enum class Theme { Light, Dark };

struct StudioPreferences {
    // "" follows the system's locale; else a code of studioLanguages().
    QString language;
    // For new sketches: 0 = automatic (the document's, or the sketch's own).
    double defaultEdgeLength = 0.0;
    // View > Dual Quaternion Skinning when the studio starts. Off by default:
    // linear blend, as glTF viewers and Blender skin exported files.
    bool dualQuaternionSkinning = false;
    // Seconds from the last change to the recovery file.
    int autosaveSeconds = 3;
    MouseBindings mouseBindings = MouseBindings::Blender;
    Theme theme = Theme::Light;

    static constexpr int kMinAutosaveSeconds = 1;
    static constexpr int kMaxAutosaveSeconds = 600;
    static constexpr double kMaxDefaultEdgeLength = 1000.0;

    // What QSettings holds, each value checked (anything out of range or
    // unknown reads as the default).
    static StudioPreferences load();
    void save() const;

    bool operator==(const StudioPreferences&) const = default;
};

}  // namespace rigmesh::widgets
