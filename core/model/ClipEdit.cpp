#include "model/ClipEdit.h"

#include <iterator>

#include "base/Error.h"
#include "model/PartNode.h"

namespace rigmesh::model {

namespace {

void applySettings(rigmesh::Clip& clip, const ClipSettings& settings) {
    clip.setFramesPerSecond(settings.framesPerSecond);
    clip.interpolation = settings.interpolation;
    clip.mode = settings.mode;
}

// The keys of `from` not (identically) in `to`.
std::map<double, rigmesh::Pose> keysNotIn(const std::map<double, rigmesh::Pose>& from,
                                          const std::map<double, rigmesh::Pose>& to) {
    std::map<double, rigmesh::Pose> out;
    for (const auto& [time, pose] : from) {
        const auto it = to.find(time);
        if (it == to.end() || !identicalPoses(it->second, pose))
            out.emplace(time, pose);
    }
    return out;
}

}  // namespace

ClipSettings settingsOf(const rigmesh::Clip& clip) {
    return {clip.framesPerSecond(), clip.interpolation, clip.mode};
}

bool ClipEdit::changesNothing() const {
    return removed.empty() && added.empty() && before == after;
}

ClipEdit ClipEdit::inverse() const {
    return {added, removed, after, before};
}

void ClipEdit::applyTo(rigmesh::Clip& clip) const {
    // Check everything first, so that a failure leaves `clip` unchanged
    // without copying it.
    for (const auto& [time, pose] : removed)
        if (!clip.keys().contains(time))
            throw Error(MessageId::NoKeyExactlyAt, std::to_string(time));
    rigmesh::Clip probe(after.framesPerSecond);  // validates the frame rate
    for (const auto& [time, pose] : added) {
        probe.insertExactKey(time, pose);  // validates the time and the pose
        if (clip.keys().contains(time) && !removed.contains(time))
            throw Error(MessageId::KeyAlreadyAt, std::to_string(time));
    }
    for (const auto& [time, pose] : removed)
        clip.eraseExactKey(time);
    for (const auto& [time, pose] : added)
        clip.insertExactKey(time, pose);
    applySettings(clip, after);
}

ClipEdit localClipEdit(const rigmesh::Clip& clip, const std::vector<double>& times,
                       const std::function<void(rigmesh::Clip&)>& change) {
    rigmesh::Clip local(clip.framesPerSecond());
    local.interpolation = clip.interpolation;
    local.mode = clip.mode;
    const auto& keys = clip.keys();
    for (const double time : times) {
        auto it = keys.lower_bound(time);
        for (int k = 0; k < 2 && it != keys.begin(); ++k)
            --it;
        for (int k = 0; k < 4 && it != keys.end(); ++k, ++it)
            if (!local.keys().contains(it->first))
                local.insertExactKey(it->first, it->second);
    }
    const rigmesh::Clip before = local;
    change(local);
    return {keysNotIn(before.keys(), local.keys()), keysNotIn(local.keys(), before.keys()),
            settingsOf(before), settingsOf(local)};
}

}  // namespace rigmesh::model
