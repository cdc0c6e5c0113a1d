// What the commands that write a document share: the export options read
// from the command line, the check of an output path's format before any
// work runs, and the QCoreApplication the model needs (commands translate
// their texts through it).
#pragma once

#include <memory>
#include <string>

#include "CommandLine.h"
#include "io/SceneExport.h"

class QCoreApplication;

namespace rigmesh::model {
class Document;
}

namespace rigmesh::cli {

// End bones at each leaf's tail (ExportOptions::leafBones) unless
// --no-leaf-bones; --leaf-bones, the default, is accepted; both at once are
// refused.
bool leafBonesOption(const CommandLine& line);

// Linear blend skinning (the studio's view default, as glTF viewers and
// Blender deform) unless --dual-quaternion; --linear-blend is accepted;
// both at once are refused.
SkinningMethod skinningOption(const CommandLine& line);

// --max-influences N (a whole number >= 0; 0 = all the format allows);
// leafBonesOption; skinningOption (how poses are baked and what an FBX's
// skin is marked with); --subdivide N (Loop, 0..4) and --decimate FACES (quadric, per part).
ExportOptions exportOptions(const CommandLine& line);

// True for a path ending in .rigmesh (any case).
bool isNativeDocument(const std::string& path);

// Throws rigmesh::Error unless `path` ends in a format exportDocument writes
// (.glb, .gltf, .fbx, .dae, .obj) or, with allowNative, .rigmesh.
void checkDocumentOutputPath(const std::string& path, bool allowNative);

// Writes `document` to `path`: natively for .rigmesh, else exported with
// `options` (export warnings go to stderr); then prints "wrote PATH".
void writeDocumentOutput(const model::Document& document, const std::string& path,
                         const ExportOptions& options = {});

// A QCoreApplication for this command, or null when there is one already;
// keep it until the command is done.
std::unique_ptr<QCoreApplication> ensureCoreApplication();

}  // namespace rigmesh::cli
