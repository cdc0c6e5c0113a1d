// A whole-part weight clean-up (Normalize All, Clean, Limit Total; issue 14
// item 3) as one undoable step; the recipe steps normalize_weights,
// clean_weights and limit_weights. The engine runs in the factory, so a bad
// argument throws rigmesh::Error and changes nothing.
#pragma once

#include <QCoreApplication>
#include <QUndoCommand>
#include <memory>
#include <nlohmann/json.hpp>

#include "model/Document.h"
#include "model/recipe/RecipeStepSource.h"

namespace rigmesh::model {

class WeightCleanupCommand : public QUndoCommand, public RecipeStepSource {
    Q_DECLARE_TR_FUNCTIONS(WeightCleanupCommand)
  public:
    static std::unique_ptr<WeightCleanupCommand> normalizeAll(Document& document, PartId part);
    static std::unique_ptr<WeightCleanupCommand> clean(Document& document, PartId part,
                                                       double threshold);
    static std::unique_ptr<WeightCleanupCommand> limitTotal(Document& document, PartId part,
                                                            int influences);

    void redo() override;
    void undo() override;
    nlohmann::json recipeStep() const override;
    int changedVertices() const { return changed_; }

  private:
    WeightCleanupCommand(Document& document, PartId part);

    Document& document_;
    PartId id_;
    int index_;
    nlohmann::json step_;
    std::shared_ptr<const Part> before_, after_;
    int changed_ = 0;
};

}  // namespace rigmesh::model
