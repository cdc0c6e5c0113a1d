// The studio in German and Spanish: the translations are
// compiled into the program, menus, docks and tools speak the language, and
// a message that comes from the engine (a stroke that crosses itself)
// reaches the status bar translated, by its id, and a damaged document is
// reported in the language down to what is wrong in it, a part's own
// problem included. Screenshots for
// docs/STUDIO.md.
#include <gtest/gtest.h>

#include <QAbstractButton>
#include <QComboBox>
#include <QDialogButtonBox>
#include <QDockWidget>
#include <QFile>
#include <QLabel>
#include <QLibraryInfo>
#include <QMenuBar>
#include <QPushButton>
#include <QStatusBar>
#include <QTemporaryDir>
#include <cmath>
#include <limits>
#include <nlohmann/json.hpp>
#include <vector>

#include "DocumentView.h"
#include "MainWindow.h"
#include "StudioTestSupport.h"
#include "dialogs/ExportDialog.h"
#include "dialogs/PreferencesDialog.h"
#include "model/DocumentFile.h"
#include "preferences/Translations.h"
#include "tools/SketchTool.h"

namespace rigmesh::test {
namespace {

struct Language {
    const char* code;
    QStringList menus;     // the menu bar's titles, left to right
    QString timelineDock;  // dock titles
    QString weightsDock;
    QString strokeCrosses;  // the status message of a self-crossing stroke starts so
    QString qtCancel;       // Qt's own "Cancel" (qtbase translations)
    QString corruptValue;   // a document whose frame rate is not finite
    QString truncated;      // a document cut short starts so
    // A sketched part with a face taken out: the document's sentence, and
    // the part's own problem (Part::validateSolid) inside it.
    QString openSurfaceStarts;
    QString openSurfaceEnds;
};

void PrintTo(const Language& language, std::ostream* out) {
    *out << language.code;
}

class TranslatedStudio : public testing::TestWithParam<Language> {
  protected:
    void SetUp() override {
        ASSERT_TRUE(recovery.isValid());
        ASSERT_TRUE(widgets::installTranslations(QString::fromLatin1(GetParam().code)));
        window = std::make_unique<widgets::MainWindow>(recovery.path());
        window->resize(1280, 800);
        window->newDocument();
        settle(window.get());
    }
    void TearDown() override {
        window.reset();
        widgets::installTranslations(QStringLiteral("en"));
    }
    widgets::Viewport* viewport() const { return window->currentView()->viewport(); }

