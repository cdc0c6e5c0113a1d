// The studio with the camel body and a leg overlapping its front (the camel
// recipe's placement), Merge tool active: the fixture of the merge, cut and
// bone-edit tests.
#pragma once

#include <gtest/gtest.h>

#include <QMenu>
#include <string>
#include <vector>

#include "StudioFixture.h"
#include "tools/MergeTool.h"

namespace rigmesh::widgettest {

class StudioMerge : public test::StudioFixture {
  protected:
    void SetUp() override {
        StudioFixture::SetUp();
        model::Document& d = *window->currentDocument();
        const std::string dir = RIGMESH_SHARED_SKETCHES;
        d.undoStack()->push(model::CreatePartCommand::create(
                                d, readSketchFile(dir + "/camel_body.json").points, "body")
                                .release());
        model::Placement legPlace;
        legPlace.translation = Vec3(1.7, -0.55, 0.3);
        d.undoStack()->push(
            model::CreatePartCommand::create(d, readSketchFile(dir + "/camel_leg.json").points,
                                             "leg", {}, legPlace)
                .release());
        viewport()->frameAll();
        window->activateTool<widgets::MergeTool>();
        QTest::qWait(50);
    }
    // A pixel on the leg's lower half, far from the body.
    QPointF onTheLeg() const {
        const QVector3D p =
            viewport()->camera().project(QVector3D(1.7f, -2.6f, 0.3f), QSizeF(viewport()->size()));
        return {p.x(), p.y()};
    }
    widgets::MergeTool* mergeTool() const {
        return dynamic_cast<widgets::MergeTool*>(viewport()->tool());
    }
    // The Snap / Split / Connect menu a plain release opens, once it shows.
    QMenu* choices() const {
        QMenu* menu = mergeTool() ? mergeTool()->choices() : nullptr;
        if (menu && !QTest::qWaitForWindowExposed(menu))
            QTest::qWait(100);
        return menu;
    }
    std::vector<QPointF> shortDrag() const {
        std::vector<QPointF> path;
        for (int i = 0; i <= 6; ++i)
            path.emplace_back(onTheLeg().x() + i, onTheLeg().y() - i);
        return path;
    }
};

}  // namespace rigmesh::widgettest
