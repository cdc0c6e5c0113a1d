// Document's timeline state: the current frame, the frame range
// and rate, auto-key. Apart from Document.cpp so the timeline stays one
// concept.
#include "model/Document.h"

namespace rigmesh::model {

void Document::setCurrentFrame(int frame) {
    checkFrame(frame);
    const bool moved = frame != contents_.currentFrame;
    contents_.currentFrame = frame;
    // Blender's rule: a new frame shows what the clips say there.
    for (const PartNode& node : contents_.parts) {
        if (node.clip.keyCount() == 0)
            continue;
        setPose(node.id, poseAtCurrentFrame(node.id));
    }
    if (moved)
        emit currentFrameChanged(frame);
}

rigmesh::Pose Document::poseAtCurrentFrame(PartId id) const {
    const PartNode& node = part(id);
    if (node.clip.keyCount() == 0)
        return node.pose;
    return node.clip.evaluate(currentTime());
}

void Document::setAutoKey(bool on) {
    if (on == autoKey_)
        return;
    autoKey_ = on;
    emit autoKeyChanged(on);
}

void Document::setTimeline(const TimelineSettings& settings) {
    checkTimelineSettings(settings);
    if (settings == contents_.timeline)
        return;
    contents_.timeline = settings;
    emit timelineChanged(settings);
}

}  // namespace rigmesh::model
