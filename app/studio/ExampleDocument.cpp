#include "ExampleDocument.h"

#include <QCoreApplication>
#include <QPointer>

#include "DocumentView.h"
#include "EmbeddedExamples.h"
#include "MainWindow.h"
#include "jobs/JobRunner.h"
#include "model/GuardedUndo.h"
#include "model/commands/CreatePartCommand.h"
#include "model/commands/WeightCleanupCommand.h"
#include "sketch/Sketch.h"
#include "viewport/Viewport.h"

namespace rigmesh::studio {

namespace {

Sketch exampleSketch() {
    return parseSketchJson(resources::exampleSketchJson(), "example.json");
}

}  // namespace

ExamplePart buildExamplePart() {
    const Sketch sketch = exampleSketch();
    ExamplePart example;
    example.stroke = sketch.points;
    example.name = QString::fromStdString(sketch.name);
    // The sketch's own units, centred at the origin: the part faces the
    // front view.
    Eigen::AlignedBox2d box;
    for (const Vec2& p : sketch.points)
        box.extend(p);
    example.placement.translation = Vec3(-box.center().x(), -box.center().y(), 0.0);
    // The first part of a document: its own edge length, as a new sketch.
    example.built = model::buildPartAtDocumentLength(0.0, example.stroke, example.name, {});
    // Its weights are a fresh global solve (Tools > Weights > Recompute
    // Weights), so Difference from Global Weights, the first view a
    // newcomer tries, shows none: the sketch's construction shortcut (paper
    // 2.4) differs at the shoulders and the crotch.
    example.built.part = model::WeightCleanupCommand::recomputed(example.built.part).to;
    return example;
}

std::unique_ptr<model::Document> makeEmptyExampleDocument() {
    auto document = std::make_unique<model::Document>();
    document->setUntitledName(QCoreApplication::translate("rigmesh::studio", "Example: %1")
                                  .arg(QString::fromStdString(exampleSketch().name)));
    return document;
}

void addExamplePart(model::Document& document, ExamplePart part) {
    model::pushCommand(
        document, model::CreatePartCommand::fromBuilt(document, std::move(part.stroke), part.name,
                                                      std::move(part.built), part.placement));
    // An example is a starting point, not an edit: no history, not modified.
    document.undoStack()->clear();
    document.undoStack()->setClean();
}

std::unique_ptr<model::Document> makeExampleDocument() {
    std::unique_ptr<model::Document> document = makeEmptyExampleDocument();
    addExamplePart(*document, buildExamplePart());
    return document;
}

void openExample(widgets::MainWindow& window) {
    QPointer<widgets::DocumentView> view = window.addDocument(makeEmptyExampleDocument());
    window.jobs()->run(
        QCoreApplication::translate("rigmesh::studio", "Building the example"),
        [view]() -> widgets::JobRunner::Apply {
            auto part = std::make_shared<ExamplePart>(buildExamplePart());
            return [view, part] {
                if (!view || view->document()->partCount() > 0)
                    return;
                addExamplePart(*view->document(), std::move(*part));
                // Opened with a part: framed once, as a document opened from
                // a file is.
                view->viewport()->frameAll();
            };
        },
        [&window](const QString& reason) {
            window.showStatus(
                QCoreApplication::translate("rigmesh::studio", "The example was not built: %1")
                    .arg(reason),
                8000);
        });
}

}  // namespace rigmesh::studio
