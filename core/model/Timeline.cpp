#include "model/Timeline.h"

#include <string>

#include "base/Error.h"
#include "pose/Clip.h"

namespace rigmesh::model {

void checkTimelineSettings(const TimelineSettings& settings) {
    const double fps = settings.framesPerSecond;
    if (!std::isfinite(fps) || fps < kMinFrameRate || fps > kMaxFrameRate)
        throw Error("The frame rate must be between " + std::to_string(int(kMinFrameRate)) +
                    " and " + std::to_string(int(kMaxFrameRate)) + " frames per second.");
    if (settings.startFrame < 0 || settings.endFrame > kMaxFrame)
        throw Error("The frame range must lie within frames 0 to " + std::to_string(kMaxFrame) +
                    ".");
    if (settings.startFrame >= settings.endFrame)
        throw Error("The frame range must end after it starts.");
    if (settings.timeOfFrame(settings.endFrame) > rigmesh::Clip::kLongestKeyTime)
        throw Error("The frame range is longer than a clip can be.");
}

void checkFrame(int frame) {
    if (frame < 0 || frame > kMaxFrame)
        throw Error("Frame " + std::to_string(frame) + " is outside frames 0 to " +
                    std::to_string(kMaxFrame) + ".");
}

}  // namespace rigmesh::model
