#include "io/SceneExport.h"

#include <assimp/postprocess.h>
#include <assimp/scene.h>
#include <assimp/Exporter.hpp>

#include <cstdint>
#include <cstdio>
#include <filesystem>
#include <fstream>
#include <iterator>
#include <map>
#include <system_error>

#include "base/Error.h"
#include "base/StagedFile.h"
#include "io/AssimpJoinVertices.h"
#include "io/AssimpSceneBuilder.h"
#include "io/BoneTipHints.h"
#include "io/ColladaSkinsAndClips.h"
#include "io/ExportFormat.h"
#include "io/FbxClusterOrder.h"
#include "io/FbxRotationCurves.h"
#include "io/FbxSentinels.h"
#include "io/FbxSkinningType.h"
#include "io/FiniteScene.h"
#include "io/GltfAnimations.h"
#include "io/GltfBuffers.h"
#include "io/GltfSceneRoots.h"
#include "io/GltfSkins.h"
#include "io/ObjSceneText.h"
#include "part/PartDetail.h"

namespace rigmesh {
namespace {

namespace fs = std::filesystem;

const char* assimpFormatId(ExportFormat format) {
    switch (format) {
        case ExportFormat::Glb:
            return "glb2";
        case ExportFormat::Gltf:
            return "gltf2";
        case ExportFormat::Fbx:
            return "fbx";  // binary; Blender reads no ASCII FBX
        case ExportFormat::Collada:
            return "collada";
        case ExportFormat::Obj:
            return "obj";
    }
    return "";
}

// docs/EXCHANGE.md rule 8: FBX and COLLADA need JoinIdenticalVertices or the mesh
// arrives open in Blender (glTF gets it from Assimp anyway). We do it
// ourselves in linear time (AssimpJoinVertices.h).
unsigned preprocessing(ExportFormat format) {
    return format == ExportFormat::Fbx || format == ExportFormat::Collada
               ? aiProcess_JoinIdenticalVertices
               : 0u;
}

// While alive, the scene has no animations for Assimp to export (when
// `detach`); they come back, to be freed with the scene, however this ends.
class DetachedAnimations {
  public:
    DetachedAnimations(aiScene& scene, bool detach)
        : scene_(scene), list_(scene.mAnimations), count_(scene.mNumAnimations), detach_(detach) {
        if (detach_) {
            scene_.mAnimations = nullptr;
            scene_.mNumAnimations = 0;
        }
    }
    ~DetachedAnimations() {
        scene_.mAnimations = list_;
        scene_.mNumAnimations = count_;
    }
    DetachedAnimations(const DetachedAnimations&) = delete;
    DetachedAnimations& operator=(const DetachedAnimations&) = delete;
    std::vector<const aiAnimation*> animations() const {
        return detach_ ? std::vector<const aiAnimation*>(list_, list_ + count_)
                       : std::vector<const aiAnimation*>();
    }

