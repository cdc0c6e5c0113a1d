// Builds the aiScene that SceneExport.h describes, following docs/EXCHANGE.md's rules
// 1-7, 9, 10, 12 and 20. Internal to io/: the header only forward-declares Assimp.
#pragma once

#include <vector>

#include "io/ExportFormat.h"
#include "io/ExportRig.h"
#include "io/SceneExport.h"

struct aiScene;

namespace rigmesh {

// Fills an empty `scene` and returns the skeleton layout of each rigged part
// (none for unrigged formats). Throws Error on a part without mesh or with
// weights that do not have one list per vertex.
std::vector<ExportRig> buildAssimpScene(aiScene& scene, const std::vector<ExportPart>& parts,
                                        const Clip* clip, ExportFormat format,
                                        const ExportOptions& options);

}  // namespace rigmesh
