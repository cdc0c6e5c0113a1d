// Limbs the proxy fused. The wrap bridges every gap narrower than about
// its alpha (autorig/ProxyWrap), so two limbs that run side by side a
// small gap apart (legs held together, shins that touch) are one limb on
// the proxy and the curve skeleton gives them one chain. The mesh itself
// still has them apart: a plane across the chain cuts it in two separate
// outlines inside the proxy's one. Where it does so along a leaf chain
// (two comparable outlines near its tip, each followed up the chain from
// plane to plane past any third, a skirt's flap, while it moves and
// changes little, at most of the planes), the chain becomes two, each
// through the middle of its own outline, from the joint where the
// outlines part. Outlines are the mesh's cut inside the proxy's outline
// around the chain (coincident vertices joined; two open ones whose ends
// pair are one loop, one inside another is one limb).
#pragma once

#include <array>
#include <vector>

#include "mesh/TriMesh.h"
#include "part/BoneWeights.h"
#include "rig/Skeleton.h"

namespace rigmesh {

struct FusedLimbsReport {
    int chainsSplit = 0;
    // Per split chain: the plane where its limbs part (the first across
    // both, facing the tips) and where the two limbs' tips were made.
    struct Split {
        Vec3 point;
        Vec3 normal;
        std::array<Vec3, 2> tips;
    };
    std::vector<Split> splits;
};

// `mesh` as the file gives it (any soup), `proxy` the closed surface the
// skeleton was made on. The skeleton stays a tree.
FusedLimbsReport splitFusedLimbs(Skeleton& skeleton, const TriMesh& mesh, const TriMesh& proxy);

// The heat, computed on the proxy where the limbs are one, gives a vertex
// of one limb weights of the other's bones. Beyond each split's plane a
// vertex of `mesh` belongs to the limb whose bones (from the leaf nearest
// its recorded tip up to the first branching joint) lie nearer, and loses
// the other limb's weights (a vertex left with none follows its own
// limb's nearest bone). The limbs' bones run through the middles of their
// own outlines, so the two sides meet in the gap between them. Returns the
// vertices changed.
int separateFusedLimbWeights(const TriMesh& mesh, const Skeleton& skeleton,
                             const FusedLimbsReport& report, WeightsById& weights);

}  // namespace rigmesh
