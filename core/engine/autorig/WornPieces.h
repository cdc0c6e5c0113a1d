// Pieces worn at a limb's end. A figure's head often wears what its
// modeller made apart from it: the horns of a helmet, a crest, a feather in
// a hat. The curve skeleton runs from the middle of the head into each
// such piece, so the neck's chain ends in a fork whose branches are those
// pieces, each a leaf, and the head itself ends in none (the dwarf of
// assimp-testmodels: its helmet's two horns were leaves, 6 where a person
// counts 5).
//
// A worn piece rides on what wears it: at a joint (not the root) where
// every branch on is a plain chain to a leaf that runs from the joint into
// a piece of its own (each joint from the one where it enters that piece
// on lies in it, and no other branch enters it), two or three of them, the
// joint lies in pieces none of those is, only the chain arriving at it lies
// in them (not the root), and each such piece is small beside the piece
// the joint lies in (its surface a quarter of that one's or less), the
// branches go and the limb ends in one bone from the joint on towards the
// worn pieces, as far as the wearing piece reaches (a head bone up to the
// crown). Only where the worn pieces' vertices stay as near a bone as the
// auto-rig's coverage asks (autorig/BoneCoverage): else the skeleton stays
// as it was. Limbs that are pieces of their own on a body (the spider's
// legs, arms of crossing primitives) leave from joints the body's chain
// goes on from, a glove or a shoe is one piece at its limb's end, and a
// hand's separate fingers are four or five: none of them is worn.
//
// Pieces and the pieces a joint is in as autorig/SkeletonPieces gives them.
#pragma once

#include <vector>

#include "mesh/TriMesh.h"
#include "rig/Skeleton.h"

namespace rigmesh {

struct WornPiecesReport {
    int limbEnds = 0;        // joints whose branches were worn pieces
    int branchesPruned = 0;  // those branches
};

// `mesh`: the mesh the part keeps, `pieceOf` its vertices' pieces (-1 for a
// vertex no face uses), `pieces` their number. `coverage`: the farthest a
// worn piece's vertex may be from every bone once its branch has gone.
// The skeleton stays a tree with its root.
WornPiecesReport pruneWornPieces(Skeleton& skeleton, const TriMesh& mesh,
                                 const std::vector<int>& pieceOf, int pieces, double coverage);

}  // namespace rigmesh
