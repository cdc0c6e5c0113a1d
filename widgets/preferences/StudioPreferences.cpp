#include "preferences/StudioPreferences.h"

#include <QSettings>
#include <cmath>

namespace rigmesh::widgets {
namespace {

const QString kLanguage = QStringLiteral("preferences/language");
const QString kEdgeLength = QStringLiteral("preferences/defaultEdgeLength");
const QString kSkinning = QStringLiteral("preferences/skinning");
const QString kAutosave = QStringLiteral("preferences/autosaveSeconds");
const QString kMouse = QStringLiteral("preferences/mouseBindings");
const QString kTheme = QStringLiteral("preferences/theme");

}  // namespace

StudioPreferences StudioPreferences::load() {
    const QSettings settings;
    StudioPreferences p;
    p.language = settings.value(kLanguage).toString();
    bool ok = false;
    const double edge = settings.value(kEdgeLength, 0.0).toDouble(&ok);
    if (ok && std::isfinite(edge) && edge >= 0.0 && edge <= kMaxDefaultEdgeLength)
        p.defaultEdgeLength = edge;
    p.dualQuaternionSkinning =
        settings.value(kSkinning).toString() == QLatin1String("dualQuaternion");
    const int seconds = settings.value(kAutosave, p.autosaveSeconds).toInt(&ok);
    if (ok && seconds >= kMinAutosaveSeconds && seconds <= kMaxAutosaveSeconds)
        p.autosaveSeconds = seconds;
    p.mouseBindings = mouseBindingsFromKey(settings.value(kMouse).toString());
    p.theme =
        settings.value(kTheme).toString() == QLatin1String("dark") ? Theme::Dark : Theme::Light;
    return p;
}

void StudioPreferences::save() const {
    QSettings settings;
    settings.setValue(kLanguage, language);
    settings.setValue(kEdgeLength, defaultEdgeLength);
    settings.setValue(kSkinning, dualQuaternionSkinning ? QStringLiteral("dualQuaternion")
                                                        : QStringLiteral("linear"));
    settings.setValue(kAutosave, autosaveSeconds);
    settings.setValue(kMouse, mouseBindingsKey(mouseBindings));
    settings.setValue(kTheme,
                      theme == Theme::Dark ? QStringLiteral("dark") : QStringLiteral("light"));
}

}  // namespace rigmesh::widgets
