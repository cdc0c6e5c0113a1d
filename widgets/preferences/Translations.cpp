#include "preferences/Translations.h"

#include <QCoreApplication>
#include <QDir>
#include <QFile>
#include <QLibraryInfo>
#include <QLocale>
#include <QTranslator>
#include <algorithm>

namespace rigmesh::widgets {
namespace {

QString& translationsDirectorySetting() {
    static QString directory;
    return directory;
}

QString studioTranslationFile(const QString& code) {
    return translationsDirectory() + QStringLiteral("/rigmesh_%1.qm").arg(code);
}

// The translators installed last, replaced by the next call.
QTranslator& studioTranslator() {
    static QTranslator translator;
    return translator;
}

QTranslator& qtTranslator() {
    static QTranslator translator;
    return translator;
}

// A language's own name as its speakers write it in a list of languages.
// CLDR's names carry the country for some ("español de España") and are
// lower case for others.
QString nativeName(const QString& code) {
    if (code == QLatin1String("de"))
        return QStringLiteral("Deutsch");
    if (code == QLatin1String("es"))
        return QStringLiteral("Espa\u00f1ol");
    QString name = QLocale(code).nativeLanguageName();
    if (!name.isEmpty())
        name[0] = name[0].toUpper();
    return name;
}

}  // namespace

QString translationsDirectory() {
    if (!translationsDirectorySetting().isEmpty())
        return translationsDirectorySetting();
    return QDir::cleanPath(QCoreApplication::applicationDirPath() +
                           QStringLiteral("/../share/rigmesh-studio/translations"));
}

void setTranslationsDirectory(const QString& directory) {
    translationsDirectorySetting() = directory;
}

QList<StudioLanguage> studioLanguages() {
    QList<StudioLanguage> languages{{QStringLiteral("en"), QStringLiteral("English")}};
    const QStringList files =
        QDir(translationsDirectory()).entryList({QStringLiteral("rigmesh_*.qm")}, QDir::Files);
    for (const QString& file : files) {
        const QString code = file.mid(8, file.size() - 8 - 3);  // rigmesh_<code>.qm
        // rigmesh_en.qm holds English's plural forms only: English is listed.
        if (code != QLatin1String("en"))
            languages.append({code, nativeName(code)});
    }
    return languages;
}

QString resolvedLanguage(const QString& preference) {
    const QList<StudioLanguage> languages = studioLanguages();
    auto spoken = [&](const QString& code) {
        return std::any_of(languages.begin(), languages.end(),
                           [&](const StudioLanguage& l) { return l.code == code; });
    };
    if (!preference.isEmpty() && spoken(preference))
        return preference;
    // uiLanguages() lists the user's preferred languages, "de-DE" first for a German desktop.
    for (const QString& ui : QLocale::system().uiLanguages()) {
        const QString code = QLocale(ui).name().section(QLatin1Char('_'), 0, 0);
        if (spoken(code))
            return code;
    }
    return QStringLiteral("en");
}

QLocale studioLocale() {
    const QString language =
        studioTranslator().isEmpty() ? QString() : studioTranslator().language();
    return language.isEmpty() ? QLocale(QLocale::English) : QLocale(language);
}

bool installTranslations(const QString& code) {
    QCoreApplication::removeTranslator(&studioTranslator());
    QCoreApplication::removeTranslator(&qtTranslator());
    if (code == QLatin1String("en")) {
        // The sources' "%n bone(s)" in English's own forms ("1 bone", "10
        // bones"): rigmesh_en.qm has only those; without it the sources show.
        if (studioTranslator().load(studioTranslationFile(code)))
            QCoreApplication::installTranslator(&studioTranslator());
        return true;
    }
    // Qt's own strings, where Qt's translations are installed (Debian:
    // qt6-translations-l10n); the studio works without them.
    if (qtTranslator().load(QStringLiteral("qtbase_") + code,
                            QLibraryInfo::path(QLibraryInfo::TranslationsPath)))
        QCoreApplication::installTranslator(&qtTranslator());
    if (!studioTranslator().load(studioTranslationFile(code)))
        return false;
    QCoreApplication::installTranslator(&studioTranslator());
    return true;
}

}  // namespace rigmesh::widgets
