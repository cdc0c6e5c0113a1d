#include "rig/Skeleton.h"

#include <algorithm>
#include <cmath>
#include <functional>
#include <numeric>
#include <queue>
#include <unordered_set>

#include <Eigen/Geometry>

#include "base/Error.h"
#include "rig/BoneSegment.h"

namespace rigmesh {

Skeleton Skeleton::restore(std::vector<Joint> joints, std::vector<Bone> bones, JointId root,
                           std::map<JointId, BoneId> attachments) {
    Skeleton s;
    s.joints_ = std::move(joints);
    s.bones_ = std::move(bones);
    s.root_ = root;
    s.attachments_ = std::move(attachments);
    for (const Joint& j : s.joints_) {
        s.nextJointId_ = std::max(s.nextJointId_, j.id + 1);
    }
    for (const Bone& b : s.bones_) {
        s.nextBoneId_ = std::max(s.nextBoneId_, b.id + 1);
    }
    s.rebuildIndex();
    return s;
}

void Skeleton::rebuildIndex() {
    jointIndex_.clear();
    boneIndex_.clear();
    // emplace keeps the first of duplicate ids; validate() reports them.
    for (int i = 0; i < jointCount(); ++i) {
        jointIndex_.emplace(joints_[i].id, i);
    }
    for (int i = 0; i < boneCount(); ++i) {
        boneIndex_.emplace(bones_[i].id, i);
    }
}

JointId Skeleton::addJoint(const Vec3& position) {
    const JointId id = nextJointId_++;
    jointIndex_.emplace(id, jointCount());
    joints_.push_back({id, position});
    if (root_ == kNoJoint) {
        root_ = id;
    }
    return id;
}

BoneId Skeleton::addBone(JointId head, JointId tail) {
    indexOfJoint(head);
    indexOfJoint(tail);
    if (head == tail) {
        throw Error(MessageId::BoneToItself, head);
    }
    const BoneId id = nextBoneId_++;
    boneIndex_.emplace(id, boneCount());
    bones_.push_back({id, head, tail});
    return id;
}

void Skeleton::setJointPosition(JointId id, const Vec3& position) {
    joints_[indexOfJoint(id)].position = position;
}

void Skeleton::reattach(BoneId gone, BoneId instead) {
    for (auto& [joint, parent] : attachments_)
        if (parent == gone)
            parent = instead;
}

void Skeleton::removeBone(BoneId id) {
    reattach(id, parentBone(id).value_or(kNoBone));
    bones_.erase(bones_.begin() + indexOfBone(id));
    rebuildIndex();
}

void Skeleton::removeJoint(JointId id) {
    indexOfJoint(id);
    for (BoneId bone : bonesAt(id))
        removeBone(bone);
    joints_.erase(joints_.begin() + indexOfJoint(id));
    attachments_.erase(id);
    if (root_ == id) {
        root_ = joints_.empty() ? kNoJoint : joints_.front().id;
        attachments_.erase(root_);
    }
    rebuildIndex();
}

void Skeleton::collapseBone(BoneId id, const Vec3& mergedPosition) {
    const Bone collapsed = bone(id);
    const JointId keep = collapsed.head;
    const JointId gone = collapsed.tail;
    reattach(id, parentBone(id).value_or(kNoBone));
    attachments_.erase(gone);
    joints_[indexOfJoint(keep)].position = mergedPosition;
    for (Bone& b : bones_) {
        if (b.head == gone) {
            b.head = keep;
        }
        if (b.tail == gone) {
            b.tail = keep;
        }
    }
    // The collapsed bone, and any parallel one, became a self-loop.
    std::erase_if(bones_, [](const Bone& b) { return b.head == b.tail; });
    joints_.erase(joints_.begin() + indexOfJoint(gone));
    if (root_ == gone) {
        root_ = keep;
    }
    rebuildIndex();
}

JointId Skeleton::splitBone(BoneId id, const Vec3& position) {
    const Vec3 head = joint(bone(id).head).position;
    const JointId oldTail = bone(id).tail;
    const Vec3 tail = joint(oldTail).position;
    const JointId middle = addJoint(position);
    bones_[indexOfBone(id)].tail = middle;
    const BoneId second = addBone(middle, oldTail);
    for (auto& [chain, parent] : attachments_) {
        const Vec3& p = joint(chain).position;
        if (parent == id &&
            pointSegmentDistance(p, {position, tail}) < pointSegmentDistance(p, {head, position}))
            parent = second;
    }
    return middle;
}

void Skeleton::mergeJoints(JointId keep, JointId gone) {
    if (!hasJoint(keep) || !hasJoint(gone))
        throw Error(MessageId::MergeMissingJoints);
    if (keep == gone)
        return;
    for (Bone& b : bones_) {
        if (b.head == gone)
            b.head = keep;
        if (b.tail == gone)
            b.tail = keep;
    }
    std::erase_if(bones_, [](const Bone& b) { return b.head == b.tail; });
    joints_.erase(joints_.begin() + indexOfJoint(gone));
    attachments_.erase(gone);
    if (root_ == gone) {
        root_ = keep;
        attachments_.erase(keep);
    }
    rebuildIndex();
}

void Skeleton::setRoot(JointId id) {
    indexOfJoint(id);
    root_ = id;
    attachments_.erase(id);
}

void Skeleton::attach(JointId joint, BoneId parent) {
    indexOfJoint(joint);
    if (parent != kNoBone)
        indexOfBone(parent);
    if (joint == root_)
        throw Error(MessageId::RootCannotHang, joint);
    attachments_[joint] = parent;
}

void Skeleton::detach(JointId joint) {
    attachments_.erase(joint);
}

std::vector<JointId> Skeleton::attachedTo(BoneId bone) const {
    std::vector<JointId> chains;
    for (const auto& [joint, parent] : attachments_)
        if (parent == bone)
            chains.push_back(joint);
    return chains;
}

int Skeleton::indexOfJoint(JointId id) const {
    const auto it = jointIndex_.find(id);
    if (it == jointIndex_.end()) {
        throw Error(MessageId::SkeletonHasNoJoint, id);
    }
    return it->second;
}

int Skeleton::indexOfBone(BoneId id) const {
    const auto it = boneIndex_.find(id);
    if (it == boneIndex_.end()) {
        throw Error(MessageId::SkeletonHasNoBone, id);
    }
    return it->second;
}

std::optional<BoneId> Skeleton::parentBone(BoneId id) const {
    const JointId head = bone(id).head;
    for (const Bone& b : bones_) {
        if (b.tail == head && b.id != id) {
            return b.id;
        }
    }
    if (const auto attached = attachments_.find(head);
        attached != attachments_.end() && hasBone(attached->second))
        return attached->second;
    return std::nullopt;
}

bool Skeleton::isConnected(BoneId id) const {
    const JointId head = bone(id).head;
    return std::any_of(bones_.begin(), bones_.end(),
                       [&](const Bone& b) { return b.tail == head && b.id != id; });
}

std::vector<BoneId> Skeleton::childrenOf(JointId id) const {
    indexOfJoint(id);
    std::vector<BoneId> children;
    for (const Bone& b : bones_) {
        if (b.head == id) {
            children.push_back(b.id);
        }
    }
    return children;
}

std::vector<BoneId> Skeleton::bonesAt(JointId id) const {
    indexOfJoint(id);
    std::vector<BoneId> touching;
    for (const Bone& b : bones_) {
        if (b.head == id || b.tail == id) {
            touching.push_back(b.id);
        }
    }
    return touching;
}

int Skeleton::degree(JointId id) const {
    return static_cast<int>(bonesAt(id).size());
}

double Skeleton::boneLength(BoneId id) const {
    const Bone& b = bone(id);
    return (joint(b.tail).position - joint(b.head).position).norm();
}

JointId chooseCentralRoot(const Skeleton& s) {
    const int n = s.jointCount();
    if (n == 0) {
        throw Error(MessageId::RootWithoutJoints);
    }
    std::vector<std::vector<std::pair<int, double>>> adjacent(n);
    for (const Bone& b : s.bones()) {
        if (s.hasJoint(b.head) && s.hasJoint(b.tail) && b.head != b.tail) {
            const int h = s.indexOfJoint(b.head);
            const int t = s.indexOfJoint(b.tail);
            const double length = s.boneLength(b.id);
            adjacent[h].push_back({t, length});
            adjacent[t].push_back({h, length});
        }
    }

    // Eccentricity of every joint by Dijkstra (the skeleton may be invalid).
    std::vector<int> reached(n, 0);
    std::vector<double> eccentricity(n, 0.0);
    using Item = std::pair<double, int>;
    for (int source = 0; source < n; ++source) {
        std::vector<double> dist(n, std::numeric_limits<double>::infinity());
        std::priority_queue<Item, std::vector<Item>, std::greater<>> queue;
        dist[source] = 0.0;
        queue.push({0.0, source});
        while (!queue.empty()) {
            const auto [d, j] = queue.top();
            queue.pop();
            if (d > dist[j]) {
                continue;
            }
            ++reached[source];
            eccentricity[source] = std::max(eccentricity[source], d);
            for (const auto& [k, length] : adjacent[j]) {
                if (d + length < dist[k]) {
                    dist[k] = d + length;
                    queue.push({dist[k], k});
                }
            }
        }
    }

    double scale = 0.0;
    for (double e : eccentricity) {
        scale = std::max(scale, e);
    }
    const double tie = 1e-9 * scale;
    int best = 0;
    for (int j = 1; j < n; ++j) {
        if (reached[j] != reached[best]) {
            if (reached[j] > reached[best]) {
                best = j;
            }
            continue;
        }
        if (eccentricity[j] < eccentricity[best] - tie) {
            best = j;
        } else if (eccentricity[j] <= eccentricity[best] + tie) {
            const JointId cand = s.joints()[j].id;
            const JointId current = s.joints()[best].id;
            if (s.degree(cand) >= 3 && s.degree(current) < 3) {
                best = j;
            }
        }
    }
    return s.joints()[best].id;
}

std::optional<BoneId> boneForJoint(const Skeleton& skeleton, JointId joint) {
    if (!skeleton.hasJoint(joint))
        return std::nullopt;
    for (const Bone& bone : skeleton.bones())
        if (bone.tail == joint)
            return bone.id;
    const std::vector<BoneId> children = skeleton.childrenOf(joint);
    if (children.empty())
        return std::nullopt;
    return children.front();
}

}  // namespace rigmesh
