#include "rig/Skeleton.h"

#include <algorithm>
#include <cmath>
#include <functional>
#include <numeric>
#include <queue>
#include <unordered_set>

#include <Eigen/Geometry>

#include "base/DisjointSets.h"
#include "base/Error.h"

namespace rigmesh {

namespace {

// A bone shorter than this fraction of the skeleton's bounding-box diagonal
// counts as zero-length.
constexpr double kZeroLengthRelative = 1e-9;

std::string jointName(JointId id) {
    return "joint " + std::to_string(id);
}
std::string boneName(BoneId id) {
    return "bone " + std::to_string(id);
}

}  // namespace

Skeleton Skeleton::restore(std::vector<Joint> joints, std::vector<Bone> bones, JointId root) {
    Skeleton s;
    s.joints_ = std::move(joints);
    s.bones_ = std::move(bones);
    s.root_ = root;
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
        throw Error("A bone cannot connect " + jointName(head) + " to itself.");
    }
    const BoneId id = nextBoneId_++;
    boneIndex_.emplace(id, boneCount());
    bones_.push_back({id, head, tail});
    return id;
}

void Skeleton::setJointPosition(JointId id, const Vec3& position) {
    joints_[indexOfJoint(id)].position = position;
}

void Skeleton::removeBone(BoneId id) {
    bones_.erase(bones_.begin() + indexOfBone(id));
    rebuildIndex();
}

void Skeleton::removeJoint(JointId id) {
    joints_.erase(joints_.begin() + indexOfJoint(id));
    std::erase_if(bones_, [id](const Bone& b) { return b.head == id || b.tail == id; });
    if (root_ == id) {
        root_ = joints_.empty() ? kNoJoint : joints_.front().id;
    }
    rebuildIndex();
}

void Skeleton::collapseBone(BoneId id, const Vec3& mergedPosition) {
    const Bone collapsed = bone(id);
    const JointId keep = collapsed.head;
    const JointId gone = collapsed.tail;
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
    const JointId oldTail = bone(id).tail;
    const JointId middle = addJoint(position);
    bones_[indexOfBone(id)].tail = middle;
    addBone(middle, oldTail);
    return middle;
}

void Skeleton::mergeJoints(JointId keep, JointId gone) {
    if (!hasJoint(keep) || !hasJoint(gone))
        throw Error("Only existing joints can be merged.");
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
    if (root_ == gone)
        root_ = keep;
    rebuildIndex();
}

void Skeleton::setRoot(JointId id) {
    indexOfJoint(id);
    root_ = id;
}

int Skeleton::indexOfJoint(JointId id) const {
    const auto it = jointIndex_.find(id);
    if (it == jointIndex_.end()) {
        throw Error("The skeleton has no " + jointName(id) + ".");
    }
    return it->second;
}

int Skeleton::indexOfBone(BoneId id) const {
    const auto it = boneIndex_.find(id);
    if (it == boneIndex_.end()) {
        throw Error("The skeleton has no " + boneName(id) + ".");
    }
    return it->second;
}

namespace {

// Breadth-first depth of every joint (by dense index) from the root; -1 when
// unreachable. Also returns bone indices in the order they were first crossed.
struct Traversal {
    std::vector<int> depth;
    std::vector<int> boneOrder;
};

Traversal traverseFromRoot(const Skeleton& s) {
    Traversal t;
    t.depth.assign(s.jointCount(), -1);
    if (!s.hasJoint(s.root())) {
        return t;
    }
    std::vector<std::vector<int>> incident(s.jointCount());
    for (int b = 0; b < s.boneCount(); ++b) {
        const Bone& bone = s.bones()[b];
        if (s.hasJoint(bone.head) && s.hasJoint(bone.tail)) {
            incident[s.indexOfJoint(bone.head)].push_back(b);
            incident[s.indexOfJoint(bone.tail)].push_back(b);
        }
    }
    std::vector<bool> crossed(s.boneCount(), false);
    std::queue<int> queue;
    const int start = s.indexOfJoint(s.root());
    t.depth[start] = 0;
    queue.push(start);
    while (!queue.empty()) {
        const int j = queue.front();
        queue.pop();
        for (int b : incident[j]) {
            const Bone& bone = s.bones()[b];
            const int a = s.indexOfJoint(bone.head);
            const int other = a == j ? s.indexOfJoint(bone.tail) : a;
            if (t.depth[other] < 0) {
                t.depth[other] = t.depth[j] + 1;
                queue.push(other);
            }
            if (!crossed[b]) {
                crossed[b] = true;
                t.boneOrder.push_back(b);
            }
        }
    }
    return t;
}

}  // namespace

