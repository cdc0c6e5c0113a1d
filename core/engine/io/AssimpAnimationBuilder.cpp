#include "io/AssimpAnimationBuilder.h"

#include <assimp/anim.h>

#include <algorithm>
#include <cmath>

#include "base/Error.h"
#include "io/AssimpConversions.h"

namespace rigmesh {

namespace {

// Appends the frames strictly inside the key segment (from, to) of a Smooth
// clip: the frame grid starts at the first key, and frames within a quarter
// frame of a key are left to the key. A long segment gets at most
// kMaxFramesPerSegment evenly spaced samples instead, so the work is bounded
// by the number of keys, never by the clip's length in frames. Frame numbers
// stay doubles: nothing is cast to an integer before it is known to be small.
void appendSegmentFrames(std::vector<double>& times, double first, double step, double from,
                         double to) {
    const double firstFrame = std::ceil((from - first) / step + 0.25);
    const double lastFrame = std::floor((to - first) / step - 0.25);
    if (!(lastFrame >= firstFrame))
        return;
    const double frames = lastFrame - firstFrame + 1;
    if (frames <= kMaxFramesPerSegment) {
        for (int f = 0; f < static_cast<int>(frames); ++f)
            times.push_back(first + (firstFrame + f) * step);
        return;
    }
    const double spacing = (to - from) / (kMaxFramesPerSegment + 1);
    for (int s = 1; s <= kMaxFramesPerSegment; ++s)
        times.push_back(from + s * spacing);
}

// glTF stores times as 32-bit floats: far from zero, close keys would merge
// into one time (or run backwards), which viewers reject.
void checkDistinctAsFloats(const std::vector<double>& times) {
    for (std::size_t k = 1; k < times.size(); ++k)
        if (!(static_cast<float>(times[k - 1]) < static_cast<float>(times[k])))
            throw Error(MessageId::ExportKeysTooClose, std::to_string(times[k - 1]),
                        std::to_string(times[k]));
}

}  // namespace

namespace {

// The rig's channels, from mChannels[next] on; the animation's duration grows
// to the clip's last written time.
void appendChannels(const Clip& clip, const ExportRig& rig, aiAnimation& animation,
                    std::size_t& next) {
    const std::vector<double> times = exportedKeyTimes(clip);
    checkDistinctAsFloats(times);
    animation.mDuration = std::max(animation.mDuration, times.back());
    const unsigned count = static_cast<unsigned>(times.size());
    // docs/EXCHANGE.md rule 5: position, rotation and scaling keys, same
    // count and times.
    std::vector<aiNodeAnim*> channels;
    for (const ExportBoneNode& node : rig.nodes) {
        auto* channel = new aiNodeAnim;
        animation.mChannels[next++] = channel;
        channel->mNodeName = aiString(node.name);
        channel->mNumPositionKeys = channel->mNumRotationKeys = channel->mNumScalingKeys = count;
        channel->mPositionKeys = new aiVectorKey[count];
        channel->mRotationKeys = new aiQuatKey[count];
        channel->mScalingKeys = new aiVectorKey[count];
        channels.push_back(channel);
    }
    // One pose at a time, written to every channel: a long clip's poses are
    // never all held at once.
    std::vector<Eigen::Quaterniond> previous(rig.nodes.size(), Eigen::Quaterniond::Identity());
    for (unsigned k = 0; k < count; ++k) {
        const Pose pose = clip.evaluate(times[k]);
        for (std::size_t n = 0; n < channels.size(); ++n) {
            const int node = static_cast<int>(n);
            Eigen::Quaterniond q = rig.localRotation(node, pose);
            if (q.dot(previous[n]) < 0)  // same hemisphere as the key before: shortest slerp
                q.coeffs() = -q.coeffs();
            previous[n] = q;
            channels[n]->mPositionKeys[k] =
                aiVectorKey(times[k], toAi(rig.localTranslation(node, pose)));
            channels[n]->mRotationKeys[k] = aiQuatKey(times[k], toAi(q));
            channels[n]->mScalingKeys[k] = aiVectorKey(times[k], aiVector3D(1, 1, 1));
        }
    }
}

}  // namespace

std::vector<double> exportedKeyTimes(const Clip& clip) {
    const std::vector<double> keys = clip.keyTimes();
    if (clip.interpolation == Interpolation::Linear || keys.size() < 2)
        return keys;
    const double step = 1.0 / clip.framesPerSecond();
    std::vector<double> times;
    for (std::size_t k = 0; k + 1 < keys.size(); ++k) {
        times.push_back(keys[k]);
        appendSegmentFrames(times, keys.front(), step, keys[k], keys[k + 1]);
    }
    times.push_back(keys.back());
    return times;
}

aiAnimation* makeAnimation(const std::vector<AnimatedRig>& rigs, const std::string& name) {
    if (rigs.empty())
        throw Error(MessageId::ExportAnimationOfNothing);
    std::size_t channelCount = 0;
    for (const AnimatedRig& animated : rigs) {
        if (animated.clip->keyCount() == 0)
            throw Error(MessageId::ExportAnimationWithoutKeys);
        channelCount += animated.rig->nodes.size();
    }
    auto* animation = new aiAnimation;
    animation->mName = aiString(name);
    animation->mTicksPerSecond = 1.0;  // docs/EXCHANGE.md rule 4: times in seconds
    animation->mDuration = 0.0;
    animation->mNumChannels = static_cast<unsigned>(channelCount);
    animation->mChannels = new aiNodeAnim*[channelCount]();
    std::size_t next = 0;
    try {
        for (const AnimatedRig& animated : rigs)
            appendChannels(*animated.clip, *animated.rig, *animation, next);
    } catch (...) {
        delete animation;  // deletes the channels made so far (the rest are null)
        throw;
    }
    return animation;
}

namespace {

// Keeps the first of `count` keys when every value equals it.
void keepOneIfConstant(aiVectorKey*& keys, unsigned& count) {
    if (count < 2 || !std::all_of(keys + 1, keys + count, [&](const aiVectorKey& key) {
            return key.mValue == keys[0].mValue;
        }))
        return;
    auto* one = new aiVectorKey[1]{keys[0]};
    delete[] keys;
    keys = one;
    count = 1;
}

}  // namespace

void keepConstantChannelsAsOneKey(aiAnimation& animation) {
    for (unsigned c = 0; c < animation.mNumChannels; ++c) {
        aiNodeAnim& channel = *animation.mChannels[c];
        keepOneIfConstant(channel.mPositionKeys, channel.mNumPositionKeys);
        keepOneIfConstant(channel.mScalingKeys, channel.mNumScalingKeys);
    }
}

}  // namespace rigmesh
