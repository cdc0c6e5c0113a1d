#include "autorig/HeldProps.h"

#include <Eigen/Geometry>
#include <algorithm>
#include <array>
#include <limits>
#include <map>
#include <optional>
#include <set>

#include "autorig/JointsInside.h"
#include "geometry/PrincipalAxes.h"
#include "rig/BoneSegments.h"

namespace rigmesh {

namespace {

// A joint is in a piece where the piece's winding number exceeds this.
constexpr double kInsideWinding = 0.5;
// A pruned branch's prop vertices must stay within this share of the
// coverage distance, the share autorig/BoneCoverage brings a far region to.
constexpr double kCoverageShare = 0.9;
// Points along a prop's axis tested for lying in the fist.
constexpr int kAxisSamples = 64;
// A held prop is long and thin (a handle, a shaft): a piece less elongated
// (a shoe with toe and heel, a helmet, shorts) is no prop.
constexpr double kLeastElongation = 3.0;

// The mesh's pieces, each with its own faces and vertices.
struct Piece {
    TriMesh mesh;  // compact: only the piece's vertices
    Eigen::AlignedBox3d box;
    Vec3 centroid = Vec3::Zero();
    Vec3 axis = Vec3::UnitX();  // the main direction of its vertices
    // The spread along the axis over the spread across it (standard
    // deviations): a shaft 7 radii long has 3.
    double elongation = 0.0;
};

std::vector<Piece> piecesOf(const TriMesh& mesh, const std::vector<int>& pieceOf, int count) {
    std::vector<Piece> pieces(count);
    std::vector<int> local(mesh.vertices.size(), -1);
    for (std::size_t v = 0; v < mesh.vertices.size(); ++v) {
        const int p = pieceOf[v];
        if (p < 0)
            continue;
        local[v] = pieces[p].mesh.vertexCount();
        pieces[p].mesh.vertices.push_back(mesh.vertices[v]);
        pieces[p].box.extend(mesh.vertices[v]);
    }
    for (const auto& [a, b, c] : mesh.faces)
        if (pieceOf[a] >= 0 && pieceOf[a] == pieceOf[b] && pieceOf[a] == pieceOf[c])
            pieces[pieceOf[a]].mesh.faces.push_back({local[a], local[b], local[c]});
    for (Piece& piece : pieces) {
        const std::vector<Vec3>& points = piece.mesh.vertices;
        if (points.empty())
            continue;
        // Eigenvalues come in increasing order: the last vector is the axis.
        const PrincipalAxes principal = principalAxesOf(points);
        const auto& solver = principal.scatter;
        piece.centroid = principal.centroid;
        piece.axis = solver.eigenvectors().col(2);
        const double across = std::max(solver.eigenvalues()(1), 0.0);
        piece.elongation = across > 0.0 ? std::sqrt(solver.eigenvalues()(2) / across)
                                        : std::numeric_limits<double>::infinity();
    }
    return pieces;
}

// The pieces each joint lies in; for a joint in none (the proxy is
// fatter than the mesh, and the flow's joints lie in the proxy), the piece
// of the nearest vertex.
std::map<JointId, std::set<int>> jointPieces(const Skeleton& skeleton, const TriMesh& mesh,
                                             const std::vector<int>& pieceOf,
                                             const std::vector<Piece>& pieces) {
    std::map<JointId, std::set<int>> inside;
    for (const Joint& joint : skeleton.joints()) {
        std::set<int>& in = inside[joint.id];
        for (int p = 0; p < static_cast<int>(pieces.size()); ++p)
            if (!pieces[p].mesh.faces.empty() && pieces[p].box.contains(joint.position) &&
                windingNumber(pieces[p].mesh, joint.position) > kInsideWinding)
                in.insert(p);
        if (!in.empty())
            continue;
        int nearest = -1;
        double nearestDistance = std::numeric_limits<double>::infinity();
        for (std::size_t v = 0; v < mesh.vertices.size(); ++v) {
            const double d = (mesh.vertices[v] - joint.position).squaredNorm();
            if (pieceOf[v] >= 0 && d < nearestDistance) {
                nearestDistance = d;
                nearest = pieceOf[v];
            }
        }
        if (nearest >= 0)
            in.insert(nearest);
    }
    return inside;
}

// The skeleton as a tree hanging from its root.
struct Tree {
    std::map<JointId, JointId> parent;  // kNoJoint for the root
    std::map<JointId, std::vector<JointId>> children;
    std::vector<JointId> order;  // breadth first from the root
};

Tree treeOf(const Skeleton& skeleton) {
    Tree tree;
    tree.parent[skeleton.root()] = kNoJoint;
    tree.order.push_back(skeleton.root());
    for (std::size_t i = 0; i < tree.order.size(); ++i) {
        const JointId here = tree.order[i];
        for (BoneId bone : skeleton.bonesAt(here)) {
            const Bone& b = skeleton.bone(bone);
            const JointId next = b.head == here ? b.tail : b.head;
            if (tree.parent.contains(next))
                continue;
            tree.parent[next] = here;
            tree.children[here].push_back(next);
            tree.order.push_back(next);
        }
    }
    return tree;
}

std::vector<JointId> childrenOf(const Tree& tree, JointId joint) {
    const auto found = tree.children.find(joint);
    return found == tree.children.end() ? std::vector<JointId>{} : found->second;
}

// `top` and every joint below it.
std::vector<JointId> subtreeOf(const Tree& tree, JointId top) {
    std::vector<JointId> joints{top};
    for (std::size_t i = 0; i < joints.size(); ++i)
        for (JointId child : childrenOf(tree, joints[i]))
            joints.push_back(child);
    return joints;
}

// From `first` down to the next junction or leaf, both included.
std::vector<JointId> branchFrom(const Tree& tree, JointId first) {
    std::vector<JointId> branch{first};
    for (std::vector<JointId> next = childrenOf(tree, first); next.size() == 1;
         next = childrenOf(tree, branch.back()))
        branch.push_back(next.front());
    return branch;
}

double reachFrom(const Skeleton& skeleton, const std::vector<JointId>& joints, const Vec3& from) {
    double reach = 0.0;
    for (JointId joint : joints)
        reach = std::max(reach, (skeleton.joint(joint).position - from).norm());
    return reach;
}

// The piece a branch runs in, outside `armPieces`: the one holding most
// of its joints, at least half of them; -1 for none.
int branchPiece(const std::vector<JointId>& branch, const std::map<JointId, std::set<int>>& inside,
                const std::set<int>& armPieces) {
    std::map<int, int> counts;
    for (JointId joint : branch)
        for (int p : inside.at(joint))
            if (!armPieces.contains(p))
                ++counts[p];
    int best = -1;
    int most = 0;
    for (const auto& [p, count] : counts)
        if (count > most) {
            best = p;
            most = count;
        }
    return 2 * most >= static_cast<int>(branch.size()) ? best : -1;
}

struct Grip {
    JointId hand = kNoJoint;
    std::array<JointId, 2> ends{kNoJoint, kNoJoint};  // the two children into the prop
    int piece = -1;                                   // the prop's piece they run in
};

// The first joint in breadth-first order, after `done`, where two
// branches run into one piece the arriving chain is not in, on either side
// of the joint along the piece's axis.
std::optional<Grip> findGrip(const Skeleton& skeleton, const Tree& tree,
                             const std::vector<Piece>& pieces,
                             const std::map<JointId, std::set<int>>& inside,
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
std::optional<Vec3> gripCentre(const std::vector<Piece>& pieces, int prop, const std::set<int>& arm,
                               const Vec3& near) {
    const Piece& piece = pieces[prop];
    double low = std::numeric_limits<double>::infinity();
    double high = -low;
    for (const Vec3& v : piece.mesh.vertices) {
        low = std::min(low, (v - piece.centroid).dot(piece.axis));
        high = std::max(high, (v - piece.centroid).dot(piece.axis));
    }
    const auto pointAt = [&](double t) { return Vec3(piece.centroid + t * piece.axis); };
    const auto held = [&](double t) {
        return std::any_of(arm.begin(), arm.end(), [&](int p) {
            return pieces[p].box.contains(pointAt(t)) &&
                   windingNumber(pieces[p].mesh, pointAt(t)) > kInsideWinding;
        });
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
    const Tree tree = treeOf(skeleton);
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

double farthestFrom(const std::vector<Vec3>& points, const std::vector<BoneSegment>& bones) {
    double farthest = 0.0;
    for (const Vec3& p : points) {
        double nearest = std::numeric_limits<double>::infinity();
        for (const BoneSegment& bone : bones)
            nearest = std::min(nearest, pointSegmentDistance(p, bone));
        farthest = std::max(farthest, nearest);
    }
    return farthest;
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
bool pruneIfCovered(Skeleton& skeleton, const Tree& tree, const std::vector<JointId>& subtree,
                    const Prop& prop, const std::map<JointId, std::set<int>>& inside, JointId hand,
                    double coverage) {
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
    const std::vector<Piece> meshPieces = piecesOf(mesh, pieceOf, pieces);
    const std::map<JointId, std::set<int>> inside =
        jointPieces(skeleton, mesh, pieceOf, meshPieces);
    std::set<JointId> done;
    while (true) {
        const Tree tree = treeOf(skeleton);
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
