// A change to a part's clip as the keys it takes out and puts in, and the
// settings before and after (key commands once stored two whole clips
// each, so keying n times took O(n^2) time and memory). An edit is computed
// from a few keys around the edited times (localClipEdit), applied in place
// (Document::editClip) and undone by its inverse, each in O(log n) per key
// changed.
#pragma once

#include <functional>
#include <map>
#include <vector>

#include "pose/Clip.h"

namespace rigmesh::model {

struct ClipSettings {
    double framesPerSecond = 24.0;
    rigmesh::Interpolation interpolation = rigmesh::Interpolation::Linear;
    rigmesh::PlaybackMode mode = rigmesh::PlaybackMode::Hold;
    bool operator==(const ClipSettings&) const = default;
};

ClipSettings settingsOf(const rigmesh::Clip& clip);

struct ClipEdit {
    std::map<double, rigmesh::Pose> removed;  // at their exact times
    std::map<double, rigmesh::Pose> added;
    ClipSettings before, after;

    bool changesNothing() const;
    ClipEdit inverse() const;
    // Throws rigmesh::Error, leaving `clip` unchanged, unless every removed
    // key is in `clip` at its exact time and every added key fits in after.
    // O(log n) per key removed or added.
    void applyTo(rigmesh::Clip& clip) const;
};

// The edit `change` makes to `clip`, found by applying it to a copy of only
// the keys around `times` (two on each side of each): enough for the clip's
// key operations, which touch only the key nearest a time. Throws whatever
// `change` throws (a bad time, no key to move).
ClipEdit localClipEdit(const rigmesh::Clip& clip, const std::vector<double>& times,
                       const std::function<void(rigmesh::Clip&)>& change);

}  // namespace rigmesh::model
