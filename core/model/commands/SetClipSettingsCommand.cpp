#include "model/commands/SetClipSettingsCommand.h"

#include <nlohmann/json.hpp>

#include "model/ClipModes.h"

namespace rigmesh::model {

namespace {

ClipEdit withSettings(const PartNode& node, double framesPerSecond,
                      rigmesh::Interpolation interpolation, rigmesh::PlaybackMode playback) {
    return localClipEdit(node.clip, {}, [&](rigmesh::Clip& clip) {
        clip.setFramesPerSecond(framesPerSecond);
        clip.interpolation = interpolation;
        clip.mode = playback;
    });
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
    const ClipSettings& settings = edit().after;
    return {{"command", "clip_settings"},
            {"part", partIndex()},
            {"frameRate", settings.framesPerSecond},
            {"interpolation", interpolationName(settings.interpolation)},
            {"playback", playbackName(settings.mode)}};
}

}  // namespace rigmesh::model
