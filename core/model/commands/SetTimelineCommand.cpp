#include "model/commands/SetTimelineCommand.h"

#include <nlohmann/json.hpp>

namespace rigmesh::model {

rigmesh::Clip retimedClip(const rigmesh::Clip& clip, double toRate) {
    const double fromRate = clip.framesPerSecond();
    rigmesh::Clip out(toRate);
    out.name = clip.name;
    out.interpolation = clip.interpolation;
    out.mode = clip.mode;
    for (const auto& [time, pose] : clip.keys())
        out.insertExactKey(fromRate == toRate ? time : time * fromRate / toRate, pose);
    return out;
}

SetTimelineCommand::SetTimelineCommand(Document& document, const TimelineSettings& settings,
                                       QUndoCommand* parent)
    : QUndoCommand(parent), document_(document), before_(document.timeline()), after_(settings) {
    checkTimelineSettings(settings);
    const double to = after_.framesPerSecond;
    if (before_.framesPerSecond != to) {
        for (const PartNode& node : document.parts()) {
            Clips after{retimedClip(node.clip, to), {}};
            for (const rigmesh::Clip& other : node.otherClips)
                after.others.push_back(retimedClip(other, to));
            clipsBefore_[node.id] = {node.clip, node.otherClips};
            clipsAfter_[node.id] = std::move(after);
        }
    }
    setObsolete(before_ == after_);
    setText(tr("Set the frame range to %1-%2 at %3 fps")
                .arg(settings.startFrame)
                .arg(settings.endFrame)
                .arg(settings.framesPerSecond));
}

void SetTimelineCommand::apply(const TimelineSettings& settings,
                               const std::map<PartId, Clips>& clips) {
    for (const auto& [id, partClips] : clips)
        document_.setClips(id, partClips.active, partClips.others);
    document_.setTimeline(settings);
}

void SetTimelineCommand::redo() {
    apply(after_, clipsAfter_);
}

void SetTimelineCommand::undo() {
    apply(before_, clipsBefore_);
}

nlohmann::json SetTimelineCommand::recipeStep() const {
    return {{"command", "timeline"},
            {"start", after_.startFrame},
            {"end", after_.endFrame},
            {"frameRate", after_.framesPerSecond}};
}

}  // namespace rigmesh::model
