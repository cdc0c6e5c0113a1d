#include "model/Timeline.h"

#include <string>

#include "base/Error.h"
#include "pose/Clip.h"

namespace rigmesh::model {

void checkTimelineSettings(const TimelineSettings& settings) {
    const double fps = settings.framesPerSecond;
    if (!std::isfinite(fps) || fps < kMinFrameRate || fps > kMaxFrameRate)
        throw Error(MessageId::FrameRateOutOfRange, int(kMinFrameRate), int(kMaxFrameRate));
    if (settings.startFrame < 0 || settings.endFrame > kMaxFrame)
        throw Error(MessageId::FrameRangeOutside, kMaxFrame);
    if (settings.startFrame >= settings.endFrame)
        throw Error(MessageId::FrameRangeEmpty);
    if (settings.timeOfFrame(settings.endFrame) > rigmesh::Clip::kLongestKeyTime)
        throw Error(MessageId::FrameRangeTooLong);
}

void checkFrame(int frame) {
    if (frame < 0 || frame > kMaxFrame)
        throw Error(MessageId::FrameOutside, frame, kMaxFrame);
}

}  // namespace rigmesh::model
