// Skeleton, skin weights and clips of the skinned meshes that share one
// skeleton (the rules are in SceneImport.h). Internal to io/: included only
// from .cpp files (it includes Assimp).
#pragma once

#include <assimp/scene.h>

#include <map>
#include <optional>
#include <set>
#include <string>
#include <vector>

#include "io/AssimpNodeTree.h"
#include "io/SceneImport.h"

namespace rigmesh {

// A mesh instance to import and where its vertices are in the world.
struct SkinnedMesh {
    unsigned mesh = 0;
    int node = -1;
    Eigen::Affine3d global = Eigen::Affine3d::Identity();
};

// What the file says beyond Assimp's scene: Blender's COLLADA tips and
// `connect` flags by joint name (BoneTipHints.h), if any.
struct RigHints {
    std::map<std::string, Vec3> colladaTips;
    // Our exporter's exact tips where Blender's are shown inside the surface
    // (ExportBoneNode::shownTail).
    std::map<std::string, Vec3> colladaExactTips;
    std::map<std::string, bool> colladaConnections;
    // Our exporter's bone names where a joint had to be named otherwise.
    std::map<std::string, std::string> colladaNames;
    // The nodes the file's animations move (by name).
    std::set<std::string> animatedNodes;
};

// Per bone of an imported part (skeleton.bones() order): its node (-1: a
// bone the file names without a node) and its world bind transform.
struct ImportedBones {
    std::vector<int> nodes;
    std::vector<Eigen::Affine3d> binds;
};

// Triangles only (points and lines are left out, and so are triangles that
// repeat a corner: they show nothing), vertices in world space.
TriMesh worldMesh(const aiMesh& mesh, const Eigen::Affine3d& global);

// The meshes grouped by the skeleton they share: two meshes share one when
// a bone node of one and a bone node of the other hang from one topmost
// bone node (in order of each group's first mesh). A bone node's ancestors
// that the file animates count as bones too (a Half-Life model's root and
// pelvis weight no vertex, so no mesh names them, yet carry the legs and
// the spine). `weightedAnywhere`: the names of the bones that weight some
// mesh of the file (AssimpBoneHints.h).
std::vector<std::vector<SkinnedMesh>> groupBySkeleton(const aiScene& scene,
                                                      const AssimpNodeTree& tree,
                                                      const std::vector<SkinnedMesh>& meshes,
                                                      const std::set<std::string>& weightedAnywhere,
                                                      const RigHints& hints);

// Fills part.part (mesh of every mesh of the group, in order, as pieces when
// there are several; skeleton; weights; bone frames) and part.boneNames.
// Returns an empty string, or why the part still needs a rig.
std::string importRig(const aiScene& scene, const std::vector<SkinnedMesh>& group,
                      const AssimpNodeTree& tree, const std::set<std::string>& weightedAnywhere,
                      const RigHints& hints, ImportedPart& part, ImportedBones& bones);

// The animation as a clip of `part` (its bones as importRig gave them), or
// nothing when it moves none of them. Keys at the file's key times.
std::optional<Clip> importClip(const aiAnimation& animation, const AssimpNodeTree& tree,
                               const ImportedPart& part, const ImportedBones& bones);

}  // namespace rigmesh
