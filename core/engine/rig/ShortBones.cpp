#include "rig/ShortBones.h"

#include "mesh/MeshAdjacency.h"

namespace rigmesh {

double minimumBoneLength(const TriMesh& mesh) {
    return minimumBoneLength(meanEdgeLength(mesh));  // 0 without faces
}

double minimumBoneLength(double meanEdgeLength) {
    return 0.5 * meanEdgeLength;
}

std::optional<ShortestBone> shortestBone(const Skeleton& skeleton) {
    std::optional<ShortestBone> shortest;
    for (const Bone& bone : skeleton.bones()) {
        const double length = skeleton.boneLength(bone.id);
        if (!shortest || length < shortest->length)
            shortest = ShortestBone{bone.id, length};
    }
    return shortest;
}

int collapseShortBones(Skeleton& skeleton, double minimum) {
    int collapsed = 0;
    while (skeleton.boneCount() > 1) {
        const std::optional<ShortestBone> shortest = shortestBone(skeleton);
        if (!shortest || shortest->length >= minimum)
            break;
        const Bone bone = skeleton.bone(shortest->bone);
        const Vec3 head = skeleton.joint(bone.head).position;
        const Vec3 tail = skeleton.joint(bone.tail).position;
        // collapseBone keeps the head's id at the given place: the end that
        // stays is the one with other bones (both: the middle).
        const bool headIsLeaf = skeleton.degree(bone.head) == 1;
        const bool tailIsLeaf = skeleton.degree(bone.tail) == 1;
        const Vec3 place = tailIsLeaf ? head : headIsLeaf ? tail : 0.5 * (head + tail);
        skeleton.collapseBone(bone.id, place);
        ++collapsed;
    }
    if (collapsed > 0) {
        // The root stays where the caller put it (the auto-rig's is the
        // thickest junction, autorig/SkeletonFromCurve; the joint a graph's
        // centre gives can lie in a long prop, the dwarf's axe-holding
        // hand), unless it was left a leaf.
        if (skeleton.degree(skeleton.root()) < 2)
            skeleton.setRoot(chooseCentralRoot(skeleton));
        skeleton.reorient();
    }
    return collapsed;
}

}  // namespace rigmesh
