// The mesh's own pieces and the skeleton as a tree hanging from its root,
// as the auto-rig's steps that look at which piece a joint lies in see them
// (autorig/HeldProps: a prop gripped in a fist; autorig/WornPieces: pieces
// worn at a limb's end). Pieces are the mesh's own (faces connected over
// coincident vertices, autorig/RigSurface); a joint is in a piece when the
// piece's winding number there is over a half, or, in none, in the piece
// of its nearest vertex (the proxy is fatter than the mesh, and the flow's
// joints lie in the proxy).
#pragma once

#include <Eigen/Geometry>
#include <map>
#include <set>
#include <vector>

#include "mesh/TriMesh.h"
#include "rig/BoneSegment.h"
#include "rig/Skeleton.h"

namespace rigmesh {

// One piece of the mesh, with its own faces and vertices.
struct FigurePiece {
    TriMesh mesh;  // compact: only the piece's vertices
    Eigen::AlignedBox3d box;
    Vec3 centroid = Vec3::Zero();
    Vec3 axis = Vec3::UnitX();  // the main direction of its vertices
    // The spread along the axis over the spread across it (standard
    // deviations): a shaft 7 radii long has 3.
    double elongation = 0.0;
};

// `pieceOf`: each vertex's piece (-1 for a vertex no face uses), `count`
// their number.
std::vector<FigurePiece> figurePiecesOf(const TriMesh& mesh, const std::vector<int>& pieceOf,
                                        int count);

// Whether `point` lies in `piece`: inside its box, and its winding number
// there over a half.
bool liesInPiece(const FigurePiece& piece, const Vec3& point);

// The pieces each joint lies in (never none while the mesh has a vertex in
// a piece).
using JointPieces = std::map<JointId, std::set<int>>;
JointPieces jointPiecesOf(const Skeleton& skeleton, const TriMesh& mesh,
                          const std::vector<int>& pieceOf, const std::vector<FigurePiece>& pieces);

// The skeleton as a tree hanging from its root.
struct SkeletonTree {
    std::map<JointId, JointId> parent;  // kNoJoint for the root
    std::map<JointId, std::vector<JointId>> children;
    std::vector<JointId> order;  // breadth first from the root
};

SkeletonTree treeOf(const Skeleton& skeleton);
std::vector<JointId> childrenOf(const SkeletonTree& tree, JointId joint);
// `top` and every joint below it, breadth first.
std::vector<JointId> subtreeOf(const SkeletonTree& tree, JointId top);
// From `first` down to the next junction or leaf, both included.
std::vector<JointId> branchFrom(const SkeletonTree& tree, JointId first);

// The piece a branch runs in, outside `excluded`: the one holding most of
// its joints, at least half of them; -1 for none.
int branchPiece(const std::vector<JointId>& branch, const JointPieces& inside,
                const std::set<int>& excluded);

// The largest distance from a point to its nearest bone.
double farthestFrom(const std::vector<Vec3>& points, const std::vector<BoneSegment>& bones);

}  // namespace rigmesh
