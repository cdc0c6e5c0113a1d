// expected_clips: what Blender must show for a document with named clips
// over several parts, exported by `rigmesh run RECIPE -o ...`.
// Reads the document the same recipe writes (.rigmesh) and, for every clip
// name and every part with a clip of that name, gives the key times, a time
// between the first two keys where Blender's interpolation equals ours
// exactly, and sample vertices at rest and skinned there by our own linear
// blend skinning (Blender's armature modifier deforms linearly), in world
// coordinates (the part's placement, which the exporter bakes in), with the
// weights each format carries (io/InfluenceLimit.h):
//   {"frames_per_second", "model_size",
//    "clips": {"<name>": {"<part>": {"key_times", "interpolation", "time",
//              "vertices": {"glb"|"fbx": [{"index", "rest", "posed"}]}}}}}
// The time: a Linear clip the middle of the first key segment (there the
// importer's per-component quaternion blend equals our slerp); a Smooth or
// Constant clip, baked per frame on export, the frame nearest that middle.
//
// With --at-second-key the time is the clip's second key instead (the first
// when it has one): a key's time, for importers that bake the animation at
// their own frame rate (Godot, tests/external/godot).
//
// usage: expected_clips DOCUMENT.rigmesh OUT.json [--at-second-key]
#include <algorithm>
#include <cmath>
#include <cstdio>
#include <numeric>
#include <string>
#include <vector>

#include <nlohmann/json.hpp>

#include "ToolMain.h"
#include "io/ExportFormat.h"
#include "io/InfluenceLimit.h"
#include "io/SceneExport.h"
#include "model/DocumentFile.h"
#include "model/PartClips.h"
#include "pose/Skinning.h"

namespace {

using rigmesh::Vec3;

nlohmann::json point(const Vec3& p) {
    return {p.x(), p.y(), p.z()};
}

// The time checked between the clip's first two keys, or at its second key
// (see above).
double checkedTime(const rigmesh::Clip& clip, bool atSecondKey) {
    const std::vector<double> keys = clip.keyTimes();
    if (atSecondKey)
        return keys.size() > 1 ? keys[1] : keys[0];
    const double middle = keys.size() > 1 ? 0.5 * (keys[0] + keys[1]) : keys[0];
    if (clip.interpolation == rigmesh::Interpolation::Linear)
        return middle;
    return std::round(middle * clip.framesPerSecond()) / clip.framesPerSecond();
}

// Twelve vertices spread by index and the eight the pose moves most.
std::vector<int> sampleVertices(const std::vector<Vec3>& rest, const std::vector<Vec3>& posed) {
    std::vector<int> picked;
    const int count = static_cast<int>(rest.size());
    for (int k = 0; k < 12; ++k)
        picked.push_back(static_cast<int>((2LL * k + 1) * count / 24));
    std::vector<int> order(rest.size());
    std::iota(order.begin(), order.end(), 0);
    std::stable_sort(order.begin(), order.end(), [&](int a, int b) {
        return (posed[a] - rest[a]).norm() > (posed[b] - rest[b]).norm();
    });
    for (int v : order) {
        if (picked.size() >= 20)
            break;
        if (std::find(picked.begin(), picked.end(), v) == picked.end())
            picked.push_back(v);
    }
    return picked;
}

int run(int argc, char** argv) {
    const bool atSecondKey = argc == 4 && std::string(argv[3]) == "--at-second-key";
    if (argc != 3 && !atSecondKey) {
        std::fprintf(stderr, "usage: expected_clips DOCUMENT.rigmesh OUT.json [--at-second-key]\n");
        return 2;
    }
    const rigmesh::model::DocumentContents document =
        rigmesh::model::DocumentFile::read(QString::fromLocal8Bit(argv[1]));
    rigmesh::SkinningOptions linear;
    linear.method = rigmesh::SkinningMethod::LinearBlend;

    nlohmann::json out;
    out["frames_per_second"] = document.timeline.framesPerSecond;
    Vec3 low = Vec3::Constant(1e300), high = -low;
    for (const rigmesh::model::PartNode& node : document.parts) {
        const Eigen::Affine3d placement =
            Eigen::Translation3d(node.placement.translation) * node.placement.rotation;
        for (const Vec3& v : node.part->mesh.vertices)
            low = low.cwiseMin(placement * v), high = high.cwiseMax(placement * v);
        for (const rigmesh::Clip* clip : rigmesh::model::clipsOf(node)) {
            if (clip->keyCount() == 0)
                continue;
            const double time = checkedTime(*clip, atSecondKey);
            const rigmesh::Pose pose = clip->evaluate(time);
            const std::vector<Vec3> posedFull =
                rigmesh::posePart(*node.part, pose, linear).mesh.vertices;
            const std::vector<int> samples = sampleVertices(node.part->mesh.vertices, posedFull);
            nlohmann::json entry = {{"key_times", clip->keyTimes()},
                                    {"interpolation", static_cast<int>(clip->interpolation)},
                                    {"time", time}};
            for (const char* extension : {"glb", "fbx"}) {
                const auto format = rigmesh::exportFormatFromPath(std::string("x.") + extension);
                rigmesh::Part exported = *node.part;
                exported.weights = rigmesh::limitInfluences(
                    node.part->weights, rigmesh::effectiveInfluenceLimit(
                                            format, rigmesh::ExportOptions{}.maxInfluences));
                const std::vector<Vec3> posed =
                    rigmesh::posePart(exported, pose, linear).mesh.vertices;
                nlohmann::json list = nlohmann::json::array();
                for (int v : samples)
                    list.push_back({{"index", v},
                                    {"rest", point(placement * node.part->mesh.vertices[v])},
                                    {"posed", point(placement * posed[v])}});
                entry["vertices"][extension] = std::move(list);
            }
            out["clips"][rigmesh::model::clipName(*clip)][node.name.toStdString()] =
                std::move(entry);
        }
    }
    out["model_size"] = (high - low).norm();
    return rigmesh::test::writeJson(out, argv[2], "expected_clips") ? 0 : 1;
}

}  // namespace

int main(int argc, char** argv) {
    return rigmesh::test::runProgram("expected_clips", &run, argc, argv);
}
