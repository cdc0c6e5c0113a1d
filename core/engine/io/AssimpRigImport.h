// Skeleton, skin weights and clip of one imported skinned mesh (the
// rules are in SceneImport.h). Internal to io/: included only
// from .cpp files (it includes Assimp).
#pragma once

#include <assimp/scene.h>

#include <map>
#include <optional>
#include <set>
#include <string>

#include "io/AssimpNodeTree.h"
#include "io/SceneImport.h"

namespace rigmesh {

// Fills part.part.skeleton, part.part.weights and part.boneNames from `mesh`'s
// bones. `meshGlobal` maps the mesh's space to the world (where the part's
// vertices already are). `weightedAnywhere`: the names of the bones that
// weight some mesh of the file (to tell the part's bones from others'). Returns an empty string, or
// why the part still needs a rig (a bone without node, a skeleton that is not one tree).
// `colladaTips`: Blender's tips by joint name (BoneTipHints.h), if any.
std::string importRig(const aiMesh& mesh, const Eigen::Affine3d& meshGlobal,
                      const AssimpNodeTree& tree, const std::set<std::string>& weightedAnywhere,
                      const std::map<std::string, Vec3>& colladaTips, ImportedPart& part);

// The animation as a clip of `part` (imported by importRig from `mesh`), or
// nothing when it moves none of the part's bones.
std::optional<Clip> importClip(const aiAnimation& animation, const aiMesh& mesh,
                               const Eigen::Affine3d& meshGlobal, const AssimpNodeTree& tree,
                               const ImportedPart& part);

}  // namespace rigmesh
