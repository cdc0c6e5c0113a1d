// Props held in a fist. A character often comes with what it carries (an
// axe, a staff, a sword) as separate pieces of its mesh, and the wrap makes
// one proxy of the fist and what it grips (autorig/ProxyWrap). The curve
// skeleton then runs through the grip both ways: from the hand's joint one
// branch goes to the handle's near end, below the fist, and one along the
// handle to the far end, where a flat blade may split it again at its
// corners. Each of those ends became a leaf, and the hand none.
//
// A held prop is one rigid object carried by the hand: its chain is the
// arm's own, continued from the hand along the prop to its far end (a
// weapon bone), and its other branches go, the short end below the fist and
// the corners of a blade. A branch goes only when it is the prop's (a plain
// chain from the hand into the prop, every joint from there on in the
// prop's pieces: never a joint of the body) and every vertex of the prop
// stays as near a bone of the arm's chain or the prop as the auto-rig's
// coverage asks (autorig/BoneCoverage): a staff held in its middle, whose
// lower half reaches far from the hand, keeps a bone in each half.
//
// A grip is a joint where two branches run into the same piece of the mesh
// that the chain arriving there (the arm) is not in, on opposite sides of
// the joint along that piece's main axis, the piece long and thin (a
// handle, a shaft; not a shoe under an ankle or a helmet). Pieces and the
// pieces a joint is in as autorig/SkeletonPieces gives them.
#pragma once

#include <vector>

#include "mesh/TriMesh.h"
#include "rig/Skeleton.h"

namespace rigmesh {

struct HeldPropsReport {
    int grips = 0;           // joints found gripping a prop
    int propsHeld = 0;       // of them, those whose prop became one chain
    int branchesPruned = 0;  // the props' ends and side branches removed
};

// `mesh`: the mesh the part keeps, `pieceOf` its vertices' pieces (-1 for a
// vertex no face uses), `pieces` their number. `coverage`: the farthest a
// vertex of a prop may be from every bone once a branch has gone (the
// auto-rig's coverage distance). The skeleton stays a tree with its root.
HeldPropsReport pruneHeldProps(Skeleton& skeleton, const TriMesh& mesh,
                               const std::vector<int>& pieceOf, int pieces, double coverage);

}  // namespace rigmesh
