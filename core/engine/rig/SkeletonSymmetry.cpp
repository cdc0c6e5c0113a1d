#include "rig/SkeletonSymmetry.h"

#include <algorithm>
#include <cmath>
#include <limits>
#include <map>
#include <set>
#include <vector>

namespace rigmesh {

namespace {

// A run of joints from a node to the next through joints of two bones; the
// nodes are the junctions, the tips and the joints on the mirror plane
// (where a chain crosses the middle: the root of a V, a spine's joints).
using Branch = std::vector<JointId>;
using Nodes = std::set<JointId>;

Nodes nodesOf(const Skeleton& skeleton, const MirrorPlane& plane, double tolerance) {
    Nodes nodes;
    for (const Joint& joint : skeleton.joints())
        if (skeleton.degree(joint.id) != 2 ||
            std::abs(plane.normal.dot(joint.position - plane.point)) <= 0.5 * tolerance)
            nodes.insert(joint.id);
    return nodes;
}

JointId otherEnd(const Skeleton& skeleton, BoneId bone, JointId joint) {
    const Bone& b = skeleton.bone(bone);
    return b.head == joint ? b.tail : b.head;
}

std::vector<Branch> branchesOf(const Skeleton& skeleton, const Nodes& nodes) {
    std::vector<Branch> branches;
    std::map<BoneId, bool> walked;
    for (const Joint& node : skeleton.joints()) {
        if (!nodes.contains(node.id))
            continue;
        for (BoneId first : skeleton.bonesAt(node.id)) {
            if (walked[first])
                continue;
            Branch branch{node.id};
            BoneId bone = first;
            JointId at = node.id;
            while (true) {
                walked[bone] = true;
                at = otherEnd(skeleton, bone, at);
                branch.push_back(at);
                if (nodes.contains(at))
                    break;
                for (BoneId next : skeleton.bonesAt(at))
                    if (next != bone) {
                        bone = next;
                        break;
                    }
            }
            branches.push_back(std::move(branch));
        }
    }
    return branches;
}

BoneId boneBetween(const Skeleton& skeleton, JointId a, JointId b) {
    for (BoneId bone : skeleton.bonesAt(a))
        if (otherEnd(skeleton, bone, a) == b)
            return bone;
    return std::numeric_limits<BoneId>::max();
}

// The nodes paired with the node nearest their reflection, when that
// pairing is mutual and within `tolerance`.
std::map<JointId, JointId> nodeImages(const Skeleton& skeleton, const Nodes& nodes,
                                      const MirrorPlane& plane, double tolerance) {
    auto nearestNode = [&](const Vec3& p) {
        JointId best = kNoJoint;
        double bestDistance = std::numeric_limits<double>::infinity();
        for (JointId n : nodes) {
            const double d = (skeleton.joint(n).position - p).norm();
            if (d < bestDistance) {
                bestDistance = d;
                best = n;
            }
        }
        return std::pair{best, bestDistance};
    };
    std::map<JointId, JointId> images;
    for (JointId n : nodes) {
        const auto [image, d] = nearestNode(plane.reflect(skeleton.joint(n).position));
        if (image != kNoJoint && d <= tolerance &&
            nearestNode(plane.reflect(skeleton.joint(image).position)).first == n)
            images[n] = image;
    }
    return images;
}

// Each branch's mirror image among the branches (its index, and whether it
// runs the other way), if its ends have images joined by a branch.
struct BranchImage {
    int branch = -1;
    bool reversed = false;
};

std::vector<BranchImage> branchImages(const std::vector<Branch>& branches,
                                      const std::map<JointId, JointId>& nodes) {
    std::map<std::pair<JointId, JointId>, int> byEnds;
    for (int i = 0; i < static_cast<int>(branches.size()); ++i)
        byEnds[{branches[i].front(), branches[i].back()}] = i;
    std::vector<BranchImage> images(branches.size());
    for (int i = 0; i < static_cast<int>(branches.size()); ++i) {
        auto a = nodes.find(branches[i].front()), b = nodes.find(branches[i].back());
        if (a == nodes.end() || b == nodes.end())
            continue;
        if (auto same = byEnds.find({a->second, b->second}); same != byEnds.end())
            images[i] = {same->second, false};
        else if (auto other = byEnds.find({b->second, a->second}); other != byEnds.end())
            images[i] = {other->second, true};
    }
    return images;
}

std::vector<JointId> interiorOf(const Branch& branch, bool reversed) {
    std::vector<JointId> inner(branch.begin() + 1, branch.end() - 1);
    if (reversed)
        std::reverse(inner.begin(), inner.end());
    return inner;
}

// Splits the longest bones of `branch` until it has `count` inner joints.
void splitToCount(Skeleton& skeleton, const Branch& branch, int count,
                  std::vector<BoneSplit>& splits) {
    std::vector<BoneId> bones;
    for (std::size_t k = 0; k + 1 < branch.size(); ++k)
        bones.push_back(boneBetween(skeleton, branch[k], branch[k + 1]));
    int added = 0;
    while (static_cast<int>(branch.size()) - 2 + added < count) {
        auto longest = std::max_element(bones.begin(), bones.end(), [&](BoneId x, BoneId y) {
            return skeleton.boneLength(x) < skeleton.boneLength(y);
        });
        const Bone& bone = skeleton.bone(*longest);
        const BoneId split = bone.id;
        const JointId middle = skeleton.splitBone(
            split, 0.5 * (skeleton.joint(bone.head).position + skeleton.joint(bone.tail).position));
        for (BoneId b : skeleton.bonesAt(middle))
            if (std::find(bones.begin(), bones.end(), b) == bones.end()) {
                bones.push_back(b);
                splits.push_back({split, b, middle});
            }
        ++added;
    }
}

}  // namespace

SymmetrizeReport symmetrizeSkeleton(Skeleton& skeleton, const TriMesh& mesh,
                                    const SymmetrizeOptions& options) {
    SymmetrizeReport report;
    if (skeleton.boneCount() == 0)
        return report;
    report.mirror = findMirrorPlane(mesh, options.search);
    if (!report.mirror)
        return report;
    const MirrorPlane& plane = report.mirror->plane;
    Eigen::AlignedBox3d box;
    for (const Vec3& v : mesh.vertices)
        box.extend(v);
    const double tolerance = mirrorJointTolerance(skeleton, *report.mirror, box.diagonal().norm());
    const Nodes nodeSet = nodesOf(skeleton, plane, tolerance);
    const std::map<JointId, JointId> nodes = nodeImages(skeleton, nodeSet, plane, tolerance);

    std::vector<Branch> branches = branchesOf(skeleton, nodeSet);
    if (options.matchJointCounts) {
        const std::vector<BranchImage> images = branchImages(branches, nodes);
        for (int i = 0; i < static_cast<int>(branches.size()); ++i) {
            const int j = images[i].branch;
            if (j <= i)
                continue;
            const int mine = static_cast<int>(branches[i].size()) - 2;
            const int theirs = static_cast<int>(branches[j].size()) - 2;
            if (mine < theirs)
                splitToCount(skeleton, branches[i], theirs, report.splits);
            else if (theirs < mine)
                splitToCount(skeleton, branches[j], mine, report.splits);
        }
        if (report.jointsAdded() > 0)
            branches = branchesOf(skeleton, nodeSet);  // new joints are never nodes
    }

    // Every joint paired with its image: the pair moved to the mean of one
    // and the other's reflection, a joint its own image onto the plane.
    std::map<JointId, JointId> images = nodes;
    const std::vector<BranchImage> branchImage = branchImages(branches, nodes);
    for (int i = 0; i < static_cast<int>(branches.size()); ++i) {
        const BranchImage& image = branchImage[i];
        if (image.branch < 0)
            continue;
        const std::vector<JointId> mine = interiorOf(branches[i], false);
        const std::vector<JointId> theirs = interiorOf(branches[image.branch], image.reversed);
        if (mine.size() != theirs.size())
            continue;  // left as it is (joint counts not matched)
        for (std::size_t k = 0; k < mine.size(); ++k)
            images[mine[k]] = theirs[k];
    }
    std::map<JointId, Vec3> moved;
    for (const auto& [joint, image] : images) {
        if (images.count(image) == 0 || images.at(image) != joint)
            continue;  // not mutual
        const Vec3 p = skeleton.joint(joint).position;
        if (image == joint) {
            moved[joint] = p - plane.normal * plane.normal.dot(p - plane.point);
            ++report.jointsOnPlane;
        } else {
            moved[joint] = 0.5 * (p + plane.reflect(skeleton.joint(image).position));
            ++report.pairedJoints;
        }
    }
    for (const auto& [joint, position] : moved)
        skeleton.setJointPosition(joint, position);
    return report;
}

}  // namespace rigmesh
