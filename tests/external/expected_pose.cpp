// expected_pose: what Blender must show for `rigmesh build SKETCH --pose-demo`.
// Builds the part from the sketch exactly as the CLI does (sketchToPart with
// default options), takes the demo clip the CLI exports (io/PoseDemoClip.h)
// and skins the part with our own engine (pose/Skinning.h posePart) at the
// clip's middle key. Writes JSON for tests/external/check_in_blender.py:
//   {"sketch", "part", "model_size" (rest bounding box diagonal),
//    "time", "key_times", "frames_per_second", "skinning",
//    "bone_names": per bone index, the node name the exporter gives it,
//    "vertices": {"glb"|"gltf"|"fbx"|"dae": [{"index", "rest": [x,y,z],
//                 "posed": [x,y,z], "influences"}]}}.
// Positions are in our own frame (y up) and units, as exported with the
// identity placement and unit scale. Each format gets the weights its export
// carries: cut to the format's influence limit (io/InfluenceLimit.h) exactly
// as the exporter cuts them. The skinning is linear blend: Blender's
// armature modifier (without "preserve volume") and glTF viewers deform
// linearly, so DQS would differ from them by design at bent joints.
//
// usage: expected_pose SKETCH OUT.json [--max-influences N]
//   N as given to `rigmesh build` (default: the exporter's default).
#include <algorithm>
#include <cstdio>
#include <cstdlib>
#include <numeric>
#include <string>
#include <vector>

#include <nlohmann/json.hpp>

#include "ToolMain.h"
#include "base/Error.h"
#include "io/ExportFormat.h"
#include "io/ExportRig.h"
#include "io/InfluenceLimit.h"
#include "io/PoseDemoClip.h"
#include "io/SceneExport.h"
#include "pipeline/SketchToPart.h"
#include "pose/Skinning.h"
#include "sketch/Sketch.h"

namespace {

using rigmesh::Vec3;

nlohmann::json point(const Vec3& p) {
    return {p.x(), p.y(), p.z()};
}

// A few vertices worth checking: those the pose moves most (the bend, where
// weights and bones matter), those where glTF's cut to 4 influences changes
// the skinned position most (so a wrong cut shows), and some spread over the
// whole surface by index.
std::vector<int> sampleVertices(const std::vector<Vec3>& rest, const std::vector<Vec3>& posed,
                                const std::vector<Vec3>& posedCut) {
    const int count = static_cast<int>(rest.size());
    std::vector<int> picked;
    auto pickLargest = [&](auto&& size, int how_many) {
        std::vector<int> order(rest.size());
        std::iota(order.begin(), order.end(), 0);
        std::stable_sort(order.begin(), order.end(),
                         [&](int a, int b) { return size(a) > size(b); });
        for (int v : order) {
            if (how_many == 0 || !(size(v) > 0))
                break;
            if (std::find(picked.begin(), picked.end(), v) == picked.end())
                picked.push_back(v), --how_many;
        }
    };
    pickLargest([&](int v) { return (posed[v] - rest[v]).norm(); }, 6);
    pickLargest([&](int v) { return (posedCut[v] - posed[v]).norm(); }, 3);
    for (int k = 0; k < 6 && count > 0; ++k) {
        const int index = static_cast<int>((static_cast<long long>(k) * 2 + 1) * count / 12);
        if (std::find(picked.begin(), picked.end(), index) == picked.end())
            picked.push_back(index);
    }
    return picked;
}

int run(int argc, char** argv) {
    if (argc != 3 && !(argc == 5 && std::string(argv[3]) == "--max-influences")) {
        std::fprintf(stderr, "usage: expected_pose SKETCH OUT.json [--max-influences N]\n");
        return 2;
    }
    const int requested = argc == 5 ? std::atoi(argv[4]) : rigmesh::ExportOptions{}.maxInfluences;

    const rigmesh::Sketch sketch = rigmesh::readSketchFile(argv[1]);
    const rigmesh::Part part = rigmesh::sketchToPart(sketch.points, sketch.name).part;
    const rigmesh::Clip clip = rigmesh::poseDemoClip(part);
    const double time = 0.5;
    const rigmesh::Pose pose = clip.evaluate(time);
    rigmesh::SkinningOptions skinning;
    skinning.method = rigmesh::SkinningMethod::LinearBlend;

    // Bounding box diagonal of the rest surface: the model's size.
    Vec3 low = part.mesh.vertices.front(), high = low;
    for (const Vec3& v : part.mesh.vertices)
        low = low.cwiseMin(v), high = high.cwiseMax(v);

    nlohmann::json out;
    out["sketch"] = sketch.name;
    out["part"] = part.name;
    out["model_size"] = (high - low).norm();
    out["time"] = time;
    out["key_times"] = clip.keyTimes();
    out["frames_per_second"] = clip.framesPerSecond();
    out["skinning"] = "linear blend (our posePart, weights cut per format as exported)";

    // The names the exporter gives the bone nodes; null for a bone it leaves out.
    const std::string partName = rigmesh::sanitizedName(part.name);
    const rigmesh::ExportRig rig =
        rigmesh::makeExportRig(part, partName, Eigen::Affine3d::Identity(), 1.0);
    out["bone_names"] = nlohmann::json::array();
    for (int node : rig.nodeOfBone)
        out["bone_names"].push_back(node >= 0 ? nlohmann::json(rig.nodes[node].name)
                                              : nlohmann::json(nullptr));

    // The part with its weights cut as the exporter cuts them for `format`.
    auto exportedPart = [&](rigmesh::ExportFormat format, int influences) {
        rigmesh::Part exported = part;
        exported.weights = rigmesh::limitInfluences(
            part.weights, rigmesh::effectiveInfluenceLimit(format, influences));
        return exported;
    };
    const std::vector<Vec3> full = rigmesh::posePart(part, pose, skinning).mesh.vertices;
    const std::vector<Vec3> cut =
        rigmesh::posePart(exportedPart(rigmesh::ExportFormat::Glb, 0), pose, skinning)
            .mesh.vertices;
    const std::vector<int> samples = sampleVertices(part.mesh.vertices, full, cut);
    for (const char* extension : {"glb", "gltf", "fbx", "dae"}) {
        const auto format = rigmesh::exportFormatFromPath(std::string("x.") + extension);
        const rigmesh::Part exported = exportedPart(format, requested);
        const std::vector<Vec3> posed = rigmesh::posePart(exported, pose, skinning).mesh.vertices;
        nlohmann::json list = nlohmann::json::array();
        for (int v : samples)
            list.push_back({{"index", v},
                            {"rest", point(part.mesh.vertices[v])},
                            {"posed", point(posed[v])},
                            {"influences", exported.weights.perVertex[v].size()}});
        out["vertices"][extension] = list;
    }

    return rigmesh::test::writeJson(out, argv[2], "expected_pose") ? 0 : 1;
}

}  // namespace

int main(int argc, char** argv) {
    return rigmesh::test::runProgram("expected_pose", &run, argc, argv);
}