  private:
    aiScene& scene_;
    aiAnimation** list_;
    unsigned count_;
    bool detach_;
};

// The files Assimp produced in memory: the main file and its companions by
// extension ("bin" for .gltf).
struct ExportedFiles {
    std::string main;
    std::map<std::string, std::string> companions;
};

ExportedFiles exportToMemory(aiScene& scene, ExportFormat format, const std::string& path) {
    // Assimp's own join is quadratic in the vertices a bone influences.
    for (unsigned m = 0; m < scene.mNumMeshes; ++m)
        joinIdenticalVertices(*scene.mMeshes[m]);
    markVerticesJoined(scene);
    Assimp::Exporter exporter;
    const aiExportDataBlob* blob = nullptr;
    try {
        blob = exporter.ExportToBlob(&scene, assimpFormatId(format), preprocessing(format));
    } catch (const std::exception& exception) {
        throw Error(MessageId::CannotWriteFile, path, exception.what());
    }
    if (blob == nullptr)
        throw Error(MessageId::CannotWriteFile, path, exporter.GetErrorString());
    ExportedFiles files;
    files.main.assign(static_cast<const char*>(blob->data), blob->size);
    for (const aiExportDataBlob* next = blob->next; next != nullptr; next = next->next)
        files.companions[next->name.C_Str()].assign(static_cast<const char*>(next->data),
                                                    next->size);
    return files;
}

std::string fnv1aHex(const std::string& bytes) {
    std::uint64_t hash = 14695981039346656037ull;
    for (const char c : bytes)
        hash = (hash ^ static_cast<unsigned char>(c)) * 1099511628211ull;
    char text[17];
    std::snprintf(text, sizeof text, "%016llx", static_cast<unsigned long long>(hash));
    return text;
}

std::string readWholeFile(const fs::path& path) {
    std::ifstream in(path, std::ios::binary);
    return std::string(std::istreambuf_iterator<char>(in), std::istreambuf_iterator<char>());
}

// .gltf + .bin. The .bin gets a content-derived name (<stem>.<hash>.bin) and
// goes into place first, then the .gltf that references it replaces the old
// one, and only then is the old .bin removed. A crash between the renames
// leaves the old .gltf with its old, untouched .bin (plus an orphan new .bin);
// after the .gltf's rename the new pair is complete. So the .gltf and the .bin
// it names never disagree.
void stageGltf(const ExportedFiles& files, const fs::path& target, std::vector<StagedFile>& staged,
               std::vector<fs::path>& undoOnFailure, std::vector<fs::path>& obsolete) {
    const auto bin = files.companions.find("bin");
    if (bin == files.companions.end())
        throw Error(MessageId::ExportGltfNoBin, target.string());
    const std::string binBytes = zeroUnreferencedBinBytes(files.main, bin->second);
    const std::string binName = target.stem().string() + "." + fnv1aHex(binBytes) + ".bin";
    const std::string gltfText = withBufferUri(files.main, binName);
    const fs::path folder = target.has_parent_path() ? target.parent_path() : fs::path(".");
    const std::string oldBin = fs::exists(target) ? bufferUriOf(readWholeFile(target)) : "";

    staged.emplace_back(folder / binName, binBytes);
    staged.emplace_back(target, gltfText);
    if (oldBin != binName)
        undoOnFailure.push_back(folder / binName);
    // Only a .bin this exporter could have written: no path, the same stem.
    const bool ours = oldBin != binName && oldBin.find('/') == std::string::npos &&
                      oldBin.find('\\') == std::string::npos &&
                      oldBin.starts_with(target.stem().string() + ".") && oldBin.ends_with(".bin");
    if (ours)
        obsolete.push_back(folder / oldBin);
}

// .obj + .mtl, written by us in each mesh's own vertex order
// (ObjSceneText.h); the .mtl goes first, so that the .obj never names a
// missing one.
void stageObj(const aiScene& scene, const fs::path& target, std::vector<StagedFile>& staged) {
    const fs::path mtlPath = fs::path(target).replace_extension(".mtl");
    const ObjText text = objSceneText(scene, mtlPath.filename().string());
    staged.emplace_back(mtlPath, text.mtl);
    staged.emplace_back(target, text.obj);
}

// What Assimp's glTF needs after export: its root node lifted out, one skin
// per armature, every bone's tail hint (GltfSceneRoots.h, GltfSkins.h,
// BoneTipHints.h).
std::string gltfPostPasses(const std::string& json, std::string& bin,
                           const std::vector<ExportRig>& rigs) {
    const std::string lifted = withRootChildrenAsSceneRoots(json);
    return withGltfBoneTails(withOneSkinPerArmature(lifted, bin), rigs);
}

// The parts at the options' detail level (held in `detailed`), or `parts`.
std::vector<ExportPart> withDetailLevel(const std::vector<ExportPart>& parts,
                                        const ExportOptions& options, std::vector<Part>& detailed) {
    if (options.subdivisionLevels == 0 && options.decimateToFaces == 0)
        return parts;
    std::vector<ExportPart> items = parts;
    detailed.reserve(parts.size());
    for (ExportPart& item : items) {
        if (item.part == nullptr)
            continue;
        Part part = subdividedPart(*item.part, options.subdivisionLevels);
        if (options.decimateToFaces > 0)
            part = decimatedPart(part, options.decimateToFaces);
        detailed.push_back(std::move(part));
        item.part = &detailed.back();
    }
    return items;
}

}  // namespace

void StagedExport::commit() {
    for (std::size_t i = 0; i < files_.size(); ++i) {
        try {
            files_[i].commit();
        } catch (const Error&) {
            std::error_code ignored;
            if (i > 0)
                for (const fs::path& path : undoOnFailure_)
                    fs::remove(path, ignored);
            files_.clear();
            throw;
        }
    }
    files_.clear();
    for (const fs::path& path : obsolete_) {
        std::error_code ignored;
        fs::remove(path, ignored);
    }
}

StagedExport stageScene(const std::vector<ExportPart>& parts, const Clip* clip,
                        const std::string& path, const ExportOptions& options) {
    const ExportFormat format = exportFormatFromPath(path);
    aiScene scene;
    std::vector<Part> detailed;
    const std::vector<ExportPart> items = withDetailLevel(parts, options, detailed);
    const std::vector<ExportRig> rigs = buildAssimpScene(scene, items, clip, format, options);
    checkSceneIsFinite(scene);
    const fs::path target(path);
    checkReplaceable(target);
    StagedExport staged;
    if (format == ExportFormat::Obj) {
        stageObj(scene, target, staged.files_);
        return staged;
    }

    // glTF animations are written by us (GltfAnimations.h), in linear time.
    const bool gltf = format == ExportFormat::Glb || format == ExportFormat::Gltf;
    std::vector<const aiAnimation*> animations;
    ExportedFiles files;
    {
        const DetachedAnimations detached(scene, gltf);
        animations = detached.animations();
        files = exportToMemory(scene, format, path);
    }
    switch (format) {
        case ExportFormat::Glb: {
            GlbChunks glb = splitGlb(zeroUnreferencedGlbBytes(std::move(files.main)));
            glb.json = withGltfAnimations(glb.json, glb.bin, animations);
            glb.json = gltfPostPasses(glb.json, glb.bin, rigs);
            staged.files_.emplace_back(target, joinGlb(glb));
            break;
        }
        case ExportFormat::Gltf: {
            std::string& bin = files.companions["bin"];
            files.main = withGltfAnimations(files.main, bin, animations);
            files.main = gltfPostPasses(files.main, bin, rigs);
            stageGltf(files, target, staged.files_, staged.undoOnFailure_, staged.obsolete_);
            break;
        }
        case ExportFormat::Fbx: {
            // One parse for every pass over Assimp's FBX; writing it back
            // adds the null records Assimp < 5.3 leaves out (FbxSentinels.h).
            const std::vector<std::uint8_t> bytes(files.main.begin(), files.main.end());
            FbxFile fbx = parseFbx(bytes);
            makeFbxRotationsContinuous(fbx);
            listFbxClustersParentsFirst(fbx);
            addFbxBoneTails(fbx, rigs);
            setFbxSkinningType(fbx, options.skinning);
            const std::vector<std::uint8_t> out = writeFbx(bytes, fbx);
            staged.files_.emplace_back(target, std::string(out.begin(), out.end()));
            break;
        }
        case ExportFormat::Collada:
            staged.files_.emplace_back(
                target, withColladaSkinRootsAndClips(withColladaBoneTips(files.main, rigs)));
            break;
        case ExportFormat::Obj:
            break;  // staged above
    }
    return staged;
}

void exportScene(const std::vector<ExportPart>& parts, const Clip* clip, const std::string& path,
                 const ExportOptions& options) {
    stageScene(parts, clip, path, options).commit();
}

}  // namespace rigmesh
