#include "io/AssimpAnimationBuilder.h"

#include <assimp/anim.h>

#include <algorithm>
#include <cmath>

#include "base/Error.h"
#include "io/AssimpConversions.h"

namespace rigmesh {

std::vector<double> exportedKeyTimes(const Clip& clip) {
    std::vector<double> times = clip.keyTimes();
    if (clip.interpolation == Interpolation::Smooth && times.size() > 1) {
        const double step = 1.0 / clip.framesPerSecond();
        const double first = times.front(), last = times.back();
        const auto frames = static_cast<long>(std::floor((last - first) / step));
        for (long f = 1; f <= frames; ++f) {
            const double t = first + static_cast<double>(f) * step;
            const bool nearKey = std::any_of(times.begin(), times.end(), [&](double k) {
                return std::abs(k - t) < 0.25 * step;
            });
            if (!nearKey)
                times.push_back(t);
        }
        std::sort(times.begin(), times.end());
    }
    return times;
}

aiAnimation* makeAnimation(const Clip& clip, const ExportRig& rig, const std::string& name) {
    if (clip.keyCount() == 0)
        throw Error("cannot export an animation without keys");
    const std::vector<double> times = exportedKeyTimes(clip);
    std::vector<Pose> poses;
    for (double t : times)
        poses.push_back(clip.evaluate(t));

    auto* animation = new aiAnimation;
    animation->mName = aiString(name);
    animation->mTicksPerSecond = 1.0;  // notes item 4: times in seconds
    animation->mDuration = times.back();
    animation->mNumChannels = static_cast<unsigned>(rig.nodes.size());
    animation->mChannels = new aiNodeAnim*[rig.nodes.size()];
    const unsigned count = static_cast<unsigned>(times.size());
    for (std::size_t n = 0; n < rig.nodes.size(); ++n) {
        // Notes item 5: position, rotation and scaling keys, same count and times.
        auto* channel = new aiNodeAnim;
        channel->mNodeName = aiString(rig.nodes[n].name);
        channel->mNumPositionKeys = channel->mNumRotationKeys = channel->mNumScalingKeys = count;
        channel->mPositionKeys = new aiVectorKey[count];
        channel->mRotationKeys = new aiQuatKey[count];
        channel->mScalingKeys = new aiVectorKey[count];
        Eigen::Quaterniond previous = Eigen::Quaterniond::Identity();
        for (unsigned k = 0; k < count; ++k) {
            const int node = static_cast<int>(n);
            Eigen::Quaterniond q = rig.localRotation(node, poses[k]);
            if (q.dot(previous) < 0)  // same hemisphere as the key before: shortest slerp
                q.coeffs() = -q.coeffs();
            previous = q;
            channel->mPositionKeys[k] =
                aiVectorKey(times[k], toAi(rig.localTranslation(node, poses[k])));
            channel->mRotationKeys[k] = aiQuatKey(times[k], toAi(q));
            channel->mScalingKeys[k] = aiVectorKey(times[k], aiVector3D(1, 1, 1));
        }
        animation->mChannels[n] = channel;
    }
    return animation;
}

}  // namespace rigmesh