    QTemporaryDir recovery;
    std::unique_ptr<widgets::MainWindow> window;
};

TEST_P(TranslatedStudio, MenusAndDocksSpeakTheLanguage) {
    QStringList menus;
    for (QAction* action : window->menuBar()->actions())
        menus << action->text();
    EXPECT_EQ(menus, GetParam().menus);
    EXPECT_EQ(window->findChild<QDockWidget*>(QStringLiteral("timelineDock"))->windowTitle(),
              GetParam().timelineDock);
    EXPECT_EQ(window->findChild<QDockWidget*>(QStringLiteral("weightsDock"))->windowTitle(),
              GetParam().weightsDock);
}

TEST_P(TranslatedStudio, AnEngineMessageReachesTheStatusBarTranslated) {
    window->activateTool<widgets::SketchTool>();
    // A figure eight: the engine's stroke cleaner refuses it by id
    // (MessageId::StrokeCrossesItselfNear) and the studio says so in its
    // language, pointing at the red cross it draws there.
    const QPointF centre(viewport()->width() / 2.0, viewport()->height() / 2.0);
    std::vector<QPointF> eight;
    for (int i = 0; i <= 120; ++i) {
        const double t = 2.0 * M_PI * i / 120.0;
        eight.emplace_back(centre.x() + 220.0 * std::sin(t),
                           centre.y() + 150.0 * std::sin(t) * std::cos(t));
    }
    drag(viewport(), eight);
    EXPECT_EQ(window->currentDocument()->partCount(), 0);
    const QString message = window->statusBar()->currentMessage();
    EXPECT_TRUE(message.startsWith(GetParam().strokeCrosses)) << message.toStdString();
    window->grab().save(
        QStringLiteral(RIGMESH_TEST_OUTPUT "/studio_%1.png").arg(QLatin1String(GetParam().code)));
}

TEST_P(TranslatedStudio, ADamagedDocumentIsReportedWhollyInTheLanguage) {
    // What is wrong comes from the engine's reader (base/JsonRead, by id)
    // inside the model's sentence (model/DocumentFile): both translated.
    const QByteArray good = model::DocumentFile::toBytes(*window->currentDocument());
    nlohmann::json root =
        nlohmann::json::from_cbor(std::vector<std::uint8_t>(good.begin() + 3, good.end()));
    root["timeline"]["framesPerSecond"] = std::numeric_limits<double>::quiet_NaN();
    std::vector<std::uint8_t> bad = {0xD9, 0xD9, 0xF7};
    nlohmann::json::to_cbor(root, bad);
    const auto refusal = [](const QByteArray& bytes) {
        try {
            model::DocumentFile::fromBytes(bytes);
        } catch (const model::DocumentFileError& error) {
            return QString::fromUtf8(error.what());
        }
        return QString();
    };
    EXPECT_EQ(refusal(QByteArray(reinterpret_cast<const char*>(bad.data()),
                                 static_cast<qsizetype>(bad.size()))),
              GetParam().corruptValue);
    const QString truncated = refusal(good.left(good.size() / 2));
    EXPECT_TRUE(truncated.startsWith(GetParam().truncated)) << truncated.toStdString();
}

TEST_P(TranslatedStudio, APartsOwnProblemIsReportedInTheLanguage) {
    // A part sketched here, whose surface then loses a face: the document
    // names the part and what keeps it from being valid (Part::validateSolid,
    // by id), both translated.
    window->activateTool<widgets::SketchTool>();
    const QPointF centre(viewport()->width() / 2.0, viewport()->height() / 2.0);
    std::vector<QPointF> ellipse;
    for (int i = 0; i <= 90; ++i) {
        const double t = 2.0 * M_PI * i / 90.0;
        ellipse.emplace_back(centre.x() + 200.0 * std::cos(t), centre.y() + 90.0 * std::sin(t));
    }
    drag(viewport(), ellipse);
    ASSERT_EQ(window->currentDocument()->partCount(), 1);
    const QByteArray good = model::DocumentFile::toBytes(*window->currentDocument());
    nlohmann::json root =
        nlohmann::json::from_cbor(std::vector<std::uint8_t>(good.begin() + 3, good.end()));
    bool opened = false;
    for (auto& node : root["parts"])
        if (node.contains("part")) {
            auto& corners = node["part"]["mesh"]["faces"];  // three per face
            corners.erase(corners.begin() + static_cast<std::ptrdiff_t>(corners.size()) - 3,
                          corners.end());
            opened = true;
        }
    ASSERT_TRUE(opened);
    std::vector<std::uint8_t> bad = {0xD9, 0xD9, 0xF7};
    nlohmann::json::to_cbor(root, bad);
    QString refusal;
    try {
        model::DocumentFile::fromBytes(QByteArray(reinterpret_cast<const char*>(bad.data()),
                                                  static_cast<qsizetype>(bad.size())));
    } catch (const model::DocumentFileError& error) {
        refusal = QString::fromUtf8(error.what());
    }
    EXPECT_TRUE(refusal.startsWith(GetParam().openSurfaceStarts)) << refusal.toStdString();
    EXPECT_TRUE(refusal.endsWith(GetParam().openSurfaceEnds)) << refusal.toStdString();
}

// Every label, button and list entry of `dialog`, shown at its own size,
// gets the width its translated text asks for: nothing is cut off.
void expectNothingCutOff(QDialog& dialog, const QString& picture) {
    dialog.show();
    QTest::qWait(50);
    for (QLabel* label : dialog.findChildren<QLabel*>()) {
        if (!label->isVisible() || label->wordWrap())
            continue;
        EXPECT_GE(label->width(), label->sizeHint().width()) << label->text().toStdString();
    }
    for (QAbstractButton* button : dialog.findChildren<QAbstractButton*>()) {
        if (!button->isVisible())
            continue;
        EXPECT_GE(button->width(), button->sizeHint().width()) << button->text().toStdString();
    }
    for (QComboBox* box : dialog.findChildren<QComboBox*>()) {
        if (!box->isVisible())
            continue;
        EXPECT_GE(box->width(), box->minimumSizeHint().width()) << box->currentText().toStdString();
    }
    dialog.grab().save(picture);
    dialog.hide();
}

TEST_P(TranslatedStudio, DialogsFitTheirTranslatedText) {
    const QString code = QLatin1String(GetParam().code);
    widgets::PreferencesDialog preferences(window->preferences(), window.get());
    EXPECT_NE(preferences.windowTitle(), QStringLiteral("Preferences"));
    expectNothingCutOff(preferences,
                        QStringLiteral(RIGMESH_TEST_OUTPUT "/preferences_%1.png").arg(code));
    // With the note on skinning shown (the view in dual quaternions).
    widgets::ExportDialog exporter(QStringLiteral("/tmp/biped.glb"), SkinningMethod::DualQuaternion,
                                   window.get());
    EXPECT_NE(exporter.windowTitle(), QStringLiteral("Export"));
    expectNothingCutOff(exporter, QStringLiteral(RIGMESH_TEST_OUTPUT "/export_%1.png").arg(code));
}

TEST_P(TranslatedStudio, QtsOwnStringsAreTranslatedWhereInstalled) {
    const QString qtbase = QLibraryInfo::path(QLibraryInfo::TranslationsPath) +
                           QStringLiteral("/qtbase_%1.qm").arg(QLatin1String(GetParam().code));
    if (!QFile::exists(qtbase))
        GTEST_SKIP() << "Qt's translations are not installed (" << qtbase.toStdString() << ")";
    QDialogButtonBox box(QDialogButtonBox::Cancel);
    EXPECT_EQ(box.button(QDialogButtonBox::Cancel)->text().remove(QLatin1Char('&')),
              GetParam().qtCancel);
}

INSTANTIATE_TEST_SUITE_P(
    Languages, TranslatedStudio,
    testing::Values(
        Language{
            "de",
            {QStringLiteral("&Datei"), QStringLiteral("&Bearbeiten"), QStringLiteral("&Ansicht"),
             QStringLiteral("&Werkzeuge"), QStringLiteral("&Animation"), QStringLiteral("&Hilfe")},
            QStringLiteral("Zeitleiste"),
            QStringLiteral("Skin-Gewichte"),
            QStringLiteral("Nichts erstellt: Der Strich kreuzt sich beim roten Kreuz selbst"),
            QStringLiteral("Abbrechen"),
            QStringLiteral("Das Dokument ist beschädigt: \"timeline\" \"framesPerSecond\" enthält "
                           "einen Wert, der nicht endlich ist."),
            QStringLiteral("Das Dokument ist beschädigt oder abgeschnitten (es endet zu früh, bei "
                           "Byte "),
            QStringLiteral("Das Dokument ist beschädigt: Teil "),
            QStringLiteral(": Die Oberfläche hat 3 Randkanten.")},
        Language{
            "es",
            {QStringLiteral("&Archivo"), QStringLiteral("&Editar"), QStringLiteral("&Vista"),
             QStringLiteral("&Herramientas"), QStringLiteral("A&nimación"),
             QStringLiteral("A&yuda")},
            QStringLiteral("Línea de tiempo"),
            QStringLiteral("Pesos de piel"),
            QStringLiteral("No se creó nada: el trazo se cruza a sí mismo donde está la cruz roja"),
            QStringLiteral("Cancelar"),
            QStringLiteral("El documento está dañado: \"timeline\" \"framesPerSecond\" contiene "
                           "un valor que no es finito."),
            QStringLiteral("El documento está dañado o truncado (termina demasiado pronto, en el "
                           "byte "),
            QStringLiteral("El documento está dañado: pieza "),
            QStringLiteral(": La superficie tiene 3 aristas de borde.")}),
    [](const testing::TestParamInfo<Language>& language) {
        return std::string(language.param.code);
    });

}  // namespace
}  // namespace rigmesh::test
