// Create a part from a sketch. Use create(): the engine build runs there,
// before anything is pushed, so a bad stroke throws rigmesh::Error and the
// document and its undo stack stay as they were.
#pragma once

#include <QCoreApplication>
#include <QUndoCommand>
#include <memory>
#include <vector>

#include "model/Document.h"
#include "model/PartBuilder.h"
#include "model/recipe/RecipeStepSource.h"

namespace rigmesh::model {

class CreatePartCommand : public QUndoCommand, public RecipeStepSource {
    Q_DECLARE_TR_FUNCTIONS(CreatePartCommand)
  public:
    // Builds the part (throws rigmesh::Error on a bad stroke) and returns the
    // command, ready to push; the new part is appended and gets a fresh id.
    // An empty name becomes "Part <id>".
    static std::unique_ptr<CreatePartCommand> create(Document& document, std::vector<Vec2> stroke,
                                                     const QString& name = {},
                                                     const BuildOptions& options = {},
                                                     const Placement& placement = {});

    // The command for a part already built (buildPartAtDocumentLength, e.g.
    // by a background job); `built.options` are recorded.
    static std::unique_ptr<CreatePartCommand> fromBuilt(Document& document,
                                                        std::vector<Vec2> stroke,
                                                        const QString& name, BuiltPart built,
                                                        const Placement& placement = {});

    // The node such a command inserts, without its id: the built part at
    // `placement` in its rest pose, named `name` (not empty). A sketch's live
    // preview (model/preview/SketchPreview.h) shows the same node.
    static PartNode nodeFromBuilt(const QString& name, std::vector<Vec2> stroke, BuiltPart built,
                                  const Placement& placement);

    void redo() override;
    void undo() override;
    nlohmann::json recipeStep() const override;
    PartId partId() const { return node_.id; }

  private:
    CreatePartCommand(Document& document, PartNode node);

    Document& document_;
    PartNode node_;
};

}  // namespace rigmesh::model
