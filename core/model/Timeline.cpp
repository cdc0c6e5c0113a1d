#include "model/Timeline.h"

#include <QCoreApplication>

#include <string>

#include "base/Error.h"
#include "pose/Clip.h"

namespace rigmesh::model {

void checkTimelineSettings(const TimelineSettings& settings) {
    const double fps = settings.framesPerSecond;
    if (!std::isfinite(fps) || fps < kMinFrameRate || fps > kMaxFrameRate)
        throw Error(QCoreApplication::translate(
                        "rigmesh::model::Timeline",
                        "The frame rate must be between %1 and %2 frames per second.")
                        .arg(int(kMinFrameRate))
                        .arg(int(kMaxFrameRate))
                        .toStdString());
    if (settings.startFrame < 0 || settings.endFrame > kMaxFrame)
        throw Error(QCoreApplication::translate("rigmesh::model::Timeline",
                                                "The frame range must lie within frames 0 to %1.")
                        .arg(kMaxFrame)
                        .toStdString());
    if (settings.startFrame >= settings.endFrame)
        throw Error(QCoreApplication::translate("rigmesh::model::Timeline",
                                                "The frame range must end after it starts.")
                        .toStdString());
    if (settings.timeOfFrame(settings.endFrame) > rigmesh::Clip::kLongestKeyTime)
        throw Error(QCoreApplication::translate("rigmesh::model::Timeline",
                                                "The frame range is longer than a clip can be.")
                        .toStdString());
}

void checkFrame(int frame) {
    if (frame < 0 || frame > kMaxFrame)
        throw Error(QCoreApplication::translate("rigmesh::model::Timeline",
                                                "Frame %1 is outside frames 0 to %2.")
                        .arg(frame)
                        .arg(kMaxFrame)
                        .toStdString());
}

}  // namespace rigmesh::model
