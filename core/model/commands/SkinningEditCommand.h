// The common ground of commands that change only a part's skin weights or
// bone locks (paint strokes, weight clean-ups, bone locks): the
// engine edit runs on a copy in the factory (a bad argument throws
// rigmesh::Error and nothing changes), redo and undo swap the part through
// Document::replaceSkinning, so the pose, pins and keys stay as they are and
// undo gives the weights back exactly.
#pragma once

#include <QUndoCommand>
#include <memory>
#include <nlohmann/json.hpp>

#include "base/Message.h"
#include "model/Document.h"
#include "model/recipe/RecipeStepSource.h"

namespace rigmesh::model {

class SkinningEditCommand : public QUndoCommand, public RecipeStepSource {
  public:
    void redo() override;
    void undo() override;
    nlohmann::json recipeStep() const override { return step_; }
    // How many vertices' weights the edit changed.
    int changedVertices() const { return changed_; }

  protected:
    // Throws rigmesh::Error for an unknown part or one without a skeleton
    // (`noSkeleton`: the message for a part without a skeleton).
    SkinningEditCommand(Document& document, PartId part, MessageId noSkeleton);
    // A copy of the part as the command found it, to edit.
    std::shared_ptr<Part> editableCopy() const { return std::make_shared<Part>(*before_); }
    // The edited part, the step that replays it and the changed vertex count.
    void setResult(std::shared_ptr<const Part> after, nlohmann::json step, int changed);
    const Part& before() const { return *before_; }
    int partIndex() const { return index_; }
    const QString& partName() const { return name_; }

  private:
    Document& document_;
    PartId id_;
    int index_;
    QString name_;
    std::shared_ptr<const Part> before_, after_;
    nlohmann::json step_;
    int changed_ = 0;
};

}  // namespace rigmesh::model
