// Key a part's current pose in its clip at a time (seconds): a key within
// half a frame of the time is replaced (Clip::setKey), otherwise one is added.
#pragma once

#include <QCoreApplication>

#include "model/commands/ClipCommand.h"

namespace rigmesh::model {

class KeyPoseCommand : public ClipCommand {
    Q_DECLARE_TR_FUNCTIONS(KeyPoseCommand)
  public:
    // Throws rigmesh::Error on an unknown id or a non-finite time.
    KeyPoseCommand(Document& document, PartId id, double time, QUndoCommand* parent = nullptr);

    nlohmann::json recipeStep() const override;
    double time() const { return time_; }

  private:
    double time_;
};

}  // namespace rigmesh::model
