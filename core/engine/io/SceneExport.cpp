#include "io/SceneExport.h"

#include <assimp/postprocess.h>
#include <assimp/scene.h>
#include <assimp/Exporter.hpp>

#include <atomic>
#include <chrono>
#include <filesystem>
#include <system_error>

#include "base/Error.h"
#include "io/AssimpSceneBuilder.h"
#include "io/ExportFormat.h"
#include "io/FbxSentinels.h"

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

// Notes item 8: FBX and COLLADA need JoinIdenticalVertices or the mesh
// arrives open in Blender.
unsigned preprocessing(ExportFormat format) {
    return format == ExportFormat::Fbx || format == ExportFormat::Collada
               ? aiProcess_JoinIdenticalVertices
               : 0u;
}

// A fresh folder beside the target: written files move out of it on success
// (notes item 11: a failed export leaves a partial file).
class TemporaryFolder {
  public:
    explicit TemporaryFolder(const fs::path& parent) {
        static std::atomic<unsigned> counter{0};
        const auto stamp = std::chrono::steady_clock::now().time_since_epoch().count();
        path_ =
            parent / (".rigmesh-export-" + std::to_string(stamp) + "-" + std::to_string(counter++));
        std::error_code error;
        if (!fs::create_directory(path_, error))
            throw Error("cannot write in " + parent.string() + ": " + error.message());
    }
    ~TemporaryFolder() {
        std::error_code ignored;
        fs::remove_all(path_, ignored);
    }
    TemporaryFolder(const TemporaryFolder&) = delete;
    TemporaryFolder& operator=(const TemporaryFolder&) = delete;
    const fs::path& path() const { return path_; }

  private:
    fs::path path_;
};

// Moves every file out of `from` into `to`, the main file last so that it
// appears only when its companions (.bin, .mtl) are in place.
void moveFiles(const fs::path& from, const fs::path& to, const fs::path& mainFile,
               const std::string& target) {
    std::vector<fs::path> files;
    for (const auto& entry : fs::directory_iterator(from))
        if (entry.path().filename() != mainFile)
            files.push_back(entry.path());
    files.push_back(from / mainFile);
    for (const fs::path& file : files) {
        std::error_code error;
        fs::rename(file, to / file.filename(), error);
        if (error)
            throw Error("cannot write " + target + ": " + error.message());
    }
}

}  // namespace

void exportScene(const std::vector<ExportPart>& parts, const Clip* clip, const std::string& path,
                 const ExportOptions& options) {
    const ExportFormat format = exportFormatFromPath(path);
    aiScene scene;
    buildAssimpScene(scene, parts, clip, format, options);

    const fs::path target(path);
    const fs::path folder = target.has_parent_path() ? target.parent_path() : fs::path(".");
    std::error_code error;
    if (!fs::is_directory(folder, error))
        throw Error("cannot write " + path + ": the folder " + folder.string() + " does not exist");
    if (fs::is_directory(target, error))
        throw Error("cannot write " + path + ": it is a folder");
    const TemporaryFolder temporary(folder);
    const fs::path written = temporary.path() / target.filename();

    Assimp::Exporter exporter;
    aiReturn result = aiReturn_FAILURE;
    try {
        result = exporter.Export(&scene, assimpFormatId(format), written.string(),
                                 preprocessing(format));
    } catch (const std::exception& exception) {
        throw Error("cannot write " + path + ": " + exception.what());
    }
    if (result != aiReturn_SUCCESS)
        throw Error("cannot write " + path + ": " + exporter.GetErrorString());
    if (!fs::is_regular_file(written, error))
        throw Error("cannot write " + path + ": the exporter wrote nothing");
    if (format == ExportFormat::Fbx && assimpNeedsFbxSentinelFix())
        addFbxSentinelsToFile(written.string());
    moveFiles(temporary.path(), folder, target.filename(), path);
}

}  // namespace rigmesh
