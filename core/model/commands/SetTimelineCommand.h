// Set the timeline's frame range and rate. A new rate keeps every
// key of every clip on its frame, as Blender does: on the frame of the
// clip's own rate, so the key times in seconds scale by the clip's rate /
// new rate (a clip imported at 30 fps into a 24 fps timeline keeps its key
// on frame 30 when the timeline goes to 30 fps). The new rate becomes every
// clip's frame rate (its half-frame tolerance and the frames an export
// samples).
#pragma once

#include <QCoreApplication>
#include <QUndoCommand>
#include <map>
#include <vector>

#include "model/Document.h"
#include "model/recipe/RecipeStepSource.h"

namespace rigmesh::model {

class SetTimelineCommand : public QUndoCommand, public RecipeStepSource {
    Q_DECLARE_TR_FUNCTIONS(SetTimelineCommand)
  public:
    // Throws rigmesh::Error on settings checkTimelineSettings refuses, or a
    // rate that would move a key beyond a clip's longest key time.
    SetTimelineCommand(Document& document, const TimelineSettings& settings,
                       QUndoCommand* parent = nullptr);

    void redo() override;
    void undo() override;
    nlohmann::json recipeStep() const override;

  private:
    struct Clips {
        rigmesh::Clip active = rigmesh::Clip();
        std::vector<rigmesh::Clip> others;
    };
    void apply(const TimelineSettings& settings, const std::map<PartId, Clips>& clips);

    Document& document_;
    TimelineSettings before_, after_;
    // Only when the rate changes: every part's clips before and after.
    std::map<PartId, Clips> clipsBefore_, clipsAfter_;
};

// `clip` with every key moved from frame f at the clip's own rate to f at
// `toRate`, and `toRate` as its frame rate. Throws rigmesh::Error on a key
// out of range.
rigmesh::Clip retimedClip(const rigmesh::Clip& clip, double toRate);

}  // namespace rigmesh::model
