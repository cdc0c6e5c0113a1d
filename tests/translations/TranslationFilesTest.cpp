// The studio's translations (translations/rigmesh_<lang>.ts) are complete
// and current: lupdate, run again over the sources into a scratch copy,
// finds nothing new, vanished or obsolete, and every entry is finished;
// each translation keeps the markers of its source; every engine message
// is there and fits on its line.
#include <gtest/gtest.h>

#include <QDir>
#include <QFile>
#include <QProcess>
#include <QRegularExpression>
#include <QSet>
#include <QTemporaryDir>
#include <QXmlStreamReader>

#include "base/Message.h"
#include "base/MessageText.h"

namespace {

struct TsMessage {
    QString context;
    QString source;
    QString type;              // of the translation: "", "unfinished", "vanished", "obsolete"
    QStringList translations;  // one, or one per numerus form
};

std::vector<TsMessage> readTs(const QString& path) {
    QFile file(path);
    EXPECT_TRUE(file.open(QIODevice::ReadOnly)) << path.toStdString();
    QXmlStreamReader xml(&file);
    std::vector<TsMessage> messages;
    QString context;
    while (!xml.atEnd()) {
        xml.readNext();
        if (!xml.isStartElement())
            continue;
        if (xml.name() == QLatin1String("name")) {
            context = xml.readElementText();
        } else if (xml.name() == QLatin1String("message")) {
            messages.push_back({context, {}, {}, {}});
        } else if (xml.name() == QLatin1String("source")) {
            messages.back().source = xml.readElementText();
        } else if (xml.name() == QLatin1String("translation")) {
            messages.back().type = xml.attributes().value(QLatin1String("type")).toString();
            // Either text, or <numerusform> children.
            QString text;
            while (!(xml.isEndElement() && xml.name() == QLatin1String("translation"))) {
                xml.readNext();
                if (xml.isCharacters())
                    text += xml.text();
                else if (xml.isStartElement() && xml.name() == QLatin1String("numerusform"))
                    messages.back().translations << xml.readElementText();
            }
            if (messages.back().translations.isEmpty())
                messages.back().translations << text;
        }
    }
    EXPECT_FALSE(xml.hasError()) << path.toStdString() << ": " << xml.errorString().toStdString();
    return messages;
}

QString tsPath(const QString& language) {
    return QStringLiteral(RIGMESH_TRANSLATIONS_DIR "/rigmesh_%1.ts").arg(language);
}

std::string describe(const TsMessage& m) {
    return (m.context + QStringLiteral(": \"") + m.source + QStringLiteral("\" (") +
            (m.type.isEmpty() ? QStringLiteral("finished") : m.type) + QStringLiteral(")"))
        .toStdString();
}

// %1 .. %99, %L1 and %n, sorted, each as often as it occurs.
QStringList markers(const QString& text) {
    static const QRegularExpression marker(QStringLiteral("%L?[0-9]+|%n"));
    QStringList found;
    for (const auto& match : marker.globalMatch(text))
        found << match.captured();
    found.sort();
    return found;
}

class TranslationFile : public testing::TestWithParam<const char*> {};

// Runs lupdate over the sources (the options of update_translations, and
// `extra`) into `copy`, a scratch copy of `ts`; its output in `output`.
void lupdateInto(const QString& ts, const QString& copy, const QStringList& extra,
                 QString& output) {
    ASSERT_TRUE(QFile::copy(ts, copy));
    QStringList arguments =
        QString::fromLatin1(RIGMESH_LUPDATE_OPTIONS).split(QLatin1Char('|'), Qt::SkipEmptyParts);
    arguments << extra << QStringLiteral("@" RIGMESH_LUPDATE_INPUTS) << QStringLiteral("-ts")
              << copy;
    QProcess lupdate;
    lupdate.setProcessChannelMode(QProcess::MergedChannels);
    lupdate.start(QStringLiteral(RIGMESH_LUPDATE), arguments);
    ASSERT_TRUE(lupdate.waitForFinished(240000));
    output = QString::fromLocal8Bit(lupdate.readAll());
    ASSERT_EQ(lupdate.exitCode(), 0) << output.toStdString();
}

TEST_P(TranslationFile, LupdateFindsEveryStringAlreadyTranslatedAndNothingObsolete) {
    QTemporaryDir scratch;
    ASSERT_TRUE(scratch.isValid());
    const QString copy = scratch.filePath(QStringLiteral("copy.ts"));
    QString output;
    ASSERT_NO_FATAL_FAILURE(lupdateInto(tsPath(QString::fromLatin1(GetParam())), copy, {}, output));

    const std::vector<TsMessage> before = readTs(tsPath(QString::fromLatin1(GetParam())));
    const std::vector<TsMessage> after = readTs(copy);
    std::vector<std::string> problems;
    for (const TsMessage& m : after)
        if (!m.type.isEmpty())
            problems.push_back(describe(m));
    EXPECT_TRUE(problems.empty()) << problems.size()
                                  << " entries are new (a source string missing from the .ts "
                                     "file), unfinished, vanished or obsolete; run the target "
                                     "update_translations and translate them. The first: "
                                  << problems.front();
    EXPECT_EQ(after.size(), before.size()) << output.toStdString();
    EXPECT_GT(after.size(), 300u);  // the studio has some four hundred strings
}

TEST_P(TranslationFile, EveryTranslationKeepsTheMarkersOfItsSource) {
    for (const TsMessage& m : readTs(tsPath(QString::fromLatin1(GetParam())))) {
        const QStringList expected = markers(m.source);
        for (const QString& translation : m.translations) {
            EXPECT_FALSE(translation.trimmed().isEmpty()) << describe(m);
            EXPECT_EQ(markers(translation), expected)
                << describe(m) << " -> \"" << translation.toStdString() << "\"";
        }
    }
}

TEST_P(TranslationFile, EveryEngineMessageHasATranslation) {
    QSet<QString> engine;
    for (const TsMessage& m : readTs(tsPath(QString::fromLatin1(GetParam()))))
        if (m.context == QLatin1String("EngineMessage") && m.type.isEmpty())
            engine.insert(m.source);
    for (int i = static_cast<int>(rigmesh::MessageId::None) + 1;
         i < static_cast<int>(rigmesh::MessageId::Count); ++i) {
        const char* text = rigmesh::messageTemplate(static_cast<rigmesh::MessageId>(i));
        EXPECT_TRUE(engine.contains(QString::fromUtf8(text))) << text;
    }
}

TEST_P(TranslationFile, EveryEngineMessageFitsOnItsLineTranslated) {
    // The rule MessageText.EveryTemplateFitsOnItsLine holds the English
    // templates to, for each translation: room for every marker's argument
    // as a short number, so that only long names elide a translated message
    // (base/MessageText.h).
    for (const TsMessage& m : readTs(tsPath(QString::fromLatin1(GetParam())))) {
        if (m.context != QLatin1String("EngineMessage"))
            continue;
        for (const QString& translation : m.translations) {
            const long room = 6 * static_cast<long>(markers(translation).size());
            EXPECT_LE(static_cast<long>(translation.toUcs4().size()) + room,
                      static_cast<long>(rigmesh::kMaxMessageCharacters))
                << describe(m) << " -> \"" << translation.toStdString() << "\"";
        }
    }
}

TEST_P(TranslationFile, ContextsAreThoseTheStudioTranslatesIn) {
    // tr() in a free function lands under a namespace, a context no
    // translate() call at run time uses: the string would stay English.
    const QSet<QString> namespaces{QStringLiteral("rigmesh"), QStringLiteral("rigmesh::model"),
                                   QStringLiteral("rigmesh::widgets")};
    for (const TsMessage& m : readTs(tsPath(QString::fromLatin1(GetParam()))))
        EXPECT_FALSE(namespaces.contains(m.context)) << describe(m);
}

// English: the sources' numerus strings ("%n bone(s)") each have English's
// two forms in rigmesh_en.ts (lupdate -pluralonly, run again over the
// sources, finds nothing new or unfinished), without "(s)", keeping the
// source's markers.
TEST(EnglishPlurals, EveryNumerusStringHasItsEnglishFormsWithoutBrackets) {
    QTemporaryDir scratch;
    ASSERT_TRUE(scratch.isValid());
    const QString copy = scratch.filePath(QStringLiteral("copy.ts"));
    QString output;
    ASSERT_NO_FATAL_FAILURE(
        lupdateInto(QStringLiteral(RIGMESH_PLURALS_TS), copy,
                    {QStringLiteral("-no-obsolete"), QStringLiteral("-pluralonly")}, output));
    const std::vector<TsMessage> after = readTs(copy);
    EXPECT_EQ(after.size(), readTs(QStringLiteral(RIGMESH_PLURALS_TS)).size())
        << output.toStdString();
    EXPECT_GT(after.size(), 20u);
    static const QRegularExpression bracketed(QStringLiteral("\\((s|es)\\)"));
    for (const TsMessage& m : after) {
        EXPECT_TRUE(m.type.isEmpty()) << describe(m) << ": run the target update_translations";
        ASSERT_EQ(m.translations.size(), 2) << describe(m);
        for (const QString& form : m.translations) {
            EXPECT_FALSE(form.contains(bracketed)) << describe(m) << " -> " << form.toStdString();
            EXPECT_EQ(markers(form), markers(m.source)) << describe(m);
        }
    }
}

INSTANTIATE_TEST_SUITE_P(Languages, TranslationFile, testing::Values("de", "es"),
                         [](const testing::TestParamInfo<const char*>& language) {
                             return std::string(language.param);
                         });

}  // namespace