void Skeleton::reorient() {
    const Traversal t = traverseFromRoot(*this);
    for (Bone& b : bones_) {
        if (!hasJoint(b.head) || !hasJoint(b.tail)) {
            continue;
        }
        const int dh = t.depth[indexOfJoint(b.head)];
        const int dt = t.depth[indexOfJoint(b.tail)];
        if (dh >= 0 && dt >= 0 && dt < dh) {
            std::swap(b.head, b.tail);
        }
    }
}

bool Skeleton::isOrientedFromRoot() const {
    const Traversal t = traverseFromRoot(*this);
    return std::all_of(bones_.begin(), bones_.end(), [&](const Bone& b) {
        if (!hasJoint(b.head) || !hasJoint(b.tail)) {
            return false;
        }
        const int dh = t.depth[indexOfJoint(b.head)];
        const int dt = t.depth[indexOfJoint(b.tail)];
        return dh >= 0 && dt == dh + 1;
    });
}

std::optional<BoneId> Skeleton::parentBone(BoneId id) const {
    const JointId head = bone(id).head;
    for (const Bone& b : bones_) {
        if (b.tail == head && b.id != id) {
            return b.id;
        }
    }
    return std::nullopt;
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

std::vector<BoneId> Skeleton::bonesInHierarchyOrder() const {
    std::vector<BoneId> order;
    for (int b : traverseFromRoot(*this).boneOrder) {
        order.push_back(bones_[b].id);
    }
    return order;
}

std::vector<std::string> Skeleton::validate() const {
    std::vector<std::string> problems;
    if (joints_.empty()) {
        problems.push_back("The skeleton has no joints.");
        return problems;
    }

    std::unordered_set<JointId> seenJoints;
    Eigen::AlignedBox3d box;
    for (const Joint& j : joints_) {
        if (!seenJoints.insert(j.id).second) {
            problems.push_back("Two joints share the id " + std::to_string(j.id) + ".");
        }
        if (!j.position.allFinite()) {
            problems.push_back(jointName(j.id) + " has a non-finite position.");
        } else {
            box.extend(j.position);
        }
    }
    std::unordered_set<BoneId> seenBones;
    for (const Bone& b : bones_) {
        if (!seenBones.insert(b.id).second) {
            problems.push_back("Two bones share the id " + std::to_string(b.id) + ".");
        }
    }
    if (!hasJoint(root_)) {
        problems.push_back(root_ == kNoJoint
                               ? "The skeleton has no root joint."
                               : "The root is " + jointName(root_) + ", which does not exist.");
    }

    const double zeroLength = kZeroLengthRelative * (box.isEmpty() ? 0.0 : box.diagonal().norm());
    DisjointSets sets(static_cast<std::size_t>(jointCount()));
    int components = jointCount();
    for (const Bone& b : bones_) {
        const bool headOk = hasJoint(b.head);
        const bool tailOk = hasJoint(b.tail);
        if (!headOk || !tailOk) {
            problems.push_back(boneName(b.id) + " refers to " +
                               jointName(headOk ? b.tail : b.head) + ", which does not exist.");
            continue;
        }
        if (b.head == b.tail) {
            problems.push_back(boneName(b.id) + " connects " + jointName(b.head) + " to itself.");
            continue;
        }
        if (boneLength(b.id) <= zeroLength) {
            problems.push_back(boneName(b.id) + " has zero length.");
        }
        if (sets.unite(indexOfJoint(b.head), indexOfJoint(b.tail))) {
            --components;
        } else {
            problems.push_back("The skeleton has a cycle: " + boneName(b.id) + " closes a loop.");
        }
    }
    if (components > 1) {
        problems.push_back("The skeleton is not connected: it has " + std::to_string(components) +
                           " separate components.");
    }
    return problems;
}

JointId chooseCentralRoot(const Skeleton& s) {
    const int n = s.jointCount();
    if (n == 0) {
        throw Error("Cannot choose a root for a skeleton without joints.");
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
