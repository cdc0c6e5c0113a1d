// The studio end to end, as a newcomer uses it: sketch a part, see it in the
// outliner, undo and redo it, pose it by dragging a joint.
#include <gtest/gtest.h>

#include <QAction>
#include <QCheckBox>
#include <QCursor>
#include <QDoubleSpinBox>
#include <QIcon>
#include <QImage>
#include <QSettings>
#include <QStatusBar>
#include <QTemporaryDir>
#include <QTreeView>
#include <QUndoStack>
#include <QtMath>
#include <algorithm>
#include <set>

#include "DocumentView.h"
#include "EmbeddedExamples.h"
#include "MainWindow.h"
#include "StudioPoseFixture.h"
#include "StudioTestSupport.h"
#include "model/Document.h"
#include "model/DocumentExport.h"
#include "model/DocumentFile.h"
#include "model/commands/CreatePartCommand.h"
#include "model/commands/ImportPartsCommand.h"
#include "panels/OutlinerPanel.h"
#include "pose/PoseHierarchy.h"
#include "pose/Skinning.h"
#include "sketch/Sketch.h"
#include "viewport/ViewMath.h"

namespace rigmesh {
namespace {

using test::drag;
using test::ellipseStroke;
using test::settle;

using Studio = test::StudioPose;

TEST_F(Studio, ToolIconsAreOurOwnAndDraw) {
    // A missing SVG icon engine (libqt6svg6) would leave the tools blank.
    for (const char* name : {"sketch", "select", "pose"}) {
        const QIcon icon(QStringLiteral(":/icons/%1.svg").arg(QLatin1String(name)));
        const QImage image = icon.pixmap(24, 24).toImage();
        ASSERT_FALSE(image.isNull()) << name;
        int drawn = 0;
        for (int y = 0; y < image.height(); ++y)
            for (int x = 0; x < image.width(); ++x)
                drawn += qAlpha(image.pixel(x, y)) > 0 ? 1 : 0;
        EXPECT_GT(drawn, 40) << name << " draws almost nothing";
    }
    window->grab().copy(0, 0, 400, 60).save(QStringLiteral(RIGMESH_TEST_OUTPUT "/toolbar.png"));
}

TEST_F(Studio, SelectedPartIsOutlined) {
    const model::PartId id = sketchEllipse();
    ASSERT_NE(id, model::kNoPart);
    // Pixels of the outline's orange (1.0, 0.55, 0.1), flat, unlit.
    auto outlinePixels = [&] {
        const QImage frame = viewport()->grabFramebuffer().convertToFormat(QImage::Format_RGB32);
        int count = 0;
        for (int y = 0; y < frame.height(); ++y)
            for (int x = 0; x < frame.width(); ++x) {
                const QRgb p = frame.pixel(x, y);
                count += qRed(p) > 240 && std::abs(qGreen(p) - 140) < 12 && qBlue(p) < 40 ? 1 : 0;
            }
        return count;
    };
    document()->setSelection({id, kNoJoint});
    const int selected = outlinePixels();
    document()->clearSelection();
    const int unselected = outlinePixels();
    EXPECT_GT(selected, 500) << "an outline around the selected part";
    EXPECT_LT(unselected, selected / 20);
}

TEST(StudioFirstRun, MouseHintShowsOnceUntilTheFirstPartIsMade) {
    QSettings().remove(QStringLiteral("hints/mouseShown"));
    QTemporaryDir recovery;
    auto window = std::make_unique<widgets::MainWindow>(recovery.path());
    window->resize(1200, 800);
    window->newDocument();
    settle(window.get());
    auto* hint = window->findChild<QWidget*>(QStringLiteral("MouseHint"));
    ASSERT_NE(hint, nullptr);
    EXPECT_TRUE(hint->isVisible()) << "a first run shows the mouse gestures";
    window->grab().save(QStringLiteral(RIGMESH_TEST_OUTPUT "/studio_first_run.png"));
    window->activateTool<widgets::SketchTool>();
    widgets::Viewport* viewport = window->currentView()->viewport();
    drag(viewport,
         ellipseStroke(QPointF(viewport->width() / 2.0, viewport->height() / 2.0), 200, 60));
    ASSERT_EQ(window->currentDocument()->partCount(), 1);
    EXPECT_FALSE(hint->isVisible()) << "the first part closes it";
    // The next start does not show it again.
    auto again = std::make_unique<widgets::MainWindow>(recovery.path());
    again->newDocument();
    settle(again.get());
    EXPECT_FALSE(again->findChild<QWidget*>(QStringLiteral("MouseHint"))->isVisible());
}

TEST_F(Studio, MouseStrokeInTheViewportCreatesARiggedPart) {
    window->activateTool<widgets::SketchTool>();
    const QPointF centre(viewport()->width() / 2.0, viewport()->height() / 2.0);
    // For people: the stroke half drawn, as the window shows it.
    const auto stroke = ellipseStroke(centre, 220, 60);
    test::sendMouse(viewport(), QEvent::MouseButtonPress, stroke.front(), Qt::LeftButton,
                    Qt::LeftButton);
    for (std::size_t i = 1; i < stroke.size() / 2; ++i)
        test::sendMouse(viewport(), QEvent::MouseMove, stroke[i], Qt::NoButton, Qt::LeftButton);
    QTest::qWait(50);
    window->grab().save(QStringLiteral(RIGMESH_TEST_OUTPUT "/studio_sketching.png"));
    for (std::size_t i = stroke.size() / 2; i < stroke.size(); ++i)
        test::sendMouse(viewport(), QEvent::MouseMove, stroke[i], Qt::NoButton, Qt::LeftButton);
    test::sendMouse(viewport(), QEvent::MouseButtonRelease, stroke.back(), Qt::LeftButton,
                    Qt::NoButton);
    test::waitForJobs();  // the part is built in the background
    ASSERT_EQ(document()->partCount(), 1);
    const model::PartNode& node = document()->parts().front();
    EXPECT_GT(node.part->mesh.vertexCount(), 100);
    EXPECT_GE(node.part->skeleton.boneCount(), 1);
    EXPECT_EQ(document()->undoStack()->count(), 1);
    // The outliner lists it.
    EXPECT_EQ(window->outliner()->view()->model()->rowCount(), 1);
}

TEST_F(Studio, CtrlZRemovesTheSketchedPartAndCtrlShiftZBringsItBack) {
    window->activateTool<widgets::SketchTool>();
    const QPointF centre(viewport()->width() / 2.0, viewport()->height() / 2.0);
    drag(viewport(), ellipseStroke(centre, 200, 70));
    ASSERT_EQ(document()->partCount(), 1);
    QTest::keyClick(window.get(), Qt::Key_Z, Qt::ControlModifier);
    EXPECT_EQ(document()->partCount(), 0);
    EXPECT_EQ(window->outliner()->view()->model()->rowCount(), 0);
    QTest::keyClick(window.get(), Qt::Key_Z, Qt::ControlModifier | Qt::ShiftModifier);
    EXPECT_EQ(document()->partCount(), 1);
}

TEST_F(Studio, TooShortStrokeChangesNothing) {
    window->activateTool<widgets::SketchTool>();
    drag(viewport(), {QPointF(100, 100), QPointF(102, 101), QPointF(103, 103)});
    EXPECT_EQ(document()->partCount(), 0);
    EXPECT_EQ(document()->undoStack()->count(), 0);
}

TEST_F(Studio, ClickInTheSketchToolDoesNothingAndSaysNothing) {
    window->activateTool<widgets::SketchTool>();
    window->statusBar()->clearMessage();
    drag(viewport(), {QPointF(200, 200), QPointF(200, 200)});
    EXPECT_EQ(document()->partCount(), 0);
    EXPECT_EQ(document()->undoStack()->count(), 0);
    EXPECT_FALSE(window->statusBar()->currentMessage().contains(QStringLiteral("too short")));
}

TEST_F(Studio, LargeCircleDrawnFastInFewEventsBecomesAPart) {
    window->activateTool<widgets::SketchTool>();
    const QPointF centre(viewport()->width() / 2.0, viewport()->height() / 2.0);
    // 13 mouse events around a circle of radius 150 px: a quick flick.
    drag(viewport(), ellipseStroke(centre, 150, 150, 13));
    EXPECT_EQ(document()->partCount(), 1) << window->statusBar()->currentMessage().toStdString();
}

TEST_F(Studio, WeightViewsColourTheSurfaceBySkinWeights) {
    const model::PartId biped = addExampleBiped();
    const Skeleton& skeleton = document()->part(biped).part->skeleton;
    const JointId hand = sidewaysHand(skeleton);
    document()->setSelection({biped, hand});
    auto count = [&](auto&& test) {
        const QImage image = viewport()->grabFramebuffer();
        int n = 0;
        for (int y = 0; y < image.height(); y += 2)
            for (int x = 0; x < image.width(); x += 2)
                n += test(QColor(image.pixel(x, y))) ? 1 : 0;
        return n;
    };
    auto red = [](const QColor& c) { return c.red() > 150 && c.green() < 90 && c.blue() < 90; };
    auto blue = [](const QColor& c) { return c.blue() > 120 && c.red() < 60 && c.green() < 90; };
    // Before the view is on, only the grid's red axis is red.
    const int redBefore = count(red);
    const int blueBefore = count(blue);
    viewport()->setWeightView(widgets::WeightView::SelectedBone);
    QTest::qWait(50);
    EXPECT_GT(count(red), redBefore + 50) << "the hand's bone leads its hand";
    EXPECT_GT(count(blue), blueBefore + 50) << "the rest of the body is cold or zero";
    window->grab().save(QStringLiteral(RIGMESH_TEST_OUTPUT "/studio_weights_bone.png"));
    // Hovering the hand lists its vertex's weights in the status bar.
    const Vec3 handAt = skeleton.joint(hand).position;
    const QVector3D p = viewport()->camera().project(
        QVector3D(float(handAt.x()), float(handAt.y()), float(handAt.z())),
        QSizeF(viewport()->size()));
    test::sendMouse(viewport(), QEvent::MouseMove, QPointF(p.x(), p.y()), Qt::NoButton,
                    Qt::NoButton);
    const QString status = window->statusBar()->currentMessage();
    EXPECT_TRUE(status.startsWith(QStringLiteral("Vertex ")) && status.contains("of biped: bone"))
        << status.toStdString();
    viewport()->setWeightView(widgets::WeightView::DominantBone);
    QTest::qWait(50);
    std::set<QRgb> colours;
    const QImage image = viewport()->grabFramebuffer();
    for (int y = 0; y < image.height(); y += 3)
        for (int x = 0; x < image.width(); x += 3)
            colours.insert(image.pixel(x, y) & 0xF0F0F0);
    EXPECT_GT(colours.size(), 20u);
    window->grab().save(QStringLiteral(RIGMESH_TEST_OUTPUT "/studio_weights_dominant.png"));
    viewport()->setWeightView(widgets::WeightView::Off);
}

// A brush stroke over the hand paints the selected bone's
// weights there only, keeps every sum at 1, is one undo step, and Esc in
// the middle of a stroke puts the weights back.
TEST_F(Studio, PaintingTheHandChangesItsWeightsInOneUndoStep) {
    const model::PartId biped = addExampleBiped();
    const Part& rest = *document()->part(biped).part;
    const JointId hand = sidewaysHand(rest.skeleton);
    // The bone ending at the shoulder: paint it onto the hand.
    JointId shoulder = kNoJoint;
    for (const Bone& bone : rest.skeleton.bones())
        if (bone.tail == hand)
            shoulder = bone.head;
    ASSERT_NE(shoulder, kNoJoint);
    document()->setSelection({biped, shoulder});
    window->activateTool<widgets::PaintTool>();
    QTest::qWait(50);
    const QByteArray before = model::DocumentFile::toBytes(*document());
    const int steps = document()->undoStack()->count();
    const Vec3 h = rest.skeleton.joint(hand).position;
    const QVector3D p = viewport()->camera().project(QVector3D(float(h.x()), float(h.y()), 0.2f),
                                                     QSizeF(viewport()->size()));
    // From the hand towards the body, on the arm.
    const double inward = h.x() < 0.0 ? 1.0 : -1.0;
    std::vector<QPointF> stroke;
    for (int i = 0; i <= 12; ++i)
        stroke.emplace_back(p.x() + inward * 5 * i, p.y());
    ASSERT_TRUE(viewport()->surfaceAt(stroke.front()).has_value());
    drag(viewport(), stroke);
    EXPECT_EQ(document()->undoStack()->count(), steps + 1)
        << "a stroke is one undo step: " << window->statusBar()->currentMessage().toStdString();
    const Part& painted = *document()->part(biped).part;
    EXPECT_TRUE(painted.validate().empty());
    EXPECT_NE(painted.weights.perVertex, rest.weights.perVertex);
    // Far from the hand (the other side of the body) nothing changed.
    for (int v = 0; v < painted.mesh.vertexCount(); ++v)
        if (painted.mesh.vertices[v].x() * h.x() < 0.0) {
            ASSERT_EQ(painted.weights.perVertex[v], rest.weights.perVertex[v]) << v;
        }
    QTest::qWait(50);
    window->grab().save(QStringLiteral(RIGMESH_TEST_OUTPUT "/studio_paint.png"));
    QTest::keyClick(window.get(), Qt::Key_Z, Qt::ControlModifier);
    EXPECT_EQ(model::DocumentFile::toBytes(*document()), before);
    // Esc in the middle of a stroke puts the weights back.
    viewport()->setFocus(Qt::MouseFocusReason);
    test::sendMouse(viewport(), QEvent::MouseButtonPress, stroke.front(), Qt::LeftButton,
                    Qt::LeftButton);
    for (const QPointF& point : stroke)
        test::sendMouse(viewport(), QEvent::MouseMove, point, Qt::NoButton, Qt::LeftButton);
    QTest::keyClick(viewport(), Qt::Key_Escape);
    test::sendMouse(viewport(), QEvent::MouseButtonRelease, stroke.back(), Qt::LeftButton,
                    Qt::NoButton);
    EXPECT_EQ(model::DocumentFile::toBytes(*document()), before);
    EXPECT_EQ(document()->undoStack()->count(), steps + 1);  // the undone stroke, redoable

    // Tools > Weights > Limit Total keeps at most four bones per vertex.
    QAction* limit = nullptr;
    for (QAction* action : window->findChildren<QAction*>())
        if (action->text() == QStringLiteral("&Limit Total (4 bones)"))
            limit = action;
    ASSERT_NE(limit, nullptr);
    limit->trigger();
    for (const auto& list : document()->part(biped).part->weights.perVertex)
        EXPECT_LE(list.size(), 4u);
    EXPECT_TRUE(document()->part(biped).part->validate().empty());
}

TEST_F(Studio, DraggingAPartMovesItAndCtrlDragTurnsIt) {
    window->activateTool<widgets::SketchTool>();
    const QPointF centre(viewport()->width() / 2.0, viewport()->height() / 2.0);
    drag(viewport(), ellipseStroke(centre, 220, 60));
    ASSERT_EQ(document()->partCount(), 1);
    const model::PartId id = document()->parts().front().id;
    const model::Placement before = document()->part(id).placement;
    window->activateTool<widgets::SelectTool>();
    QTest::qWait(50);  // the first paint frames the new part
    // A pixel on the surface but away from every joint.
    QPointF grab;
    bool found = false;
    for (double dy = 10; dy < 200 && !found; dy += 5) {
        grab = QPointF(centre.x() + 30, centre.y() + dy);
        found = viewport()->partAt(grab).has_value() && !viewport()->jointAt(grab).has_value();
    }
    ASSERT_TRUE(found);
    std::vector<QPointF> path;
    for (int i = 0; i <= 10; ++i)
        path.emplace_back(grab.x() + 5.0 * i, grab.y());
    drag(viewport(), path);
    const model::Placement moved = document()->part(id).placement;
    EXPECT_GT((moved.translation - before.translation).norm(), 0.0);
    const int steps = document()->undoStack()->count();
    // Ctrl + drag from a point on the part sweeps around its centre.
    std::vector<QPointF> arc;
    for (int i = 0; i <= 10; ++i) {
        const double a = 0.05 * i;
        arc.emplace_back(grab.x() + 50 + 50 * std::cos(a), grab.y() - 50 * std::sin(a));
    }
    drag(viewport(), arc, Qt::ControlModifier);
    const model::Placement turned = document()->part(id).placement;
    EXPECT_GT(turned.rotation.angularDistance(moved.rotation), 0.1);
    EXPECT_EQ(document()->undoStack()->count(), steps + 1) << "a drag is one undo step";
    // Another plain drag of the same part is another step; undo takes back
    // only that one.
    drag(viewport(), path);
    EXPECT_EQ(document()->undoStack()->count(), steps + 2) << "two drags, two undo steps";
    QTest::keyClick(window.get(), Qt::Key_Z, Qt::ControlModifier);
    EXPECT_EQ(document()->part(id).placement, turned);
    QTest::keyClick(window.get(), Qt::Key_Z, Qt::ControlModifier);
    EXPECT_EQ(document()->part(id).placement, moved);
}

TEST_F(Studio, UnriggedImportedMeshIsDrawnAndCannotBePosed) {
    window->activateTool<widgets::SketchTool>();
    const QPointF centre(viewport()->width() / 2.0, viewport()->height() / 2.0);
    drag(viewport(), ellipseStroke(centre, 220, 60));
    ASSERT_EQ(document()->partCount(), 1);
    const QString obj = recovery.filePath(QStringLiteral("static.obj"));
    model::exportDocument(*document(), obj.toStdString());
    document()->undoStack()->push(model::ImportPartsCommand::create(*document(), obj).release());
    ASSERT_EQ(document()->partCount(), 2);
    viewport()->frameAll();
    QTest::qWait(50);  // paints both parts; the unrigged one at rest
    const QImage frame = viewport()->grabFramebuffer();
    EXPECT_FALSE(frame.isNull());
    window->activateTool<widgets::PoseTool>();
    document()->setSelection({document()->parts().back().id, kNoJoint});
    QTest::keyClick(window.get(), Qt::Key_R, Qt::AltModifier);  // reset pose: nothing to do
    EXPECT_EQ(document()->partCount(), 2);
}

TEST_F(Studio, SavedDocumentReopensWithTheSameContent) {
    window->activateTool<widgets::SketchTool>();
    const QPointF centre(viewport()->width() / 2.0, viewport()->height() / 2.0);
    drag(viewport(), ellipseStroke(centre, 220, 60));
    ASSERT_EQ(document()->partCount(), 1);
    const QString path = recovery.filePath(QStringLiteral("saved.rigmesh"));
    model::DocumentFile::save(*document(), path);
    const QByteArray saved = model::DocumentFile::toBytes(*document());
    EXPECT_FALSE(document()->isModified());
    ASSERT_TRUE(window->closeDocument(window->tabs()->currentIndex()));
    ASSERT_TRUE(window->files()->openFile(path));
    EXPECT_EQ(model::DocumentFile::toBytes(*document()), saved);
}

}  // namespace
}  // namespace rigmesh
