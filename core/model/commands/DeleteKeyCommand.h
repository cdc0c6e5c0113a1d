// Delete the key of a part's clip at a time (within half a frame).
#pragma once

#include <QCoreApplication>

#include "model/commands/ClipCommand.h"

namespace rigmesh::model {

class DeleteKeyCommand : public ClipCommand {
    Q_DECLARE_TR_FUNCTIONS(DeleteKeyCommand)
  public:
    // Throws rigmesh::Error on an unknown id or when there is no key there.
    DeleteKeyCommand(Document& document, PartId id, double time, QUndoCommand* parent = nullptr);

    nlohmann::json recipeStep() const override;

  private:
    double time_;
};

}  // namespace rigmesh::model
