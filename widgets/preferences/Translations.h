// The languages the studio speaks and the translators that make it speak
// one: the studio's own (translations/rigmesh_<code>.ts, compiled to .qm
// files in share/rigmesh-studio/translations beside bin/, as the .deb
// installs them) and Qt's (qtbase_<code>.qm from Qt's translations folder, where
// installed: standard dialog buttons, context menus of text fields).
#pragma once

#include <QLocale>

#include <QList>
#include <QString>

namespace rigmesh::widgets {

struct StudioLanguage {
    QString code;        // "en", "de", "es"
    QString nativeName;  // "English", "Deutsch", "Español"
};

// Where the studio's .qm files are: ../share/rigmesh-studio/translations
// from the program's folder (/usr/bin -> /usr/share/..., and the build
// tree's app/ -> share/...), unless set (tests, whose programs live
// elsewhere in the build tree).
QString translationsDirectory();
void setTranslationsDirectory(const QString& directory);

// English first, then every language with a compiled translation.
QList<StudioLanguage> studioLanguages();

// The language a preference means: itself if the studio speaks it, else
// (the empty preference: follow the system) the system locale's language
// if the studio speaks it, else English.
QString resolvedLanguage(const QString& preference);

// Replaces the application's RigMesh and Qt translators with those for
// `code` ("en" removes them). Widgets made afterwards speak it; the studio
// applies a new language at its next start. False if the studio's own
// translation of a language other than English is missing.
bool installTranslations(const QString& code);

// The locale of the language installTranslations() installed (English
// without one), for dates and numbers in the studio's own sentences.
QLocale studioLocale();

}  // namespace rigmesh::widgets
