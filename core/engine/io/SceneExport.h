// Exporting rigged parts to glTF 2.0 (.glb, .gltf), binary FBX, COLLADA and
// OBJ through Assimp. Assimp stays inside the .cpp files.
//
// Layout (the rules Assimp 5.2.5 and Blender need are in docs/EXCHANGE.md):
// an identity root node; one node per part carrying its mesh (the part's
// name); for rigged formats each part's bones under its own armature node
// `<part>_armature` (in FBX holding the part's mesh node too; glTF gets one
// skin per part, GltfSkins.h), except in COLLADA: one `Armature` node beside
// the mesh nodes (Blender's COLLADA importer makes one armature anyway:
// AssimpSceneBuilder.cpp). One
// node per bone named after it or `<part>_bone<id>`, placed at the
// bone's head with its +Y axis along the bone (ExportRig.h) and parented by
// the bone hierarchy; optionally an end bone at each leaf's tail. Several parts are several skinned
// meshes on that one hierarchy, each bound to its own bones (Assimp 5.2.5's glTF exporter writes a
// single skin listing every bone; each mesh's weights use only its own part's bones, and
// importScene sorts them out again). Nodes are in the bind pose; each part's `pose` is used only by
// OBJ (restPose = false). Each clip with keys is an animation of its part's bones (named after
// the clip, else `<part>_clip`; one channel per bone node, keys in seconds); the clips of all
// parts with one name are one animation. Coordinates: our parts
// are y up; glTF is y up, metres, as are our FBX (UnitScaleFactor 100 = metres) and COLLADA files.
#pragma once

#include <filesystem>
#include <string>
#include <vector>

#include <Eigen/Geometry>

#include "base/StagedFile.h"
#include "part/Part.h"
#include "pose/Clip.h"
#include "pose/Pose.h"
#include "pose/Skinning.h"

namespace rigmesh {

struct ExportPart {
    const Part* part = nullptr;
    Pose pose;  // OBJ with restPose = false writes the part skinned to it
    // Rigid (rotation, translation); baked into the written positions.
    Eigen::Affine3d placement = Eigen::Affine3d::Identity();
    std::string name;  // empty: the part's own name
    // Its animation (written when it has keys and ExportOptions::animation);
    // may be null.
    const Clip* clip = nullptr;
    // Its further clips, each written as an animation too. Clips of
    // several parts with one name make one animation animating all of them.
    std::vector<const Clip*> otherClips;
};

struct ExportOptions {
    // Influences per vertex: 0 = all the format allows (4 for glTF, all for
    // FBX and COLLADA). Cut without creases (InfluenceLimit.h).
    int maxInfluences = 4;
    // Rest mesh, or each part's current pose: OBJ poses its mesh; for the
    // rigged formats model::exportDocument makes the pose the rest shape.
    bool restPose = true;
    // With restPose = false in a rigged format: keep the rest shape and write
    // each part's current pose as an animation of a single key at 0 s
    // instead of making it the rest shape (model::exportDocument).
    bool poseAsKey = false;
    // The studio's view skinning (View > Dual Quaternion Skinning): how a
    // pose is baked into written vertices (OBJ's posed mesh, the current
    // pose as the rest shape), and the skinning type an FBX's skin deformers
    // carry (io/FbxSkinningType.h; Maya reads it). glTF and COLLADA have no
    // skinning type: their importers skin linearly (Blender by default too).
    // The default is the engine's (pose/Skinning.h); the studio and the CLI
    // pass their own (linear blend unless chosen otherwise).
    SkinningMethod skinning = SkinningMethod::DualQuaternion;
    bool animation = true;   // write the clip when there is one
    double unitScale = 1.0;  // multiplies every written coordinate
    // An end bone `<bone>_end` at each leaf bone's tail (Blender's FBX "Add
    // Leaf Bones"), so that importers know the leaves' lengths too.
    bool leafBones = false;
    // Detail levels (part/PartDetail.h): Loop subdivision
    // rounds (0..4), then decimation to at most this many faces per part
    // (0: none). Skin weights are carried, the rig is unchanged.
    int subdivisionLevels = 0;
    int decimateToFaces = 0;
};

// Writes `parts` to `path` (`clip`, may be null, animates part 0 when that
// part has no clip of its own), the
// format chosen by its extension: .glb, .gltf (+ .bin beside it), .fbx, .dae,
// .obj (+ .mtl). Assimp exports into memory; every file is then written
// beside its target with every write checked and renamed into place only when
// complete (base/StagedFile.h), keeping the target's permissions, so a failure
// (a full disk) leaves the previous files as they were and no temporary file.
// Throws Error on an unknown extension, a part without mesh or weights that
// do not match it, a non-finite number to write, a missing folder, a
// read-only target or any write failure.
void exportScene(const std::vector<ExportPart>& parts, const Clip* clip, const std::string& path,
                 const ExportOptions& options = {});

// The files of one export, complete beside their targets but not in place
// yet (base/StagedFile.h): commit() renames them in an order that never
// leaves a file naming a companion that is not there (a .bin before its
// .gltf, an .mtl before its .obj), then removes the .bin the old .gltf named.
// Destroyed uncommitted, it removes them and the targets stay as they were
// (a background export the user cancelled after it was written).
class StagedExport {
  public:
    StagedExport() = default;
    StagedExport(StagedExport&&) noexcept = default;
    StagedExport& operator=(StagedExport&&) noexcept = default;

    // Throws Error when a rename fails; the files already renamed are then
    // the new ones, and no file names a missing companion.
    void commit();
    bool empty() const { return files_.empty(); }

  private:
    friend StagedExport stageScene(const std::vector<ExportPart>&, const Clip*, const std::string&,
                                   const ExportOptions&);
    std::vector<StagedFile> files_;  // in commit order
    // Removed when a later file of the set fails to commit (a new .bin whose
    // .gltf did not land).
    std::vector<std::filesystem::path> undoOnFailure_;
    // Removed after every file is in place (the .bin only the old .gltf named).
    std::vector<std::filesystem::path> obsolete_;
};

// exportScene without the final renames: everything is written and checked,
// nothing replaced until commit(). Throws Error as exportScene does.
StagedExport stageScene(const std::vector<ExportPart>& parts, const Clip* clip,
                        const std::string& path, const ExportOptions& options = {});

}  // namespace rigmesh
