// Merging, cutting and editing bones in the studio by mouse: a
// dragged leg merges into the body in one undo step, Esc puts it
// back, a line cuts a part, K and Shift+K split and delete bones.
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
#include "StudioMergeFixture.h"
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
using widgettest::StudioMerge;

TEST_F(StudioMerge, DraggingALegIntoTheBodyMergesThemInOneUndoStep) {
    ASSERT_EQ(document()->partCount(), 2);
    ASSERT_TRUE(viewport()->partAt(onTheLeg()).has_value());
    const QByteArray before = model::DocumentFile::toBytes(*document());
    const int steps = document()->undoStack()->count();
    drag(viewport(), shortDrag());
    QMenu* menu = choices();
    ASSERT_NE(menu, nullptr) << "a plain release offers snap, split and connect";
    QTest::keyClick(menu, Qt::Key_Return);  // Snap, the default item
    rigmesh::test::waitForJobs();           // the merge runs in the background
    ASSERT_EQ(document()->partCount(), 1) << window->statusBar()->currentMessage().toStdString();
    EXPECT_EQ(document()->undoStack()->count(), steps + 1);
    EXPECT_TRUE(document()->parts()[0].part->validateSolid().empty());
    EXPECT_TRUE(window->statusBar()->currentMessage().contains(QStringLiteral("merged in")))
        << window->statusBar()->currentMessage().toStdString();
    QTest::qWait(50);
    window->grab().save(QStringLiteral(RIGMESH_TEST_OUTPUT "/studio_merged.png"));
    // The paper's Fig. 9a view: where the local re-skin differs from a
    // global one (near the seam, warmer than the untouched blue).
    viewport()->setWeightView(widgets::WeightView::GlobalDifference);
    rigmesh::test::waitForGlobalDifferences(viewport());
    const QImage difference = viewport()->grabFramebuffer();
    int warm = 0, cold = 0;
    for (int y = 0; y < difference.height(); y += 2)
        for (int x = 0; x < difference.width(); x += 2) {
            const QColor c(difference.pixel(x, y));
            warm += c.green() > 120 && c.blue() < 200 ? 1 : 0;
            cold += c.blue() > 120 && c.green() < 60 && c.red() < 60 ? 1 : 0;
        }
    EXPECT_GT(cold, warm) << "most of the part is as the global computation";
    window->grab().save(QStringLiteral(RIGMESH_TEST_OUTPUT "/studio_weights_difference.png"));
    viewport()->setWeightView(widgets::WeightView::Off);
    QTest::keyClick(window.get(), Qt::Key_Z, Qt::ControlModifier);
    EXPECT_EQ(model::DocumentFile::toBytes(*document()), before);
}

TEST_F(StudioMerge, EscapeDuringTheDragPutsThePartBackAndMergesNothing) {
    const model::PartId leg = document()->parts()[1].id;
    const model::Placement start = document()->part(leg).placement;
    const int steps = document()->undoStack()->count();
    const std::vector<QPointF> path = shortDrag();
    viewport()->setFocus(Qt::MouseFocusReason);
    test::sendMouse(viewport(), QEvent::MouseButtonPress, path.front(), Qt::LeftButton,
                    Qt::LeftButton);
    for (const QPointF& p : path)
        test::sendMouse(viewport(), QEvent::MouseMove, p, Qt::NoButton, Qt::LeftButton);
    EXPECT_FALSE(document()->part(leg).placement == start);  // the live preview
    QTest::qWait(50);
    window->grab().save(QStringLiteral(RIGMESH_TEST_OUTPUT "/studio_merge_drag.png"));
    QTest::keyClick(viewport(), Qt::Key_Escape);
    EXPECT_EQ(document()->part(leg).placement, start);
    test::sendMouse(viewport(), QEvent::MouseButtonRelease, path.back(), Qt::LeftButton,
                    Qt::NoButton);
    EXPECT_EQ(document()->partCount(), 2);
    EXPECT_EQ(document()->undoStack()->count(), steps);
}

// The pixel of a document point.
QPointF pixelOf(const widgets::Viewport& viewport, const Vec3& point) {
    const QVector3D p = viewport.camera().project(
        QVector3D(float(point.x()), float(point.y()), float(point.z())), QSizeF(viewport.size()));
    return {p.x(), p.y()};
}

TEST_F(StudioMerge, ALineAcrossThePartCutsItInTwoInOneUndoStep) {
    window->activateTool<widgets::CutTool>();
    const QByteArray before = model::DocumentFile::toBytes(*document());
    // Across the body's back half, from above it to below it.
    const QPointF top = pixelOf(*viewport(), Vec3(-1.2, 1.6, 0.0));
    const QPointF bottom = pixelOf(*viewport(), Vec3(-1.1, -1.6, 0.0));
    ASSERT_FALSE(viewport()->partAt(top).has_value());
    ASSERT_FALSE(viewport()->partAt(bottom).has_value());
    drag(viewport(), {top, (top + bottom) / 2, bottom});
    ASSERT_EQ(document()->partCount(), 3) << window->statusBar()->currentMessage().toStdString();
    for (const model::PartNode& node : document()->parts())
        EXPECT_TRUE(node.part->validateSolid().empty());
    QTest::qWait(50);
    window->grab().save(QStringLiteral(RIGMESH_TEST_OUTPUT "/studio_cut.png"));
    QTest::keyClick(window.get(), Qt::Key_Z, Qt::ControlModifier);
    EXPECT_EQ(model::DocumentFile::toBytes(*document()), before);
    // A line that starts on the part cuts nothing and says why.
    drag(viewport(), {pixelOf(*viewport(), Vec3(-1.2, 0.0, 0.0)), bottom});
    EXPECT_EQ(document()->partCount(), 2);
    EXPECT_TRUE(window->statusBar()->currentMessage().contains(QStringLiteral("Nothing cut")));
}

TEST_F(StudioMerge, KSplitsTheBoneUnderTheCursorAndShiftKDeletesIt) {
    const model::PartId leg = document()->parts()[1].id;
    ASSERT_EQ(document()->part(leg).part->skeleton.boneCount(), 1);
    viewport()->setFocus(Qt::MouseFocusReason);
    const QPointF knee = pixelOf(*viewport(), Vec3(1.7, -2.0, 0.3));
    QCursor::setPos(viewport()->mapToGlobal(knee.toPoint()));
    QTest::qWait(20);
    QTest::keyClick(viewport(), Qt::Key_K);
    ASSERT_EQ(document()->part(leg).part->skeleton.boneCount(), 2)
        << window->statusBar()->currentMessage().toStdString();
    EXPECT_TRUE(document()->part(leg).part->validateSolid().empty());
    QCursor::setPos(viewport()->mapToGlobal(pixelOf(*viewport(), Vec3(1.7, -3.0, 0.3)).toPoint()));
    QTest::qWait(20);
    QTest::keyClick(viewport(), Qt::Key_K, Qt::ShiftModifier);
    EXPECT_EQ(document()->part(leg).part->skeleton.boneCount(), 1);
    QTest::keyClick(window.get(), Qt::Key_Z, Qt::ControlModifier);
    EXPECT_EQ(document()->part(leg).part->skeleton.boneCount(), 2);
}

}  // namespace
}  // namespace rigmesh
