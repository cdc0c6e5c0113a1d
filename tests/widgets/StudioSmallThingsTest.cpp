// The small things an artist stumbles on: a self-crossing stroke is shown,
// not told in coordinates; the timeline scrolls its rows; the Properties
// panel shows the current document's edge length; recovered documents keep
// their names and dates speak the studio's language; "1 bone"; the dark
// theme's icons and Lock boxes show; the window has a minimum size; an undo
// replaces the undone step's message; the pinned vertex goes with the weight
// views; tooltips name the keys; the example's weights are a fresh solve.
#include <gtest/gtest.h>

#include <QAbstractButton>
#include <QAction>
#include <QCheckBox>
#include <QDateTime>
#include <QDockWidget>
#include <QDoubleSpinBox>
#include <QFile>
#include <QLabel>
#include <QMessageBox>
#include <QRegularExpression>
#include <QScrollBar>
#include <QStatusBar>
#include <QTabWidget>
#include <QTemporaryDir>
#include <QTimer>
#include <QTreeView>
#include <QUndoStack>
#include <QUndoView>
#include <iostream>

#include "CommandLineFiles.h"
#include "DocumentView.h"
#include "ExampleDocument.h"
#include "StudioFixture.h"
#include "jobs/JobRunner.h"
#include "merge/MergeParts.h"
#include "model/Autosave.h"
#include "model/DocumentExport.h"
#include "model/DocumentFile.h"
#include "model/commands/RenamePartCommand.h"
#include "panels/OutlinerPanel.h"
#include "panels/PropertiesPanel.h"
#include "part/BoneWeights.h"
#include "preferences/Theme.h"
#include "preferences/Translations.h"
#include "rig/LocalBoneHeat.h"
#include "timeline/TimelineDock.h"
#include "timeline/TimelineView.h"
#include "viewport/ViewMath.h"
#include "viewport/Viewport.h"

