#include "autorig/WornPieces.h"

#include <algorithm>
#include <map>
#include <optional>
#include <set>

#include "autorig/SkeletonPieces.h"
#include "mesh/MeshChecks.h"
#include "rig/BoneSegments.h"

namespace rigmesh {

namespace {

// A worn piece's surface is at most this share of the wearing piece's.
constexpr double kLargestWornShare = 0.25;
// Worn pieces' vertices must stay within this share of the coverage
// distance, the share autorig/BoneCoverage brings a far region to (as
// autorig/HeldProps asks of a prop).
constexpr double kCoverageShare = 0.9;
// Pieces are worn in twos or threes at one limb's end (a pair of horns,
// antennae, a crest between two horns): a single piece at a limb's end
// (a glove, a shoe) is the limb's own hand or foot, and a hand whose fingers
// are pieces of their own has four or five; those are limbs.
constexpr std::size_t kFewestWornPieces = 2;
constexpr std::size_t kMostWornPieces = 3;
// Steps along the limb's last bone when finding how far the wearing piece
// reaches.
constexpr int kReachSamples = 32;

// A limb's end wearing pieces: its branches into them, and the pieces.
struct WornEnd {
    std::vector<JointId> branches;  // the joint's children
    std::vector<int> worn;          // their pieces
};

// Whether the branch from `first` is a plain chain that, from the joint
// where it enters `piece`, lies in it.
bool runsInto(const SkeletonTree& tree, JointId first, int piece, const JointPieces& inside) {
    const std::vector<JointId> chain = branchFrom(tree, first);
    if (!childrenOf(tree, chain.back()).empty())
        return false;
    bool entered = false;
    for (JointId joint : chain) {
        const bool in = inside.at(joint).contains(piece);
        if (entered && !in)
            return false;
        entered = entered || in;
    }
    return entered;
}

// The joint's branches when each runs into a worn piece of its own, small
// beside the pieces the joint lies in.
std::optional<WornEnd> wornEndAt(const SkeletonTree& tree, JointId joint, const JointPieces& inside,
                                 const std::vector<double>& areas) {
    const std::vector<JointId> children = childrenOf(tree, joint);
    const std::set<int>& wearing = inside.at(joint);
    if (children.size() < kFewestWornPieces || children.size() > kMostWornPieces ||
        tree.parent.at(joint) == kNoJoint || wearing.empty())
        return std::nullopt;
    // The joint ends its limb in the wearing pieces: of the skeleton, only
    // the chain arriving at it lies in them (a head on a neck; not a back
    // whose spine goes on, nor a body holding the root).
    const std::vector<JointId> subtree = subtreeOf(tree, joint);
    const std::set<JointId> below(subtree.begin() + 1, subtree.end());
    std::set<JointId> arriving;
    for (JointId j = tree.parent.at(joint); tree.parent.at(j) != kNoJoint; j = tree.parent.at(j))
        arriving.insert(j);
    for (const auto& [j, pieces] : inside)
        if (j != joint && !arriving.contains(j) && !below.contains(j) &&
            std::any_of(wearing.begin(), wearing.end(), [&](int p) { return pieces.contains(p); }))
            return std::nullopt;
    double wearingArea = 0.0;
    for (int p : wearing)
        wearingArea = std::max(wearingArea, areas[p]);
    WornEnd end{children, {}};
    for (JointId child : children) {
        const int piece = branchPiece(branchFrom(tree, child), inside, wearing);
        if (piece < 0 || areas[piece] > kLargestWornShare * wearingArea ||
            std::find(end.worn.begin(), end.worn.end(), piece) != end.worn.end() ||
            !runsInto(tree, child, piece, inside))
            return std::nullopt;
        end.worn.push_back(piece);
    }
    // No other branch of the skeleton enters a worn piece.
    for (const auto& [j, pieces] : inside)
        if (!below.contains(j))
            for (int p : end.worn)
                if (pieces.contains(p))
                    return std::nullopt;
    return end;
}

// The farthest point from `from` towards `target` that still lies in one of
// `wearing` (the crown of a head, towards its horns); `from` itself when
// the next step leaves them.
Vec3 reachOfWearer(const std::vector<FigurePiece>& pieces, const std::set<int>& wearing,
                   const Vec3& from, const Vec3& target) {
    Vec3 reach = from;
    for (int i = 1; i <= kReachSamples; ++i) {
        const Vec3 point = from + (target - from) * (static_cast<double>(i) / kReachSamples);
        const bool in = std::any_of(wearing.begin(), wearing.end(),
                                    [&](int p) { return liesInPiece(pieces[p], point); });
        if (!in)
            break;
        reach = point;
    }
    return reach;
}

}  // namespace

WornPiecesReport pruneWornPieces(Skeleton& skeleton, const TriMesh& mesh,
                                 const std::vector<int>& pieceOf, int pieces, double coverage) {
    WornPiecesReport report;
    if (pieces < 2 || skeleton.jointCount() < 3)
        return report;
    const std::vector<FigurePiece> meshPieces = figurePiecesOf(mesh, pieceOf, pieces);
    std::vector<double> areas;
    for (const FigurePiece& piece : meshPieces)
        areas.push_back(surfaceArea(piece.mesh));
    const JointPieces inside = jointPiecesOf(skeleton, mesh, pieceOf, meshPieces);
    const SkeletonTree tree = treeOf(skeleton);
    for (JointId joint : tree.order) {
        if (!skeleton.hasJoint(joint))
            continue;
        const std::optional<WornEnd> end = wornEndAt(tree, joint, inside, areas);
        if (!end)
            continue;
        std::vector<Vec3> wornPoints;
        Vec3 wornCentre = Vec3::Zero();
        for (int p : end->worn) {
            const std::vector<Vec3>& points = meshPieces[p].mesh.vertices;
            wornPoints.insert(wornPoints.end(), points.begin(), points.end());
            wornCentre += meshPieces[p].centroid;
        }
        wornCentre /= static_cast<double>(end->worn.size());
        Skeleton pruned = skeleton;
        for (JointId child : end->branches)
            for (JointId j : subtreeOf(tree, child))
                pruned.removeJoint(j);
        // The limb ends in a bone on towards what it wears, as far as the
        // wearing piece reaches.
        const Vec3& at = skeleton.joint(joint).position;
        const Vec3 crown = reachOfWearer(meshPieces, inside.at(joint), at, wornCentre);
        if (crown != at)
            pruned.addBone(joint, pruned.addJoint(crown));
        if (farthestFrom(wornPoints, segmentsOf(pruned)) > kCoverageShare * coverage)
            continue;
        skeleton = std::move(pruned);
        ++report.limbEnds;
        report.branchesPruned += static_cast<int>(end->branches.size());
    }
    return report;
}

}  // namespace rigmesh
