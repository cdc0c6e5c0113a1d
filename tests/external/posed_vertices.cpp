// posed_vertices: where the studio puts an imported part's vertices when its
// clip plays (posed in the studio and in Blender at the same frame,
// linear blend skinning on both sides). Reads a document (`rigmesh import`
// writes one), takes its rigged parts' vertices one after the other, rest and
// skinned by the clip of that name at each time, in world coordinates (each
// part's placement), y up:
//   {"rest": [[x, y, z], ...], "posed": {"<time>": [[x, y, z], ...], ...}}
//
// A time "+S" is S seconds after the clip's first key (a file's frame 1 lies
// at 0 s or 1/24 s, depending on its exporter); the output keeps the
// argument as written.
//
// CLIP "-" is each part's active clip (its name written as "clip"); a time
// "@keys" stands for six of the clip's key times spread over it, each
// written in seconds.
//
// usage: posed_vertices DOCUMENT.rigmesh CLIP OUT.json SECONDS...
#include <algorithm>
#include <cstdio>
#include <exception>
#include <fstream>
#include <string>
#include <vector>

#include <nlohmann/json.hpp>

#include "model/DocumentFile.h"
#include "model/PartClips.h"
#include "pose/Skinning.h"

namespace {

nlohmann::json points(const std::vector<rigmesh::Vec3>& vertices,
                      const rigmesh::model::Placement& placement) {
    nlohmann::json out = nlohmann::json::array();
    for (const rigmesh::Vec3& v : vertices) {
        const rigmesh::Vec3 p = placement.rotation * v + placement.translation;
        out.push_back({p.x(), p.y(), p.z()});
    }
    return out;
}

}  // namespace

int main(int argc, char** argv) {
    if (argc < 5) {
        std::fprintf(stderr, "usage: posed_vertices DOCUMENT.rigmesh CLIP OUT.json SECONDS...\n");
        return 2;
    }
    try {
        const rigmesh::model::DocumentContents contents =
            rigmesh::model::DocumentFile::read(QString::fromLocal8Bit(argv[1]));
        const std::string clipName = argv[2];
        nlohmann::json out = {{"rest", nlohmann::json::array()},
                              {"posed", nlohmann::json::object()}};
        for (const rigmesh::model::PartNode& node : contents.parts) {
            if (!node.part || node.part->skeleton.boneCount() == 0)
                continue;
            for (const auto& p : points(node.part->mesh.vertices, node.placement))
                out["rest"].push_back(p);
            const rigmesh::Clip* clip =
                clipName == "-" ? &node.clip : rigmesh::model::findClip(node, clipName);
            if (!clip) {
                std::fprintf(stderr, "posed_vertices: part %s has no clip %s\n",
                             node.name.toStdString().c_str(), clipName.c_str());
                return 1;
            }
            if (clip)
                out["clip"] = rigmesh::model::clipName(*clip);
            std::vector<std::string> times(argv + 4, argv + argc);
            if (clip && times == std::vector<std::string>{"@keys"}) {
                times.clear();
                const std::vector<double> keys = clip->keyTimes();
                for (std::size_t k = 0; k < keys.size() && times.size() < 6;
                     k += std::max<std::size_t>(1, keys.size() / 6)) {
                    char text[32];
                    std::snprintf(text, sizeof text, "%.9g", keys[k]);
                    times.push_back(text);
                }
            }
            for (const std::string& time : times) {
                const double seconds = time.starts_with("+")
                                           ? clip->keyTimes().front() + std::stod(time.substr(1))
                                           : std::stod(time);
                const rigmesh::PosedMesh posed = rigmesh::posePart(
                    *node.part, clip->evaluate(seconds), {rigmesh::SkinningMethod::LinearBlend, 2});
                nlohmann::json& list = out["posed"][time];
                if (list.is_null())
                    list = nlohmann::json::array();
                for (const auto& p : points(posed.mesh.vertices, node.placement))
                    list.push_back(p);
            }
        }
        std::ofstream(argv[3]) << out.dump();
        return 0;
    } catch (const std::exception& error) {
        std::fprintf(stderr, "posed_vertices: %s\n", error.what());
        return 1;
    }
}
