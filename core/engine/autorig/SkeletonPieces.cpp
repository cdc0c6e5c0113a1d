#include "autorig/SkeletonPieces.h"

#include <algorithm>
#include <cmath>
#include <limits>

#include "autorig/JointsInside.h"
#include "geometry/PrincipalAxes.h"

namespace rigmesh {

namespace {

// A joint is in a piece where the piece's winding number exceeds this.
constexpr double kInsideWinding = 0.5;

}  // namespace

std::vector<FigurePiece> figurePiecesOf(const TriMesh& mesh, const std::vector<int>& pieceOf,
                                        int count) {
    std::vector<FigurePiece> pieces(count);
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
    for (FigurePiece& piece : pieces) {
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

bool liesInPiece(const FigurePiece& piece, const Vec3& point) {
    return !piece.mesh.faces.empty() && piece.box.contains(point) &&
           windingNumber(piece.mesh, point) > kInsideWinding;
}

JointPieces jointPiecesOf(const Skeleton& skeleton, const TriMesh& mesh,
                          const std::vector<int>& pieceOf, const std::vector<FigurePiece>& pieces) {
    JointPieces inside;
    for (const Joint& joint : skeleton.joints()) {
        std::set<int>& in = inside[joint.id];
        for (int p = 0; p < static_cast<int>(pieces.size()); ++p)
            if (liesInPiece(pieces[p], joint.position))
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

SkeletonTree treeOf(const Skeleton& skeleton) {
    SkeletonTree tree;
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

std::vector<JointId> childrenOf(const SkeletonTree& tree, JointId joint) {
    const auto found = tree.children.find(joint);
    return found == tree.children.end() ? std::vector<JointId>{} : found->second;
}

std::vector<JointId> subtreeOf(const SkeletonTree& tree, JointId top) {
    std::vector<JointId> joints{top};
    for (std::size_t i = 0; i < joints.size(); ++i)
        for (JointId child : childrenOf(tree, joints[i]))
            joints.push_back(child);
    return joints;
}

std::vector<JointId> branchFrom(const SkeletonTree& tree, JointId first) {
    std::vector<JointId> branch{first};
    for (std::vector<JointId> next = childrenOf(tree, first); next.size() == 1;
         next = childrenOf(tree, branch.back()))
        branch.push_back(next.front());
    return branch;
}

int branchPiece(const std::vector<JointId>& branch, const JointPieces& inside,
                const std::set<int>& excluded) {
    std::map<int, int> counts;
    for (JointId joint : branch)
        for (int p : inside.at(joint))
            if (!excluded.contains(p))
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

}  // namespace rigmesh
