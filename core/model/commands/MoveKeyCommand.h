// Move the key of a part's clip at one time to another, replacing a key
// there (Clip::moveKey).
#pragma once

#include <QCoreApplication>

#include "model/commands/ClipCommand.h"

namespace rigmesh::model {

class MoveKeyCommand : public ClipCommand {
    Q_DECLARE_TR_FUNCTIONS(MoveKeyCommand)
  public:
    // Throws rigmesh::Error on an unknown id, a non-finite time or when there
    // is no key at `from`.
    MoveKeyCommand(Document& document, PartId id, double from, double to,
                   QUndoCommand* parent = nullptr);

    nlohmann::json recipeStep() const override;

  private:
    double from_, to_;
};

}  // namespace rigmesh::model