namespace rigmesh {
namespace {

using test::drag;

// A closed ellipse outline in document units: a part of one bone.
std::vector<Vec2> ellipse() {
    std::vector<Vec2> points;
    for (int i = 0; i < 64; ++i) {
        const double t = 2.0 * M_PI * i / 64.0;
        points.emplace_back(1.5 * std::cos(t), 0.6 * std::sin(t));
    }
    return points;
}

class StudioSmallThings : public test::StudioFixture {
  protected:
    QString status() const { return window->statusBar()->currentMessage(); }
    // Near-white pixels in the check box at the start of the Outliner's
    // selected row (its first 20 pixels, before the name).
    int checkMarkPixels() const {
        QTreeView* tree = window->outliner()->view();
        const QModelIndex row = tree->currentIndex();
        if (!row.isValid())
            return -1;
        const QRect cell = tree->visualRect(row.siblingAtColumn(0));
        const QImage image =
            tree->viewport()->grab(QRect(cell.left(), cell.top(), 20, cell.height())).toImage();
        image.save(QStringLiteral(RIGMESH_TEST_OUTPUT "/studio_outliner_selected_box.png"));
        int light = 0;
        for (int y = 0; y < image.height(); ++y)
            for (int x = 0; x < image.width(); ++x)
                light += QColor(image.pixel(x, y)).lightness() > 200;
        return light;
    }
};

TEST_F(StudioSmallThings, ASelfCrossingStrokeIsMarkedNotToldInCoordinates) {
    window->activateTool<widgets::SketchTool>();
    const QPointF c(viewport()->width() / 2.0, viewport()->height() / 2.0);
    // A figure eight.
    std::vector<QPointF> eight;
    for (int i = 0; i <= 120; ++i) {
        const double t = 2.0 * M_PI * i / 120.0;
        eight.emplace_back(c.x() + 200.0 * std::sin(t), c.y() + 120.0 * std::sin(2.0 * t));
    }
    drag(viewport(), eight);
    EXPECT_EQ(document()->partCount(), 0);
    EXPECT_TRUE(status().contains(QStringLiteral("red cross"))) << status().toStdString();
    EXPECT_FALSE(status().contains(QLatin1Char('('))) << status().toStdString();
    EXPECT_FALSE(status().contains(QRegularExpression(QStringLiteral("[0-9]"))))
        << status().toStdString();
    ASSERT_TRUE(viewport()->problemMark().has_value());
    // The mark is where the stroke crosses itself: the eight's middle.
    const QVector3D mark =
        viewport()->camera().project(*viewport()->problemMark(), QSizeF(viewport()->size()));
    EXPECT_LT(QLineF(QPointF(mark.x(), mark.y()), c).length(), 25.0);
    QTest::qWait(50);
    window->grab().save(QStringLiteral(RIGMESH_TEST_OUTPUT "/studio_self_crossing.png"));
    // A new stroke takes the mark away.
    drag(viewport(), test::ellipseStroke(c, 150, 80));
    EXPECT_FALSE(viewport()->problemMark().has_value());
}

TEST_F(StudioSmallThings, TheTimelineScrollsRowsThatDoNotFit) {
    const model::PartId biped = addExampleBiped();
    auto* view = window->findChild<widgets::TimelineView*>(QStringLiteral("timelineView"));
    ASSERT_NE(view, nullptr);
    auto* bar = view->findChild<QScrollBar*>(QStringLiteral("timelineRowsScrollBar"));
    ASSERT_NE(bar, nullptr);
    view->setExpanded(biped, true);  // a row per joint
    QTest::qWait(20);
    ASSERT_GT(document()->part(biped).part->skeleton.jointCount() * 20, view->height());
    EXPECT_TRUE(bar->isVisible()) << "more rows than fit";
    bar->setValue(bar->maximum());
    EXPECT_GT(bar->maximum(), 0);
    view->setExpanded(biped, false);
    QTest::qWait(20);
    EXPECT_FALSE(bar->isVisible()) << "one row fits";
}

TEST_F(StudioSmallThings, PropertiesShowTheCurrentDocumentsEdgeLength) {
    const model::PartId biped = addExampleBiped();
    document()->setSelection({biped, kNoJoint});
    auto* edge = window->propertiesPanel()->findChild<QDoubleSpinBox*>();
    ASSERT_NE(edge, nullptr);
    const double bipedEdge = edge->value();
    EXPECT_GT(bipedEdge, 0.0);
    window->newDocument();  // empty: nothing selected
    QTest::qWait(20);
    EXPECT_EQ(edge->value(), 0.0) << "not the other document's";
}

TEST_F(StudioSmallThings, RecoveredDocumentsKeepTheirNamesAndDatesSpeakTheLanguage) {
    QTemporaryDir folder;
    model::Document document;
    document.setUntitledName(QStringLiteral("Untitled 7"));
    model::Autosave autosave(&document, folder.path());
    document.undoStack()->push(
        model::CreatePartCommand::create(document, ellipse(), "blob").release());
    ASSERT_TRUE(autosave.writeNow());
    const QList<model::RecoveryFile> files = model::Autosave::recoveryFiles(folder.path());
    ASSERT_EQ(files.size(), 1);
    EXPECT_EQ(files.front().name, QStringLiteral("Untitled 7"));
    const QString english = widgets::FilesController::recoveryQuestion(files.front());
    EXPECT_TRUE(english.contains(QStringLiteral("\"Untitled 7\""))) << english.toStdString();
    widgets::setTranslationsDirectory(QStringLiteral(RIGMESH_QM_DIR));
    ASSERT_TRUE(widgets::installTranslations(QStringLiteral("de")));
    const QString german = widgets::FilesController::recoveryQuestion(files.front());
    widgets::installTranslations(QStringLiteral("en"));
    EXPECT_TRUE(german.contains(
        QLocale(QLocale::German).toString(files.front().lastModified, QLocale::LongFormat)))
        << german.toStdString();
}

TEST_F(StudioSmallThings, OneBoneIsOneBone) {
    // The shared tube sketch is a part of one bone.
    document()->undoStack()->push(
        model::CreatePartCommand::create(
            *document(), readSketchFile(std::string(RIGMESH_SHARED_SKETCHES) + "/tube.json").points,
            "tube")
            .release());
    const model::PartNode& node = document()->parts().front();
    ASSERT_EQ(node.part->skeleton.boneCount(), 1);
    document()->setSelection({node.id, kNoJoint});
    QString figures;
    for (QLabel* label : window->propertiesPanel()->findChildren<QLabel*>())
        figures += label->text();
    EXPECT_TRUE(figures.contains(QStringLiteral("1 bone"))) << figures.toStdString();
    EXPECT_FALSE(figures.contains(QStringLiteral("1 bones"))) << figures.toStdString();
}

// Mean lightness of an icon's opaque pixels.
double lightness(const QIcon& icon) {
    const QImage image = icon.pixmap(24, 24).toImage().convertToFormat(QImage::Format_ARGB32);
    double sum = 0.0;
    int count = 0;
    for (int y = 0; y < image.height(); ++y)
        for (int x = 0; x < image.width(); ++x) {
            const QColor c = QColor::fromRgba(image.pixel(x, y));
            if (c.alpha() > 200) {
                sum += c.lightness();
                ++count;
            }
        }
    return count > 0 ? sum / count : 0.0;
}

TEST_F(StudioSmallThings, TheDarkThemesIconsAndLockBoxesStandOut) {
    for (const char* name : {"sketch", "pose", "select", "cut"}) {
        const QString path = QStringLiteral(":/icons/%1.svg").arg(QLatin1String(name));
        // Light lines on the dark palette; the light theme's icon as drawn.
        EXPECT_GT(lightness(widgets::themedIcon(path, widgets::Theme::Dark)), 130.0) << name;
        EXPECT_EQ(widgets::themedIcon(path, widgets::Theme::Light).pixmap(24, 24).toImage(),
                  QIcon(path).pixmap(24, 24).toImage())
            << name;
    }
    widgets::StudioPreferences dark = window->preferences();
    dark.theme = widgets::Theme::Dark;
    window->applyPreferences(dark);
    EXPECT_TRUE(window->styleSheet().contains(QStringLiteral("indicator")));
    const model::PartId biped = addExampleBiped();
    document()->setSelection({biped, kNoJoint});
    for (auto* dock : window->findChildren<QDockWidget*>())
        if (dock->objectName() == QStringLiteral("weightsDock"))
            dock->raise();
    QTest::qWait(50);
    window->grab().save(QStringLiteral(RIGMESH_TEST_OUTPUT "/studio_dark_theme.png"));
    // The selected part's row in the Outliner: its visibility box shows
    // checked, a light check mark on the highlight (a box filled with the
    // highlight colour vanished into the row).
    EXPECT_GT(checkMarkPixels(), 6) << "the visible part's box shows its check mark";
    widgets::StudioPreferences light = dark;
    light.theme = widgets::Theme::Light;
    window->applyPreferences(light);
    EXPECT_TRUE(window->styleSheet().isEmpty());
    QTest::qWait(50);
    window->grab().save(QStringLiteral(RIGMESH_TEST_OUTPUT "/studio_light_theme.png"));
}

TEST_F(StudioSmallThings, TheWindowKeepsRoomForTheViewAndTheDocks) {
    EXPECT_GE(window->minimumSize().width(), 900);
    EXPECT_GE(window->minimumSize().height(), 600);
    window->resize(520, 360);
    QTest::qWait(50);
    EXPECT_GE(window->width(), 900);
    // No dock lies over the view.
    const QRect view(viewport()->mapTo(window.get(), QPoint(0, 0)), viewport()->size());
    for (auto* dock : window->findChildren<QDockWidget*>()) {
        if (dock->isVisible() && !dock->isFloating()) {
            EXPECT_FALSE(
                QRect(dock->mapTo(window.get(), QPoint(0, 0)), dock->size()).intersects(view))
                << dock->objectName().toStdString();
        }
    }
    window->grab().save(QStringLiteral(RIGMESH_TEST_OUTPUT "/studio_minimum_size.png"));
}

TEST_F(StudioSmallThings, AnUndoReplacesTheUndoneStepsMessage) {
    const model::PartId biped = addExampleBiped();
    document()->setSelection({biped, kNoJoint});
    window->showStatus(QStringLiteral("Cut biped in 20 ms"));
    document()->undoStack()->undo();
    EXPECT_TRUE(status().startsWith(QStringLiteral("Undone: "))) << status().toStdString();
    // Ctrl+Shift+Z, the Edit menu's Redo.
    QTest::keyClick(window.get(), Qt::Key_Z, Qt::ControlModifier | Qt::ShiftModifier);
    ASSERT_EQ(document()->undoStack()->index(), 1);
    EXPECT_TRUE(status().startsWith(QStringLiteral("Redone: "))) << status().toStdString();
}

// A new step after an undo takes the place of the undone one: the stack's
// index and count are as after a redo, but nothing was redone, and the new
// step's own message stays.
TEST_F(StudioSmallThings, ANewStepAfterAnUndoIsNotCalledARedo) {
    const model::PartId biped = addExampleBiped();
    document()->undoStack()->push(new model::RenamePartCommand(*document(), biped, "first"));
    document()->undoStack()->undo();
    ASSERT_EQ(document()->undoStack()->count(), 2);
    ASSERT_EQ(document()->undoStack()->index(), 1);
    document()->undoStack()->push(new model::RenamePartCommand(*document(), biped, "second"));
    ASSERT_EQ(document()->undoStack()->count(), 2);
    ASSERT_EQ(document()->undoStack()->index(), 2);
    window->showStatus(QStringLiteral("Renamed"));
    QCoreApplication::processEvents();
    EXPECT_EQ(status(), QStringLiteral("Renamed"));
    // Several steps to redo at once from the History dock: a redo.
    document()->undoStack()->setIndex(0);
    EXPECT_TRUE(status().startsWith(QStringLiteral("Undone: "))) << status().toStdString();
    auto* history = window->findChild<QUndoView*>();
    ASSERT_NE(history, nullptr);
    for (auto* dock : window->findChildren<QDockWidget*>())
        if (dock->objectName() == QStringLiteral("historyDock")) {
            dock->show();
            dock->raise();
        }
    QTest::qWait(20);
    // Row 0 is the original state, row 2 the second step.
    const QRect last = history->visualRect(history->model()->index(2, 0));
    ASSERT_FALSE(last.isEmpty());
    QTest::mouseClick(history->viewport(), Qt::LeftButton, {}, last.center());
    EXPECT_EQ(document()->undoStack()->index(), 2);
    EXPECT_TRUE(status().startsWith(QStringLiteral("Redone: "))) << status().toStdString();
    // One step to redo, redone from the History dock.
    document()->undoStack()->undo();
    QTest::mouseClick(history->viewport(), Qt::LeftButton, {}, last.center());
    EXPECT_EQ(document()->undoStack()->index(), 2);
    EXPECT_TRUE(status().startsWith(QStringLiteral("Redone: "))) << status().toStdString();
}

TEST_F(StudioSmallThings, ThePinnedVertexGoesWithTheWeightView) {
    const model::PartId biped = addExampleBiped();
    viewport()->setWeightView(widgets::WeightView::DominantBone);
    viewport()->setInspectedVertex(widgets::Viewport::SurfaceHit{biped, 10});
    EXPECT_TRUE(viewport()->inspectedVertex().has_value());
    viewport()->setWeightView(widgets::WeightView::Off);
    EXPECT_FALSE(viewport()->inspectedVertex().has_value());
}

TEST_F(StudioSmallThings, ToolTipsNameTheKeys) {
    for (const widgets::ToolRegistry::Entry& entry : window->tools()->entries()) {
        const QString key = entry.action->shortcut().toString(QKeySequence::NativeText);
        EXPECT_TRUE(entry.action->toolTip().endsWith(QStringLiteral("(%1)").arg(key)))
            << entry.action->toolTip().toStdString();
    }
}

// The example is the first thing a newcomer inspects: Difference from Global
// Weights shows nothing on it.
TEST_F(StudioSmallThings, TheExamplesWeightsAreAFreshSolve) {
    const std::unique_ptr<model::Document> example = studio::makeExampleDocument();
    ASSERT_EQ(example->partCount(), 1);
    EXPECT_FALSE(example->isModified());
    EXPECT_EQ(example->undoStack()->count(), 0);
    const Part& part = *example->parts().front().part;
    EXPECT_FALSE(part.weightsPainted);
    const WeightsById fresh = recomputeWeightsGlobally(part.mesh, part.skeleton);
    double worst = 0.0;
    for (double d : weightDifferences(part.weights.perVertex, fresh))
        worst = std::max(worst, d);
    EXPECT_LT(worst, 1e-9);
}

// The studio's start: the example's build and solve run on the worker
// thread, so the window is there at once and the part arrives, framed, as
// a clean document with no history whose weights are a fresh solve.
TEST_F(StudioSmallThings, TheExampleIsBuiltWithoutBlockingTheWindow) {
    const int before = static_cast<int>(window->views().size());
    studio::openExample(*window);
    ASSERT_EQ(static_cast<int>(window->views().size()), before + 1);
    model::Document* example = window->currentView()->document();
    EXPECT_EQ(example->partCount(), 0) << "the part comes from the worker";
    EXPECT_TRUE(window->jobs()->busy());
    test::waitForJobs();
    ASSERT_EQ(example->partCount(), 1) << status().toStdString();
    EXPECT_FALSE(example->isModified());
    EXPECT_EQ(example->undoStack()->count(), 0);
    const Part& part = *example->parts().front().part;
    EXPECT_TRUE(part.validate().empty());
    const WeightsById fresh = recomputeWeightsGlobally(part.mesh, part.skeleton);
    double worst = 0.0;
    for (double d : weightDifferences(part.weights.perVertex, fresh))
        worst = std::max(worst, d);
    EXPECT_LT(worst, 1e-9);
    // Framed when it arrived: the whole part is in the view.
    const widgets::Viewport& view = *window->currentView()->viewport();
    for (int v = 0; v < part.mesh.vertexCount(); v += 97) {
        const QVector3D s = view.camera().project(
            widgets::toQt(example->parts().front().placement.toWorld(part.mesh.vertices[v])),
            QSizeF(view.size()));
        EXPECT_TRUE(QRectF(QPointF(0, 0), QSizeF(view.size())).contains(QPointF(s.x(), s.y())))
            << v;
    }
}

// Counted things read as English counts them: the sources' "%n bone(s)" in
// English's own forms (translations/rigmesh_en.ts), "1 bone" and "10
// bones"; Spanish keeps its own. English is listed once among the
// languages.
TEST_F(StudioSmallThings, CountsReadAsEnglishSaysThem) {
    auto rigged = [](int n) {
        return QCoreApplication::translate("RigPartCommand", "%1 rigged with %n bone(s)", nullptr,
                                           n)
            .arg(QStringLiteral("biped"));
    };
    auto painted = [](int n) {
        return QCoreApplication::translate("rigmesh::widgets::PaintTool",
                                           "Painted %n dab(s), %1 vertices changed", nullptr, n);
    };
    ASSERT_TRUE(widgets::installTranslations(QStringLiteral("en")));
    EXPECT_EQ(rigged(1), QStringLiteral("biped rigged with 1 bone"));
    EXPECT_EQ(rigged(10), QStringLiteral("biped rigged with 10 bones"));
    EXPECT_EQ(painted(1), QStringLiteral("Painted 1 dab, %1 vertices changed"));
    EXPECT_EQ(painted(3), QStringLiteral("Painted 3 dabs, %1 vertices changed"));
    ASSERT_TRUE(widgets::installTranslations(QStringLiteral("es")));
    EXPECT_EQ(rigged(1), QStringLiteral("biped riggeada con 1 hueso"));
    EXPECT_EQ(rigged(10), QStringLiteral("biped riggeada con 10 huesos"));
    widgets::installTranslations(QStringLiteral("en"));
    int english = 0;
    for (const widgets::StudioLanguage& language : widgets::studioLanguages())
        english += language.code == QLatin1String("en");
    EXPECT_EQ(english, 1);
}

// rigmesh-studio FILE.obj: a file that is not a document is imported into a
// new document, one undo step as File > Import makes it; a missing file and
// a file that is no 3D scene are refused with a message that names them,
// and leave no part behind.
TEST_F(StudioSmallThings, AFileNamedOnTheCommandLineIsImportedIntoANewDocument) {
    QTemporaryDir scratch;
    ASSERT_TRUE(scratch.isValid());
    model::Document source;
    source.undoStack()->push(model::CreatePartCommand::create(source, ellipse(), "blob").release());
    const QString obj = scratch.filePath(QStringLiteral("blob.obj"));
    model::exportDocument(source, obj.toStdString(), ExportOptions{});
    // Messages are read and closed as they come; the offer to rig the
    // imported mesh is answered "Not Now".
    QStringList messages;
    QTimer answerer;
    answerer.setInterval(10);
    QObject::connect(&answerer, &QTimer::timeout, [&] {
        for (QWidget* widget : QApplication::topLevelWidgets()) {
            auto* box = qobject_cast<QMessageBox*>(widget);
            if (!box || !box->isVisible())
                continue;
            if (box->objectName() == QStringLiteral("offerToRig")) {
                for (QAbstractButton* button : box->buttons())
                    if (box->buttonRole(button) == QMessageBox::RejectRole)
                        button->click();
                continue;
            }
            messages << box->text();
            box->close();
        }
    });
    answerer.start();
    const int tabs = window->tabs()->count();
    widgets::openFromCommandLine(*window, obj);
    test::waitForJobs();
    ASSERT_EQ(window->tabs()->count(), tabs + 1) << "a new document";
    ASSERT_EQ(document()->partCount(), 1) << messages.join(QLatin1Char('\n')).toStdString();
    EXPECT_EQ(document()->undoStack()->count(), 1);
    EXPECT_GT(document()->parts().front().part->mesh.vertexCount(), 100);
    // An imported mesh was never smoothed and cannot be rebuilt: its sketch
    // options are greyed out, and the smoothing box does not claim it was.
    document()->setSelection({document()->parts().front().id, kNoJoint});
    QTest::qWait(20);
    auto* smoothing = window->propertiesPanel()->findChild<QCheckBox*>();
    ASSERT_NE(smoothing, nullptr);
    EXPECT_FALSE(smoothing->isEnabled());
    EXPECT_FALSE(smoothing->isChecked());
    document()->undoStack()->undo();
    EXPECT_EQ(document()->partCount(), 0);

    const QString missing = scratch.filePath(QStringLiteral("missing.obj"));
    widgets::openFromCommandLine(*window, missing);
    test::waitWhile([&] { return messages.isEmpty(); }, 5000);
    ASSERT_EQ(messages.size(), 1);
    EXPECT_TRUE(messages.front().contains(missing)) << messages.front().toStdString();
    EXPECT_EQ(window->tabs()->count(), tabs + 1) << "no document for a missing file";

    const QString junk = scratch.filePath(QStringLiteral("junk.obj"));
    QFile file(junk);
    ASSERT_TRUE(file.open(QIODevice::WriteOnly));
    file.write("this is not a mesh\n");
    file.close();
    widgets::openFromCommandLine(*window, junk);
    test::waitForJobs();
    test::waitWhile([&] { return messages.size() < 2; }, 10000);
    answerer.stop();
    ASSERT_EQ(messages.size(), 2);
    std::cout << "junk.obj: " << messages.back().toStdString() << std::endl;
    EXPECT_FALSE(messages.back().isEmpty());
    EXPECT_EQ(document()->partCount(), 0);
}

}  // namespace
}  // namespace rigmesh
