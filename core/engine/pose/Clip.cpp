#include "pose/Clip.h"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <iterator>
#include <string>

#include "base/Error.h"
#include "pose/QuaternionInterpolation.h"

namespace rigmesh {

namespace {

void checkTime(double time) {
    if (!std::isfinite(time))
        throw Error(MessageId::KeyTimeNotFinite);
}

std::string seconds(double time) {
    char text[32];
    std::snprintf(text, sizeof text, "%g", time);
    return text;
}

// Where a key may go: a finite time from 0 to the longest clip. Nothing
// plays before 0 s, and glTF refuses animation times below zero.
void checkKeyTime(double time) {
    checkTime(time);
    if (time < 0.0)
        throw Error(MessageId::KeyTimeNegative, seconds(time));
    if (time > Clip::kLongestKeyTime)
        throw Error(MessageId::KeyTimeTooLate, seconds(time), seconds(Clip::kLongestKeyTime));
}

Eigen::Quaterniond unitRotation(const Pose& pose, JointId joint) {
    return pose.rotation(joint).normalized();
}

// Catmull-Rom through p1 (u = 0) and p2 (u = 1) with neighbours p0 and p3,
// as a cubic Hermite curve with tangents (p2 - p0) / 2 and (p3 - p1) / 2.
Vec3 catmullRom(const Vec3& p0, const Vec3& p1, const Vec3& p2, const Vec3& p3, double u) {
    if (u == 0.0)
        return p1;
    const double u2 = u * u, u3 = u2 * u;
    const Vec3 m1 = 0.5 * (p2 - p0), m2 = 0.5 * (p3 - p1);
    return (2 * u3 - 3 * u2 + 1) * p1 + (u3 - 2 * u2 + u) * m1 + (-2 * u3 + 3 * u2) * p2 +
           (u3 - u2) * m2;
}

}  // namespace

Clip::Clip(double framesPerSecond) : framesPerSecond_(24.0) {
    setFramesPerSecond(framesPerSecond);
}

void Clip::setFramesPerSecond(double framesPerSecond) {
    if (!std::isfinite(framesPerSecond) || !(framesPerSecond > 0))
        throw Error(MessageId::ClipFrameRateInvalid);
    framesPerSecond_ = framesPerSecond;
}

std::map<double, Pose>::const_iterator Clip::find(double time) const {
    auto best = keys_.end();
    double bestDistance = keyTolerance();
    const auto after = keys_.lower_bound(time);
    if (after != keys_.end() && after->first - time <= bestDistance) {
        best = after;
        bestDistance = after->first - time;
    }
    if (after != keys_.begin()) {
        const auto before = std::prev(after);
        if (time - before->first <= bestDistance)
            best = before;
    }
    return best;
}

void Clip::setKey(double time, const Pose& pose) {
    checkKeyTime(time);
    if (!pose.isFinite())
        throw Error(MessageId::KeyPoseInvalid);
    const auto existing = find(time);
    if (existing != keys_.end())
        keys_.erase(existing);
    keys_.emplace(time, pose);
}

void Clip::insertExactKey(double time, const Pose& pose) {
    checkKeyTime(time);
    if (!pose.isFinite())
        throw Error(MessageId::KeyPoseInvalid);
    if (!keys_.emplace(time, pose).second)
        throw Error(MessageId::KeyAlreadyAt, std::to_string(time));
}

void Clip::eraseExactKey(double time) {
    if (keys_.erase(time) == 0)
        throw Error(MessageId::NoKeyExactlyAt, std::to_string(time));
}

void Clip::moveKey(double from, double to) {
    checkTime(from);
    checkKeyTime(to);
    const auto it = find(from);
    if (it == keys_.end())
        throw Error(MessageId::NoKeyToMove, std::to_string(from));
    const Pose pose = it->second;
    keys_.erase(it);
    setKey(to, pose);
}

void Clip::removeKey(double time) {
    checkTime(time);
    const auto it = find(time);
    if (it == keys_.end())
        throw Error(MessageId::NoKeyToDelete, std::to_string(time));
    keys_.erase(it);
}

bool Clip::hasKey(double time) const {
    return std::isfinite(time) && find(time) != keys_.end();
}

const Pose& Clip::key(double time) const {
    return keys_.find(keyTime(time))->second;
}

double Clip::keyTime(double time) const {
    checkTime(time);
    const auto it = find(time);
    if (it == keys_.end())
        throw Error(MessageId::NoKeyAt, std::to_string(time));
    return it->first;
}

std::vector<double> Clip::keyTimes() const {
    std::vector<double> times;
    times.reserve(keys_.size());
    for (const auto& [time, pose] : keys_)
        times.push_back(time);
    return times;
}

double Clip::duration() const {
    if (keys_.empty())
        throw Error(MessageId::ClipHasNoKeys);
    return keys_.rbegin()->first - keys_.begin()->first;
}

double Clip::wrap(double time) const {
    const double first = keys_.begin()->first;
    const double last = keys_.rbegin()->first;
    if (mode == PlaybackMode::Hold || last == first)
        return std::clamp(time, first, last);
    const double span = last - first;
    const double period = mode == PlaybackMode::PingPong ? 2 * span : span;
    double offset = std::fmod(time - first, period);
    if (offset < 0)
        offset += period;
    if (offset > span)  // ping-pong on its way back
        offset = period - offset;
    return first + offset;
}

Pose Clip::evaluate(double time) const {
    if (keys_.empty())
        throw Error(MessageId::ClipPlayedWithoutKeys);

    checkTime(time);
    const double t = wrap(time);
    const auto exact = keys_.find(t);
    if (exact != keys_.end())
        return exact->second;

    // The keys around t: k1 <= t < k2, with neighbours k0 and k3 (clamped).
    const auto k2 = keys_.upper_bound(t);
    const auto k1 = std::prev(k2);
    if (interpolation == Interpolation::Constant)
        return k1->second;
    const auto k0 = k1 == keys_.begin() ? k1 : std::prev(k1);
    const auto k3 = std::next(k2) == keys_.end() ? k2 : std::next(k2);
    const double u = (t - k1->first) / (k2->first - k1->first);
    const Pose& p0 = k0->second;
    const Pose& p1 = k1->second;
    const Pose& p2 = k2->second;
    const Pose& p3 = k3->second;

    // The joints any of the four keys rotates, ascending (one sorted vector:
    // exports evaluate a clip at every frame, docs/EXCHANGE.md rule 5).
    std::vector<JointId> joints;
    joints.reserve(p1.rotations.size() + p2.rotations.size());
    for (const Pose* p : {&p0, &p1, &p2, &p3}) {
        for (const auto& [joint, q] : p->rotations)
            joints.push_back(joint);
    }
    std::sort(joints.begin(), joints.end());
    joints.erase(std::unique(joints.begin(), joints.end()), joints.end());

    Pose result;
    if (interpolation == Interpolation::Linear) {
        for (JointId joint : joints)
            result.rotations.emplace_hint(
                result.rotations.end(), joint,
                slerpShortest(unitRotation(p1, joint), unitRotation(p2, joint), u));
        result.rootTranslation = (1 - u) * p1.rootTranslation + u * p2.rootTranslation;
        return result;
    }
    std::vector<Eigen::Quaterniond> q(4);
    for (JointId joint : joints) {
        // Hemisphere continuity along the four keys before squad.
        q = {unitRotation(p0, joint), unitRotation(p1, joint), unitRotation(p2, joint),
             unitRotation(p3, joint)};
        alignHemispheres(q);
        const Eigen::Quaterniond s1 = squadControl(q[0], q[1], q[2]);
        const Eigen::Quaterniond s2 = squadControl(q[1], q[2], q[3]);
        result.rotations.emplace_hint(result.rotations.end(), joint, squad(q[1], q[2], s1, s2, u));
    }
    result.rootTranslation = catmullRom(p0.rootTranslation, p1.rootTranslation, p2.rootTranslation,
                                        p3.rootTranslation, u);
    return result;
}

}  // namespace rigmesh
