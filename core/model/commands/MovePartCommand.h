// Move and/or rotate a part. Consecutive moves of the same part (recipe
// steps, scripted moves) merge into one undo step (id() + mergeWith); a merge
// that lands back where it started makes the command obsolete.
//
// Interactive drags preview the placement live and push the command once, on
// release (model/preview/PlacementPreview.h), with CommandMerging::Never: a
// whole drag never merges (id() is -1), so two drags are two undo steps.
#pragma once

#include <QCoreApplication>
#include <QUndoCommand>

#include "model/Document.h"
#include "model/commands/CommandIds.h"
#include "model/recipe/RecipeStepSource.h"

namespace rigmesh::model {

class MovePartCommand : public QUndoCommand, public RecipeStepSource {
    Q_DECLARE_TR_FUNCTIONS(MovePartCommand)
  public:
    // Throws rigmesh::Error on an unknown id. `from` is the placement before
    // the move (the part's current one unless a preview shows the move).
    MovePartCommand(Document& document, PartId id, const Placement& from, const Placement& to,
                    CommandMerging merging = CommandMerging::Consecutive,
                    QUndoCommand* parent = nullptr);
    // From the part's current placement.
    MovePartCommand(Document& document, PartId id, const Placement& to,
                    QUndoCommand* parent = nullptr);

    void redo() override;
    void undo() override;
    nlohmann::json recipeStep() const override;
    int id() const override { return merging_ == CommandMerging::Never ? -1 : MovePartCommandId; }
    bool mergeWith(const QUndoCommand* other) override;

    PartId partId() const { return id_; }

  private:
    Document& document_;
    PartId id_;
    int index_;
    Placement from_, to_;
    CommandMerging merging_;
};

}  // namespace rigmesh::model
