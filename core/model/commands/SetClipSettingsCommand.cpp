#include "model/commands/SetClipSettingsCommand.h"

#include <nlohmann/json.hpp>

#include "model/ClipModes.h"

namespace rigmesh::model {

namespace {

rigmesh::Clip withSettings(const PartNode& node, double framesPerSecond,
                           rigmesh::Interpolation interpolation, rigmesh::PlaybackMode playback) {
    rigmesh::Clip clip = node.clip;
    clip.setFramesPerSecond(framesPerSecond);
    clip.interpolation = interpolation;
    clip.mode = playback;
    return clip;
}

}  // namespace

SetClipSettingsCommand::SetClipSettingsCommand(Document& document, PartId id,
                                               double framesPerSecond,
                                               rigmesh::Interpolation interpolation,
                                               rigmesh::PlaybackMode playback, QUndoCommand* parent)
    : ClipCommand(document, id,
                  withSettings(document.part(id), framesPerSecond, interpolation, playback),
                  parent) {
    setText(tr("Set clip of %1").arg(document.part(id).name));
}

nlohmann::json SetClipSettingsCommand::recipeStep() const {
    const rigmesh::Clip& clip = toClip();
    return {{"command", "clip_settings"},
            {"part", partIndex()},
            {"frameRate", clip.framesPerSecond()},
            {"interpolation", interpolationName(clip.interpolation)},
            {"playback", playbackName(clip.mode)}};
}

}  // namespace rigmesh::model
