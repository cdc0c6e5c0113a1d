// One weight paint dab (issue 14 item 3) as an undoable step: the engine dab
// (part/WeightPaint.h) runs in create(), so a refused dab (locked or unknown
// bone, bad brush) throws rigmesh::Error and changes nothing. Undo gives the
// part's weights back exactly. The recipe step is "paint_weights".
#pragma once

#include <QCoreApplication>
#include <QUndoCommand>
#include <memory>

#include "model/Document.h"
#include "model/recipe/RecipeStepSource.h"
#include "part/WeightPaint.h"

namespace rigmesh::model {

class PaintWeightsCommand : public QUndoCommand, public RecipeStepSource {
    Q_DECLARE_TR_FUNCTIONS(PaintWeightsCommand)
  public:
    // `dab.centre` is in document coordinates.
    static std::unique_ptr<PaintWeightsCommand> create(Document& document, PartId part,
                                                       const WeightDab& dab);

    void redo() override;
    void undo() override;
    nlohmann::json recipeStep() const override;
    int changedVertices() const { return changed_; }
    int skippedVertices() const { return skipped_; }

  private:
    PaintWeightsCommand(Document& document, PartId part, const WeightDab& dab);

    Document& document_;
    PartId id_;
    int index_;
    WeightDab dab_;  // centre in document coordinates
    std::shared_ptr<const Part> before_, after_;
    int changed_ = 0, skipped_ = 0;
};

}  // namespace rigmesh::model
