// Edit > Preferences: each setting takes effect at once
// (the language at the next start) and is kept in QSettings; the window
// layout, the new docks included, comes back as it was left.
#include <gtest/gtest.h>

#include <QAction>
#include <QApplication>
#include <QComboBox>
#include <QDialogButtonBox>
#include <QDockWidget>
#include <QDoubleSpinBox>
#include <QMenuBar>
#include <QPushButton>
#include <QSettings>
#include <QSpinBox>
#include <QStatusBar>
#include <QTimer>
#include <QToolButton>

#include "StudioFixture.h"
#include "dialogs/PreferencesDialog.h"
#include "model/Autosave.h"
#include "preferences/StudioPreferences.h"
#include "preferences/Theme.h"
#include "preferences/Translations.h"

namespace rigmesh::test {
namespace {

using widgets::MouseBindings;
using widgets::PreferencesDialog;
using widgets::StudioPreferences;
using widgets::Theme;

class Preferences : public StudioFixture {
  protected:
    void TearDown() override {
        // Later tests start from the defaults again.
        window.reset();
        StudioPreferences{}.save();
        widgets::applyTheme(Theme::Light);
    }

    // Edit > Preferences as a person uses it: the dialog opens, `choose`
    // sets its controls, OK closes it.
    void setInDialog(const std::function<void(PreferencesDialog&)>& choose) {
        QAction* open = menuAction(QStringLiteral("&Edit"), QStringLiteral("&Preferences..."));
        ASSERT_NE(open, nullptr);
        bool seen = false;
        QTimer::singleShot(0, window.get(), [&] {
            auto* dialog = qobject_cast<PreferencesDialog*>(QApplication::activeModalWidget());
            if (!dialog)
                return;
            seen = true;
            choose(*dialog);
            dialog->findChild<QDialogButtonBox*>()->button(QDialogButtonBox::Ok)->click();
        });
        open->trigger();
        EXPECT_TRUE(seen) << "Edit > Preferences opened no dialog";
    }

