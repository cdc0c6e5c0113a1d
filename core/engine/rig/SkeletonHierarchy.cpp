// The skeleton's hierarchy (Skeleton.h): breadth first from the root through
// bones, and from each bone on to the chains attached to it; orientation from
// each chain's root; and validate(), which checks the whole.
#include <algorithm>
#include <map>
#include <numeric>
#include <queue>
#include <set>
#include <string>
#include <unordered_set>

#include <Eigen/Geometry>

#include "rig/Skeleton.h"

#include "base/DisjointSets.h"

namespace rigmesh {

namespace {

// A bone shorter than this fraction of the skeleton's bounding-box diagonal
// counts as zero-length.
constexpr double kZeroLengthRelative = 1e-9;

// One of validate()'s problems: joints and bones by their ids.
template <class... Args>
Message problem(MessageId id, const Args&... args) {
    return Message{id, {messageArgument(args)...}};
}

// Breadth-first depth of every joint (by dense index) within its chain: 0 at
// the root and at each attached chain's root, -1 when unreachable. Also the
// bone indices in the order they were first crossed: a bone after the bone
// leading to it, a chain's bones after the bone it hangs from.
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
    // Chain roots per bone index they hang from; root chains apart.
    std::vector<std::vector<int>> chainsOf(s.boneCount());
    std::vector<int> rootChains;
    for (const auto& [joint, parent] : s.attachments()) {
        if (!s.hasJoint(joint))
            continue;
        if (parent == kNoBone)
            rootChains.push_back(s.indexOfJoint(joint));
        else if (s.hasBone(parent))
            chainsOf[s.indexOfBone(parent)].push_back(s.indexOfJoint(joint));
    }
    std::vector<bool> crossed(s.boneCount(), false);
    std::queue<int> queue;
    auto startChain = [&](int j) {
        if (t.depth[j] < 0) {
            t.depth[j] = 0;
            queue.push(j);
        }
    };
    const int start = s.indexOfJoint(s.root());
    startChain(start);
    for (int j : rootChains)
        startChain(j);
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
                for (int chain : chainsOf[b])
                    startChain(chain);
            }
        }
    }
    return t;
}

// validate()'s checks of the attachments: known joints and bones, the root
// not attached, exactly one attached joint in every chain but the root's,
// none hanging from its own chain, no loop of chains hanging from each other.
// `sets` holds the joints' components.
void checkChains(const Skeleton& s, DisjointSets& sets, std::vector<Message>& problems) {
    std::map<int, JointId> chainRootOf;  // component -> its attached joint
    int loose = 0, components = 0;
    for (const auto& [joint, parent] : s.attachments()) {
        if (!s.hasJoint(joint)) {
            problems.push_back(problem(MessageId::SkeletonHangingJointMissing, joint));
            continue;
        }
        if (joint == s.root())
            problems.push_back(problem(MessageId::SkeletonRootHangs, joint));
        if (parent != kNoBone && !s.hasBone(parent))
            problems.push_back(problem(MessageId::SkeletonHangsFromMissingBone, joint, parent));
        const int component = sets.find(s.indexOfJoint(joint));
        if (const auto [it, added] = chainRootOf.emplace(component, joint); !added)
            problems.push_back(problem(MessageId::SkeletonOneChainHangsTwice, it->second, joint));
    }
    const int rootComponent = s.hasJoint(s.root()) ? sets.find(s.indexOfJoint(s.root())) : -1;
    if (const auto inRoot = chainRootOf.find(rootComponent);
        inRoot != chainRootOf.end() && inRoot->second != s.root()) {
        problems.push_back(problem(MessageId::SkeletonHangsInRootChain, inRoot->second));
        chainRootOf.erase(inRoot);
    }
    for (int j = 0; j < s.jointCount(); ++j) {
        if (sets.find(j) != j)
            continue;
        ++components;
        if (j != rootComponent && !chainRootOf.contains(j))
            ++loose;
    }
    if (loose > 0) {
        problems.push_back(s.attachments().empty()
                               ? problem(MessageId::SkeletonNotConnected, components)
                               : problem(MessageId::SkeletonNotConnectedLoose, components, loose));
    }
    // Each chain up through the bones it hangs from must reach the root's.
    for (const auto& [component, joint] : chainRootOf) {
        std::set<int> seen{component};
        for (int at = component, steps = 1;; ++steps) {
            const auto chainRoot = chainRootOf.find(at);
            if (chainRoot == chainRootOf.end())
                break;  // the root's chain or a loose one (said above)
            const BoneId parent = s.attachments().at(chainRoot->second);
            if (parent == kNoBone || !s.hasBone(parent) || !s.hasJoint(s.bone(parent).head))
                break;
            at = sets.find(s.indexOfJoint(s.bone(parent).head));
            if (!seen.insert(at).second) {
                problems.push_back(problem(at == component && steps == 1
                                               ? MessageId::SkeletonHangsFromOwnChain
                                               : MessageId::SkeletonChainsHangInALoop,
                                           joint));
                break;
            }
        }
    }
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

std::vector<BoneId> Skeleton::bonesInHierarchyOrder() const {
    std::vector<BoneId> order;
    for (int b : traverseFromRoot(*this).boneOrder) {
        order.push_back(bones_[b].id);
    }
    return order;
}

std::vector<Message> Skeleton::validate() const {
    std::vector<Message> problems;
    if (joints_.empty()) {
        problems.push_back(problem(MessageId::SkeletonNoJoints));
        return problems;
    }

    std::unordered_set<JointId> seenJoints;
    Eigen::AlignedBox3d box;
    for (const Joint& j : joints_) {
        if (!seenJoints.insert(j.id).second) {
            problems.push_back(problem(MessageId::SkeletonJointIdTwice, j.id));
        }
        if (!j.position.allFinite()) {
            problems.push_back(problem(MessageId::SkeletonJointNotFinite, j.id));
        } else {
            box.extend(j.position);
        }
    }
    std::unordered_set<BoneId> seenBones;
    for (const Bone& b : bones_) {
        if (!seenBones.insert(b.id).second) {
            problems.push_back(problem(MessageId::SkeletonBoneIdTwice, b.id));
        }
    }
    if (!hasJoint(root_)) {
        problems.push_back(root_ == kNoJoint ? problem(MessageId::SkeletonNoRoot)
                                             : problem(MessageId::SkeletonRootMissing, root_));
    }

    const double zeroLength = kZeroLengthRelative * (box.isEmpty() ? 0.0 : box.diagonal().norm());
    DisjointSets sets(static_cast<std::size_t>(jointCount()));
    for (const Bone& b : bones_) {
        const bool headOk = hasJoint(b.head);
        const bool tailOk = hasJoint(b.tail);
        if (!headOk || !tailOk) {
            problems.push_back(
                problem(MessageId::SkeletonBoneMissingJoint, b.id, headOk ? b.tail : b.head));
            continue;
        }
        if (b.head == b.tail) {
            problems.push_back(problem(MessageId::SkeletonBoneJoinsItself, b.id, b.head));
            continue;
        }
        if (boneLength(b.id) <= zeroLength) {
            problems.push_back(problem(MessageId::SkeletonBoneZeroLength, b.id));
        }
        if (!sets.unite(indexOfJoint(b.head), indexOfJoint(b.tail))) {
            problems.push_back(problem(MessageId::SkeletonCycle, b.id));
        }
    }
    checkChains(*this, sets, problems);
    return problems;
}

}  // namespace rigmesh
