#include "ExampleDocument.h"

#include <QCoreApplication>

#include "EmbeddedExamples.h"
#include "model/commands/CreatePartCommand.h"
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
    document->undoStack()->push(command.release());
    // An example is a starting point, not an edit: no history, not modified.
    document->undoStack()->clear();
    document->undoStack()->setClean();
    document->setUntitledName(QCoreApplication::translate("rigmesh::studio", "Example: %1")
                                  .arg(QString::fromStdString(sketch.name)));
    return document;
}

}  // namespace rigmesh::studio