    void apply(const std::function<void(StudioPreferences&)>& change) {
        StudioPreferences p = window->preferences();
        change(p);
        window->applyPreferences(p);
    }
};

TEST_F(Preferences, LanguageIsKeptForTheNextStartAndSaidSo) {
    setInDialog([](PreferencesDialog& dialog) {
        dialog.languageBox()->setCurrentIndex(dialog.languageBox()->findData(QStringLiteral("es")));
    });
    EXPECT_EQ(QSettings().value(QStringLiteral("preferences/language")).toString(),
              QStringLiteral("es"));
    EXPECT_EQ(widgets::resolvedLanguage(StudioPreferences::load().language), QStringLiteral("es"));
    EXPECT_TRUE(window->statusBar()->currentMessage().contains(QStringLiteral("starts again")));
    // The running studio keeps its language until then.
    EXPECT_EQ(window->menuBar()->actions().front()->text(), QStringLiteral("&File"));
}

TEST_F(Preferences, TheDialogOffersEveryLanguageAndTheSystemDefault) {
    PreferencesDialog dialog(window->preferences());
    QStringList codes;
    for (int i = 0; i < dialog.languageBox()->count(); ++i)
        codes << dialog.languageBox()->itemData(i).toString();
    EXPECT_EQ(codes, (QStringList{QString(), QStringLiteral("en"), QStringLiteral("de"),
                                  QStringLiteral("es")}));
    EXPECT_EQ(dialog.languageBox()->itemText(2), QStringLiteral("Deutsch"));
    EXPECT_EQ(dialog.languageBox()->itemText(3), QStringLiteral("Español"));
    dialog.grab().save(QStringLiteral(RIGMESH_TEST_OUTPUT "/preferences_dialog.png"));
}

TEST_F(Preferences, DefaultEdgeLengthIsTheEdgeLengthOfNewSketches) {
    window->activateTool<widgets::SketchTool>();
    const QPointF centre(viewport()->width() / 2.0, viewport()->height() / 2.0);
    drag(viewport(), ellipseStroke(centre, 220, 70));
    ASSERT_EQ(document()->partCount(), 1);
    const double automatic = document()->parts().front().options.targetEdgeLength;
    ASSERT_GT(automatic, 0.0);
    const int automaticVertices = document()->parts().front().part->mesh.vertexCount();

    const double coarser = 2.0 * automatic;
    setInDialog([&](PreferencesDialog& dialog) { dialog.edgeLengthBox()->setValue(coarser); });
    EXPECT_NEAR(window->preferences().defaultEdgeLength, coarser, 1e-3);
    drag(viewport(), ellipseStroke(centre, 220, 70));
    ASSERT_EQ(document()->partCount(), 2);
    const model::PartNode& second = document()->parts().back();
    EXPECT_NEAR(second.options.targetEdgeLength, coarser, 1e-3);
    // Twice the edge length, about a quarter of the vertices.
    EXPECT_LT(second.part->mesh.vertexCount(), automaticVertices / 2);
}

TEST_F(Preferences, TheViewSkinsLinearlyByDefaultAsExportedFilesAre) {
    // glTF viewers and Blender skin an exported file linearly.
    EXPECT_FALSE(viewport()->dualQuaternionSkinning());
    QAction* dqs = menuAction(QStringLiteral("&View"), QStringLiteral("&Dual Quaternion Skinning"));
    ASSERT_NE(dqs, nullptr);
    EXPECT_FALSE(dqs->isChecked());
    // Dual quaternions are one click away.
    dqs->trigger();
    EXPECT_TRUE(viewport()->dualQuaternionSkinning());
    dqs->trigger();
    EXPECT_FALSE(viewport()->dualQuaternionSkinning());
}

TEST_F(Preferences, SkinningModeSetsTheViewAndTheViewMenu) {
    ASSERT_FALSE(viewport()->dualQuaternionSkinning());
    setInDialog([](PreferencesDialog& dialog) { dialog.skinningBox()->setCurrentIndex(0); });
    EXPECT_TRUE(window->preferences().dualQuaternionSkinning);
    EXPECT_TRUE(viewport()->dualQuaternionSkinning());
    QAction* dqs = menuAction(QStringLiteral("&View"), QStringLiteral("&Dual Quaternion Skinning"));
    ASSERT_NE(dqs, nullptr);
    EXPECT_TRUE(dqs->isChecked());
    // A document opened afterwards starts with dual quaternion skinning too.
    window->newDocument();
    EXPECT_TRUE(viewport()->dualQuaternionSkinning());
    // And the next start (a new window) as well.
    widgets::MainWindow next(recovery.path());
    next.newDocument();
    EXPECT_TRUE(next.currentView()->viewport()->dualQuaternionSkinning());
}

TEST_F(Preferences, AutosaveIntervalReachesOpenAndNewDocuments) {
    auto delayOf = [](widgets::DocumentView* view) {
        auto* autosave = view->findChild<model::Autosave*>();
        return autosave ? autosave->delay() : -1;
    };
    EXPECT_EQ(delayOf(window->currentView()), 3000);
    setInDialog([](PreferencesDialog& dialog) { dialog.autosaveBox()->setValue(7); });
    EXPECT_EQ(delayOf(window->currentView()), 7000);
    window->newDocument();
    EXPECT_EQ(delayOf(window->currentView()), 7000);
}

TEST_F(Preferences, MayaBindingsNavigateWithAltAndLeaveTheToolAlone) {
    const model::PartId id = addExampleBiped();
    window->activateTool<widgets::SelectTool>();
    // The first paint frames the scene: let it happen before the camera is measured.
    QTest::qWait(50);
    const QPointF middle(viewport()->width() / 2.0, viewport()->height() / 2.0);
    const QVector3D eye = viewport()->camera().eye();
    const model::Placement placed = document()->part(id).placement;

    // Blender bindings: Alt + left drag is the tool's (it may move the part), not the view's.
    const int before = document()->undoStack()->count();
    drag(viewport(), {middle, middle + QPointF(40, 0), middle + QPointF(80, 10)}, Qt::AltModifier);
    EXPECT_EQ(viewport()->camera().eye(), eye);
    if (document()->undoStack()->count() > before)
        document()->undoStack()->undo();

    setInDialog([](PreferencesDialog& dialog) {
        dialog.mouseBox()->setCurrentIndex(dialog.mouseBox()->findData(1));
    });
    ASSERT_EQ(viewport()->mouseBindings(), MouseBindings::Maya);
    const int steps = document()->undoStack()->count();
    // Alt + left drag orbits.
    drag(viewport(), {middle, middle + QPointF(40, 0), middle + QPointF(80, 10)}, Qt::AltModifier);
    EXPECT_GT((viewport()->camera().eye() - eye).length(), 0.01f);
    EXPECT_EQ(document()->undoStack()->count(), steps);
    EXPECT_EQ(document()->part(id).placement.translation, placed.translation);
    // Alt + middle drag pans: the target moves.
    const QVector3D target = viewport()->camera().target();
    buttonDrag(viewport(), Qt::MiddleButton, middle, middle + QPointF(60, 0), Qt::AltModifier);
    EXPECT_GT((viewport()->camera().target() - target).length(), 0.001f);
    // Alt + right drag zooms: right is closer.
    const double distance = viewport()->camera().distance();
    buttonDrag(viewport(), Qt::RightButton, middle, middle + QPointF(120, 0), Qt::AltModifier);
    EXPECT_LT(viewport()->camera().distance(), distance);
    // A plain middle drag is no longer the view's.
    const QVector3D unmoved = viewport()->camera().eye();
    buttonDrag(viewport(), Qt::MiddleButton, middle, middle + QPointF(60, 30));
    EXPECT_EQ(viewport()->camera().eye(), unmoved);
    // The status bar and the first-run card name the Maya gestures.
    EXPECT_TRUE(widgets::navigationHint(MouseBindings::Maya).contains(QStringLiteral("Alt")));
}

TEST_F(Preferences, BlenderBindingsOrbitPanAndZoomWithTheMiddleButton) {
    const QPointF middle(viewport()->width() / 2.0, viewport()->height() / 2.0);
    auto middleDrag = [&](QPointF by, Qt::KeyboardModifiers modifiers) {
        buttonDrag(viewport(), Qt::MiddleButton, middle, middle + by, modifiers);
    };
    const QVector3D target = viewport()->camera().target();
    const QVector3D eye = viewport()->camera().eye();
    middleDrag(QPointF(50, 0), Qt::NoModifier);  // orbit: same target, other eye
    EXPECT_EQ(viewport()->camera().target(), target);
    EXPECT_GT((viewport()->camera().eye() - eye).length(), 0.01f);
    middleDrag(QPointF(50, 0), Qt::ShiftModifier);  // pan
    EXPECT_GT((viewport()->camera().target() - target).length(), 0.001f);
    const double distance = viewport()->camera().distance();
    middleDrag(QPointF(0, -120), Qt::ControlModifier);  // zoom: up is closer
    EXPECT_LT(viewport()->camera().distance(), distance);
}

TEST_F(Preferences, DarkThemeDarkensTheWholeStudioAtOnce) {
    setInDialog([](PreferencesDialog& dialog) {
        dialog.themeBox()->setCurrentIndex(dialog.themeBox()->findData(1));
    });
    EXPECT_EQ(window->preferences().theme, Theme::Dark);
    EXPECT_EQ(QApplication::style()->name().toLower(), QStringLiteral("fusion"));
    EXPECT_LT(QApplication::palette().color(QPalette::Window).lightness(), 70);
    EXPECT_GT(QApplication::palette().color(QPalette::WindowText).lightness(), 180);
    EXPECT_LT(window->palette().color(QPalette::Window).lightness(), 70);  // the open window too
    // The timeline's transport icons are light on the dark buttons.
    auto* play = window->findChild<QToolButton*>(QStringLiteral("timelinePlay"));
    ASSERT_NE(play, nullptr);
    const QImage icon = play->icon().pixmap(16, 16).toImage();
    int lightest = 0;
    for (int y = 0; y < icon.height(); ++y)
        for (int x = 0; x < icon.width(); ++x)
            if (qAlpha(icon.pixel(x, y)) > 200)
                lightest = std::max(lightest, QColor(icon.pixel(x, y)).lightness());
    EXPECT_GT(lightest, 180);
    addExampleBiped();
    window->grab().save(QStringLiteral(RIGMESH_TEST_OUTPUT "/studio_dark.png"));
    apply([](StudioPreferences& p) { p.theme = Theme::Light; });
    EXPECT_GT(QApplication::palette().color(QPalette::Window).lightness(), 180);
}

TEST_F(Preferences, RestoreDefaultsResetsTheDialogOnly) {
    StudioPreferences changed;
    changed.autosaveSeconds = 30;
    changed.mouseBindings = MouseBindings::Maya;
    PreferencesDialog dialog(changed);
    dialog.findChild<QDialogButtonBox*>()->button(QDialogButtonBox::RestoreDefaults)->click();
    EXPECT_EQ(dialog.preferences(), StudioPreferences{});
    EXPECT_EQ(window->preferences(), StudioPreferences{});
}

TEST_F(Preferences, OutOfRangeSettingsReadAsDefaults) {
    QSettings settings;
    settings.setValue(QStringLiteral("preferences/autosaveSeconds"), 0);
    settings.setValue(QStringLiteral("preferences/defaultEdgeLength"), -1.0);
    settings.setValue(QStringLiteral("preferences/mouseBindings"), QStringLiteral("houdini"));
    EXPECT_EQ(StudioPreferences::load(), StudioPreferences{});
}

TEST_F(Preferences, WindowLayoutWithTheNewDocksComesBack) {
    auto* timeline = window->findChild<QDockWidget*>(QStringLiteral("timelineDock"));
    auto* weights = window->findChild<QDockWidget*>(QStringLiteral("weightsDock"));
    ASSERT_TRUE(timeline && weights);
    window->addDockWidget(Qt::TopDockWidgetArea, timeline);
    window->addDockWidget(Qt::LeftDockWidgetArea, weights);
    window->findChild<QDockWidget*>(QStringLiteral("historyDock"))->hide();
    window->close();  // keeps the layout, as quitting does

    widgets::MainWindow next(recovery.path());
    settle(&next);
    EXPECT_EQ(next.dockWidgetArea(next.findChild<QDockWidget*>(QStringLiteral("timelineDock"))),
              Qt::TopDockWidgetArea);
    EXPECT_EQ(next.dockWidgetArea(next.findChild<QDockWidget*>(QStringLiteral("weightsDock"))),
              Qt::LeftDockWidgetArea);
    EXPECT_FALSE(next.findChild<QDockWidget*>(QStringLiteral("historyDock"))->isVisible());
    EXPECT_TRUE(next.findChild<QDockWidget*>(QStringLiteral("timelineDock"))->isVisible());
    next.close();
    QSettings().remove(QStringLiteral("window"));
}

TEST_F(Preferences, ALayoutSavedBeforeTheNewDocksShowsThemWhereTheyBelong) {
    // A studio before the timeline and the Skin Weights panel saved its
    // layout without them: they must still appear, at their default places.
    auto* timeline = window->findChild<QDockWidget*>(QStringLiteral("timelineDock"));
    auto* weights = window->findChild<QDockWidget*>(QStringLiteral("weightsDock"));
    window->removeDockWidget(timeline);
    window->removeDockWidget(weights);
    QSettings().setValue(QStringLiteral("window/state"), window->saveState());

    widgets::MainWindow next(recovery.path());
    settle(&next);
    auto* nextTimeline = next.findChild<QDockWidget*>(QStringLiteral("timelineDock"));
    auto* nextWeights = next.findChild<QDockWidget*>(QStringLiteral("weightsDock"));
    EXPECT_TRUE(nextTimeline->isVisible());
    EXPECT_EQ(next.dockWidgetArea(nextTimeline), Qt::BottomDockWidgetArea);
    EXPECT_FALSE(nextTimeline->isFloating());
    EXPECT_EQ(next.dockWidgetArea(nextWeights), Qt::RightDockWidgetArea);
    EXPECT_FALSE(nextWeights->isFloating());
    next.close();
    QSettings().remove(QStringLiteral("window"));
}

}  // namespace
}  // namespace rigmesh::test
