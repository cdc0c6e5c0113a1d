// What Assimp's scene says about one mesh's bones beyond their weights:
// which bone nodes are its own, which bones only mark a leaf's tail, which
// name no node, the tails our exporter wrote into node metadata, and the
// frame Blender's COLLADA tips are in. Internal to io/: included only from
// .cpp files (it includes Assimp).
#pragma once

#include <assimp/scene.h>

#include <map>
#include <optional>
#include <set>
#include <string>
#include <vector>

#include <Eigen/Geometry>

#include "base/Types.h"
#include "io/AssimpNodeTree.h"

namespace rigmesh {

struct MeshBones {
    // The mesh's own bones by node (aiBone index): its aiBones less the bone
    // trees that belong to other meshes (Assimp 5.2.5's glTF exporter wrote
    // one skin listing every part's bones: the trees that weight this mesh,
    // and the ones that weight no mesh but start at the same joint as a kept
    // one, are its own) and less the end bones.
    std::map<int, unsigned> boneOfNode;
    // End bones (our leafBones, Blender's FBX "Add Leaf Bones"): a bone named
    // `<parent>_end` whose node is a child of its parent bone's node, with no
    // weights and no bone below it; it only marks its parent's tail. Per
    // parent bone node.
    std::map<int, unsigned> endOfParent;
    // aiBones whose name no node has (a skin naming a missing joint).
    std::vector<unsigned> nodeless;
};

// `weightedAnywhere`: the names of the bones that weight some mesh of the file.
MeshBones meshBones(const aiMesh& mesh, const Eigen::Affine3d& meshGlobal,
                    const AssimpNodeTree& tree, const std::set<std::string>& weightedAnywhere);

// Our exporter's bone tail (BoneTipHints.h) in the node's own frame, which
// Assimp reads into the node's metadata: from glTF extras as a nested list,
// from an FBX user property as a vector.
std::optional<Vec3> tailMetadata(const aiNode& node);

// The bone's own name our exporter wrote beside a node it had to name
// otherwise (BoneTipHints.h: kNameMetadataKey), if any.
std::optional<std::string> nameMetadata(const aiNode& node);

// The rotation of the space Blender's COLLADA tips are in: the armature, the
// nearest ancestor of `node` that is no bone.
template <typename BoneNodes>
Eigen::Matrix3d armatureRotation(int node, const AssimpNodeTree& tree, const BoneNodes& bones) {
    int up = tree.parent(node);
    while (up >= 0 && bones.contains(up))
        up = tree.parent(up);
    return up < 0 ? Eigen::Matrix3d::Identity() : Eigen::Matrix3d(tree.restGlobal(up).linear());
}

// A mesh's name for the user: its node's (the object a user named, e.g.
// Blender's "Capsule"), else its mesh's (e.g. "Cylinder"), else "part".
std::string meshName(const aiMesh& mesh, const aiNode& node);

// A clip's frame rate for keys at `ticks`: the first common rate (24, 25,
// 30, 48, 50, 60, 96, 100, 120, 240) that puts every key on a frame, else
// 24 doubled until no two keys share a frame.
double clipRate(const std::set<double>& ticks, double ticksPerSecond);

}  // namespace rigmesh
