// The document's timeline: the frame range played and shown, the
// frame rate that turns frames into the seconds clips are keyed in, and the
// current frame.
//
// Keys stay in seconds with the clip's half-frame tolerance (pose/Clip.h),
// not on integer frames: the engine, the file, recipes and every exchange
// format speak seconds, and an imported animation keeps its exact key times.
// What the timeline writes it writes on whole frames (time = frame / rate),
// it shows a key in the column of its nearest frame, and changing the rate
// keeps keys on their frames (Blender's behaviour: the seconds scale).
#pragma once

#include <cmath>

namespace rigmesh::model {

// Frames lie in [0, kMaxFrame]: at 24 fps, 4.8 days.
inline constexpr int kMaxFrame = 10'000'000;
inline constexpr double kMinFrameRate = 1.0;
inline constexpr double kMaxFrameRate = 1000.0;

struct TimelineSettings {
    int startFrame = 0;
    int endFrame = 48;  // two seconds at 24 fps
    double framesPerSecond = 24.0;

    double timeOfFrame(double frame) const { return frame / framesPerSecond; }
    // The nearest frame (ties away from zero).
    double frameOfTime(double time) const { return std::round(time * framesPerSecond); }

    friend bool operator==(const TimelineSettings&, const TimelineSettings&) = default;
};

// Throws rigmesh::Error unless 0 <= start < end <= kMaxFrame and the rate is
// within [kMinFrameRate, kMaxFrameRate] and the end lies within a clip's
// longest key time.
void checkTimelineSettings(const TimelineSettings& settings);
// Throws rigmesh::Error unless 0 <= frame <= kMaxFrame.
void checkFrame(int frame);

}  // namespace rigmesh::model
