#include "autorig/HeldProps.h"

#include <Eigen/Geometry>
#include <algorithm>
#include <array>
#include <limits>
#include <map>
#include <optional>
#include <set>

#include "autorig/SkeletonPieces.h"
#include "rig/BoneSegments.h"

namespace rigmesh {

namespace {

// A pruned branch's prop vertices must stay within this share of the
// coverage distance, the share autorig/BoneCoverage brings a far region to.
constexpr double kCoverageShare = 0.9;
// Points along a prop's axis tested for lying in the fist.
constexpr int kAxisSamples = 64;
// A held prop is long and thin (a handle, a shaft): a piece less elongated
// (a shoe with toe and heel, a helmet, shorts) is no prop.
constexpr double kLeastElongation = 3.0;

double reachFrom(const Skeleton& skeleton, const std::vector<JointId>& joints, const Vec3& from) {
    double reach = 0.0;
    for (JointId joint : joints)
        reach = std::max(reach, (skeleton.joint(joint).position - from).norm());
    return reach;
}

struct Grip {
    JointId hand = kNoJoint;
    std::array<JointId, 2> ends{kNoJoint, kNoJoint};  // the two children into the prop
    int piece = -1;                                   // the prop's piece they run in
};

// The first joint in breadth-first order, after `done`, where two
// branches run into one piece the arriving chain is not in, on either side
// of the joint along the piece's axis.
std::optional<Grip> findGrip(const Skeleton& skeleton, const SkeletonTree& tree,
                             const std::vector<FigurePiece>& pieces, const JointPieces& inside,
                             const std::set<JointId>& done) {
    for (JointId hand : tree.order) {
        const std::vector<JointId> children = childrenOf(tree, hand);
        const JointId arm = tree.parent.at(hand);
        if (children.size() < 2 || arm == kNoJoint || done.contains(hand))
            continue;
        const std::set<int>& armPieces = inside.at(arm);
        const Vec3& at = skeleton.joint(hand).position;
        for (std::size_t i = 0; i < children.size(); ++i) {
            const std::vector<JointId> first = branchFrom(tree, children[i]);
            const int piece = branchPiece(first, inside, armPieces);
            if (piece < 0 || pieces[piece].elongation < kLeastElongation)
                continue;
            const Vec3& axis = pieces[piece].axis;
            const double side = (skeleton.joint(first.back()).position - at).dot(axis);
            for (std::size_t j = i + 1; j < children.size(); ++j) {
                const std::vector<JointId> second = branchFrom(tree, children[j]);
                if (branchPiece(second, inside, armPieces) != piece)
                    continue;
                if (side * (skeleton.joint(second.back()).position - at).dot(axis) < 0.0)
                    return Grip{hand, {children[i], children[j]}, piece};
            }
        }
    }
    return std::nullopt;
}

// The middle of the run of the prop's axis inside the arm's pieces
// nearest `near`; none when the axis does not pass through them.
std::optional<Vec3> gripCentre(const std::vector<FigurePiece>& pieces, int prop,
                               const std::set<int>& arm, const Vec3& near) {
    const FigurePiece& piece = pieces[prop];
    double low = std::numeric_limits<double>::infinity();
    double high = -low;
    for (const Vec3& v : piece.mesh.vertices) {
        low = std::min(low, (v - piece.centroid).dot(piece.axis));
        high = std::max(high, (v - piece.centroid).dot(piece.axis));
    }
    const auto pointAt = [&](double t) { return Vec3(piece.centroid + t * piece.axis); };
    const auto held = [&](double t) {
        return std::any_of(arm.begin(), arm.end(),
                           [&](int p) { return liesInPiece(pieces[p], pointAt(t)); });
    };
    const double nearT = (near - piece.centroid).dot(piece.axis);
    std::optional<Vec3> best;
    double bestGap = std::numeric_limits<double>::infinity();
    int runStart = -1;
    for (int i = 0; i <= kAxisSamples; ++i) {
        const bool in = i < kAxisSamples && held(low + (high - low) * (i + 0.5) / kAxisSamples);
        if (in && runStart < 0)
            runStart = i;
        if (!in && runStart >= 0) {
            const double from = low + (high - low) * runStart / kAxisSamples;
            const double to = low + (high - low) * i / kAxisSamples;
            const double gap = nearT < from ? from - nearT : nearT > to ? nearT - to : 0.0;
            if (gap < bestGap) {
                bestGap = gap;
                best = pointAt(0.5 * (from + to));
            }
            runStart = -1;
        }
    }
    return best;
}

// The skeleton's bones that carry a prop held at `hand`: those of the
// chain from the root to the hand and those below the hand.
std::vector<BoneSegment> carryingBones(const Skeleton& skeleton, JointId hand) {
    const SkeletonTree tree = treeOf(skeleton);
    std::set<JointId> carrying;
    for (JointId joint : subtreeOf(tree, hand))
        carrying.insert(joint);
    for (JointId joint = tree.parent.at(hand); joint != kNoJoint; joint = tree.parent.at(joint))
        carrying.insert(joint);
    std::vector<BoneSegment> bones;
    for (const Bone& bone : skeleton.bones())
        if (carrying.contains(bone.head) && carrying.contains(bone.tail))
            bones.push_back(segmentOf(skeleton, bone));
    return bones;
}

// What a removal may take and must keep covered.
struct Prop {
    std::set<int> pieces;      // the prop's pieces
    std::vector<Vec3> points;  // the prop's vertices
};

// Removes `subtree` (breadth first from its top) when it is the prop's:
// a plain chain from its top until it enters the prop (the stretch in the
// fist), every joint from there on in the prop's pieces, and when the
// prop's points stay covered by the bones that carry it.
bool pruneIfCovered(Skeleton& skeleton, const SkeletonTree& tree,
                    const std::vector<JointId>& subtree, const Prop& prop,
                    const JointPieces& inside, JointId hand, double coverage) {
    const auto inProp = [&](JointId joint) {
        const std::set<int>& in = inside.at(joint);
        return std::any_of(in.begin(), in.end(), [&](int p) { return prop.pieces.contains(p); });
    };
    JointId entry = subtree.front();
    while (!inProp(entry)) {
        const std::vector<JointId> next = childrenOf(tree, entry);
        if (next.size() != 1)
            return false;
        entry = next.front();
    }
    for (JointId joint : subtreeOf(tree, entry))
        if (!inProp(joint))
            return false;
    Skeleton pruned = skeleton;
    for (JointId joint : subtree)
        pruned.removeJoint(joint);
    if (farthestFrom(prop.points, carryingBones(pruned, hand)) > kCoverageShare * coverage)
        return false;
    skeleton = std::move(pruned);
    return true;
}

}  // namespace

HeldPropsReport pruneHeldProps(Skeleton& skeleton, const TriMesh& mesh,
                               const std::vector<int>& pieceOf, int pieces, double coverage) {
    HeldPropsReport report;
    if (pieces < 2 || skeleton.jointCount() < 4)
        return report;
    const std::vector<FigurePiece> meshPieces = figurePiecesOf(mesh, pieceOf, pieces);
    const JointPieces inside = jointPiecesOf(skeleton, mesh, pieceOf, meshPieces);
    std::set<JointId> done;
    while (true) {
        const SkeletonTree tree = treeOf(skeleton);
        const std::optional<Grip> grip = findGrip(skeleton, tree, meshPieces, inside, done);
        if (!grip)
            break;
        ++report.grips;
        const JointId arm = tree.parent.at(grip->hand);
        // The prop: every piece its branches run in, but the arm's.
        std::array<std::vector<JointId>, 2> subtrees{subtreeOf(tree, grip->ends[0]),
                                                     subtreeOf(tree, grip->ends[1])};
        done.insert(grip->hand);
        for (const std::vector<JointId>& subtree : subtrees)
            done.insert(subtree.begin(), subtree.end());
        Prop prop;
        const std::set<int>& armPieces = inside.at(arm);
        for (const std::vector<JointId>& subtree : subtrees)
            for (JointId joint : subtree)
                for (int p : inside.at(joint))
                    if (!armPieces.contains(p))
                        prop.pieces.insert(p);
        for (int p : prop.pieces)
            prop.points.insert(prop.points.end(), meshPieces[p].mesh.vertices.begin(),
                               meshPieces[p].mesh.vertices.end());
        // The hand's joint is the grip's pivot: the middle of the stretch
        // of the prop's axis that the fist holds (the arm's pieces or the
        // hand's own), the run nearest the joint.
        std::set<int> fist = armPieces;
        fist.insert(inside.at(grip->hand).begin(), inside.at(grip->hand).end());
        fist.erase(grip->piece);
        const Vec3 flowHand = skeleton.joint(grip->hand).position;
        const Vec3 pivot = gripCentre(meshPieces, grip->piece, fist, flowHand).value_or(flowHand);
        // The prop's short end (below the fist) goes first; the chain runs
        // on to the far end.
        const bool firstFarther =
            reachFrom(skeleton, subtrees[0], pivot) >= reachFrom(skeleton, subtrees[1], pivot);
        const std::vector<JointId>& shortEnd = subtrees[firstFarther ? 1 : 0];
        const JointId farEnd = grip->ends[firstFarther ? 0 : 1];
        skeleton.setJointPosition(grip->hand, pivot);
        if (!pruneIfCovered(skeleton, tree, shortEnd, prop, inside, grip->hand, coverage)) {
            // No grip after all: the skeleton stays as the flow made it.
            skeleton.setJointPosition(grip->hand, flowHand);
            continue;
        }
        ++report.propsHeld;
        ++report.branchesPruned;
        // Beyond the hand the prop is one chain: at each junction the
        // branch reaching farthest from the hand stays.
        for (JointId junction : subtreeOf(tree, farEnd)) {
            if (!skeleton.hasJoint(junction))
                continue;
            std::vector<JointId> children = childrenOf(tree, junction);
            if (children.size() < 2)
                continue;
            std::sort(children.begin(), children.end(), [&](JointId a, JointId b) {
                return reachFrom(skeleton, subtreeOf(tree, a), pivot) >
                       reachFrom(skeleton, subtreeOf(tree, b), pivot);
            });
            for (std::size_t i = 1; i < children.size(); ++i)
                if (pruneIfCovered(skeleton, tree, subtreeOf(tree, children[i]), prop, inside,
                                   grip->hand, coverage))
                    ++report.branchesPruned;
        }
    }
    return report;
}

}  // namespace rigmesh
