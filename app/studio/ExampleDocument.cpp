#include "ExampleDocument.h"

#include <QCoreApplication>

#include "EmbeddedExamples.h"
#include "model/commands/CreatePartCommand.h"
#include "model/commands/WeightCleanupCommand.h"
#include "sketch/Sketch.h"

namespace rigmesh::studio {

std::unique_ptr<model::Document> makeExampleDocument() {
    auto document = std::make_unique<model::Document>();
    const Sketch sketch = parseSketchJson(resources::exampleSketchJson(), "example.json");
    // The sketch's own units, centred at the origin: the part faces the front view.
    Eigen::AlignedBox2d box;
    for (const Vec2& p : sketch.points)
        box.extend(p);
    model::Placement placement;
    placement.translation = Vec3(-box.center().x(), -box.center().y(), 0.0);
    auto command = model::CreatePartCommand::create(
        *document, sketch.points, QString::fromStdString(sketch.name), {}, placement);
    const model::PartId id = command->partId();
    document->undoStack()->push(command.release());
    // Its weights are a fresh global solve (Tools > Weights > Recompute
    // Weights), so Difference from Global Weights, the first view a newcomer
    // tries, shows none: the sketch's construction shortcut (paper 2.4)
    // differs at the shoulders and the crotch.
    document->undoStack()->push(model::WeightCleanupCommand::recompute(*document, id).release());
    // An example is a starting point, not an edit: no history, not modified.
    document->undoStack()->clear();
    document->undoStack()->setClean();
    document->setUntitledName(QCoreApplication::translate("rigmesh::studio", "Example: %1")
                                  .arg(QString::fromStdString(sketch.name)));
    return document;
}

}  // namespace rigmesh::studio
