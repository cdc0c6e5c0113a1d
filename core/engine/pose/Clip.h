// An animation clip: keyframed poses over time (paper section 3: posed parts
// are animated by keyframing FK/IK poses). Keys live in a map sorted by time
// (seconds) and are addressed by time with a tolerance of half a frame at the
// clip's frame rate, so a key set "at frame 12" is found again from any time
// that rounds to frame 12.
//
// Evaluation interpolates every bone's rotation (Pose.h) and the root
// translation between the two keys around the time:
//   - Constant: the earlier key's pose until the next key (a stepped clip);
//   - Linear: slerp of rotations (shorter arc), lerp of the translation;
//   - Smooth: squad (Shoemake 1987) through the key rotations after aligning
//     each joint's keys into one hemisphere (so no segment takes the long way
//     round), and a Catmull-Rom spline through the translations; both pass
//     through the keys exactly and are C1 for evenly spaced keys. End keys use
//     themselves as their missing neighbour.
// A joint missing from a key counts as its identity rotation there.
// Outside [first key, last key]: Hold clamps to the end keys, Loop repeats
// the span from the first to the last key (the last key's instant shows the
// first key), PingPong plays the span forwards then backwards (Blender's
// "Ping Pong": the last key's instant shows the last key, twice the span
// later the first key again).
#pragma once

#include <map>
#include <string>
#include <vector>

#include "pose/Pose.h"

namespace rigmesh {

enum class Interpolation { Linear, Smooth, Constant };
enum class PlaybackMode { Hold, Loop, PingPong };

class Clip {
  public:
    // Throws Error unless framesPerSecond is finite and positive.
    explicit Clip(double framesPerSecond = 24.0);

    double framesPerSecond() const { return framesPerSecond_; }
    void setFramesPerSecond(double framesPerSecond);
    // Half a frame: how close a time must be to address a key.
    double keyTolerance() const { return 0.5 / framesPerSecond_; }

    // The action's name in exported files (kept from an imported file);
    // empty: `<part>_clip`.
    std::string name;
    Interpolation interpolation = Interpolation::Linear;
    PlaybackMode mode = PlaybackMode::Hold;

    // Key times lie from 0 to kLongestKeyTime seconds (11.6 days): nothing
    // plays before 0 s (glTF refuses negative animation times), the end is
    // far beyond any animation, and small enough that time * frame rate and
    // the exported frame counts stay exact in integers and doubles.
    static constexpr double kLongestKeyTime = 1e6;

    // Sets the key at `time`: replaces the key within half a frame of it (the
    // nearest; it takes the new time), or inserts a new one. Throws Error on
    // a time that is not finite, below 0 or beyond kLongestKeyTime, or a pose that is
    // not finite.
    void setKey(double time, const Pose& pose);
    // Moves the key at `from` to `to`, replacing any other key at `to`.
    // Throws Error if there is no key at `from` or `to` is out of range.
    void moveKey(double from, double to);
    // Throws Error if there is no key at `time`.
    void removeKey(double time);

    // Exact edits, for replaying a recorded change (undo, redo): no
    // half-frame matching. insertExactKey throws Error as setKey does, or if
    // a key is at exactly `time`; eraseExactKey throws Error unless one is.
    void insertExactKey(double time, const Pose& pose);
    void eraseExactKey(double time);

    bool hasKey(double time) const;
    // The key at `time` (within half a frame); throws Error if none.
    const Pose& key(double time) const;
    // The exact time of the key at `time`; throws Error if none.
    double keyTime(double time) const;
    const std::map<double, Pose>& keys() const { return keys_; }
    int keyCount() const { return static_cast<int>(keys_.size()); }
    std::vector<double> keyTimes() const;
    // Last key time minus first key time; throws Error with no keys.
    double duration() const;

    // The pose at `time`. Throws Error if the clip has no keys or the time is
    // NaN. Exactly a key's pose at its time.
    Pose evaluate(double time) const;

  private:
    // The key nearest `time` within half a frame, or end().
    std::map<double, Pose>::const_iterator find(double time) const;
    double wrap(double time) const;

    double framesPerSecond_;
    std::map<double, Pose> keys_;
};

}  // namespace rigmesh
