// The example document the studio opens with: the biped built from the
// sketch compiled into the binary, its weights a fresh global solve, as a
// clean document with an empty history. The build and the solve take about
// a second, so the studio does them on its worker thread: the document
// shows at once and its part arrives when built.
#pragma once

#include <QString>
#include <memory>
#include <vector>

#include "model/Document.h"
#include "model/PartBuilder.h"

namespace rigmesh::widgets {
class MainWindow;
}

namespace rigmesh::studio {

// The example's part, built and solved, not yet in a document.
struct ExamplePart {
    std::vector<Vec2> stroke;
    QString name;
    model::BuiltPart built;
    model::Placement placement;
};

// The build: touches no document, so it may run on any thread.
ExamplePart buildExamplePart();
// The document as it shows before its part arrives: empty, titled
// "Example: <name>".
std::unique_ptr<model::Document> makeEmptyExampleDocument();
// Puts the part into the example document as if it was opened with it: no
// history, not modified.
void addExamplePart(model::Document& document, ExamplePart part);
// Both on the calling thread (tests).
std::unique_ptr<model::Document> makeExampleDocument();
// Opens the example in `window`: the document at once, its part built on
// the window's job runner and framed in the view when it arrives.
void openExample(widgets::MainWindow& window);

}  // namespace rigmesh::studio
