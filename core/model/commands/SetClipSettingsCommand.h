// Set a part's clip frame rate, interpolation and playback mode at once (the
// keys stay at their times).
#pragma once

#include <QCoreApplication>

#include "model/commands/ClipCommand.h"

namespace rigmesh::model {

class SetClipSettingsCommand : public ClipCommand {
    Q_DECLARE_TR_FUNCTIONS(SetClipSettingsCommand)
  public:
    // Throws rigmesh::Error on an unknown id or a frame rate that is not a
    // positive number.
    SetClipSettingsCommand(Document& document, PartId id, double framesPerSecond,
                           rigmesh::Interpolation interpolation, rigmesh::PlaybackMode playback,
                           QUndoCommand* parent = nullptr);

    nlohmann::json recipeStep() const override;
};

}  // namespace rigmesh::model
