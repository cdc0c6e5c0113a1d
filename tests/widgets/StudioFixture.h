// A studio window with one new document, for tests that drive it like a
// person (StudioTestSupport.h has the mouse helpers).
#pragma once

#include <gtest/gtest.h>

#include <QAction>
#include <QMenu>
#include <QMenuBar>
#include <QTemporaryDir>
#include <QUndoStack>
#include <memory>

#include "DocumentView.h"
#include "EmbeddedExamples.h"
#include "MainWindow.h"
#include "StudioTestSupport.h"
#include "SymmetricOutline.h"
#include "model/Document.h"
#include "model/commands/CreatePartCommand.h"
#include "sketch/Sketch.h"
// The controllers and every tool (for activateTool<T>(), MainWindow.h).
#include "controllers/ExchangeController.h"
#include "controllers/FilesController.h"
#include "controllers/RigController.h"
#include "controllers/WeightsController.h"
#include "tools/CutTool.h"
#include "tools/MergeTool.h"
#include "tools/PaintTool.h"
#include "tools/PoseTool.h"
#include "tools/SelectTool.h"
#include "tools/SketchTool.h"

namespace rigmesh::test {

class StudioFixture : public testing::Test {
  protected:
    void SetUp() override {
        ASSERT_TRUE(recovery.isValid());
        window = std::make_unique<widgets::MainWindow>(recovery.path());
        window->resize(1200, 800);
        window->newDocument();
        settle(window.get());
    }
    widgets::Viewport* viewport() const { return window->currentView()->viewport(); }
    model::Document* document() const { return window->currentDocument(); }
    // The example biped as a part, framed: its id.
    model::PartId addExampleBiped() {
        const Sketch sketch = parseSketchJson(resources::exampleSketchJson(), "example.json");
        document()->undoStack()->push(
            model::CreatePartCommand::create(*document(), sketch.points, "biped").release());
        viewport()->frameAll();
        return document()->parts().back().id;
    }
    // The example biped made exactly symmetric (its outline mirrored about
    // its axis), as the only part: X-mirror finds every bone's image.
    model::PartId addSymmetricExampleBiped() {
        addExampleBiped();
        const std::vector<Vec2> outline =
            testsupport::symmetricOutline(document()->parts().back().part->outline);
        document()->undoStack()->undo();
        document()->undoStack()->push(
            model::CreatePartCommand::create(*document(), outline, "biped").release());
        viewport()->frameAll();
        return document()->parts().front().id;
    }
    // Where a point of the part's rest shape (at its placement) is on screen.
    QPointF onScreen(const Vec3& p) const {
        const QVector3D s = viewport()->camera().project(
            QVector3D(float(p.x()), float(p.y()), float(p.z())), QSizeF(viewport()->size()));
        return {s.x(), s.y()};
    }

    // The menu bar's action `text` of the menu `menu` (as written, with its
    // '&'), or null.
    QAction* menuAction(const QString& menu, const QString& text) const {
        for (QAction* top : window->menuBar()->actions())
            if (top->text() == menu && top->menu())
                for (QAction* action : top->menu()->actions())
                    if (action->text() == text)
                        return action;
        return nullptr;
    }

    QTemporaryDir recovery;
    std::unique_ptr<widgets::MainWindow> window;
};

}  // namespace rigmesh::test
