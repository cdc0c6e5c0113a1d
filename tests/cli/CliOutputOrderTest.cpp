// Every file one `rigmesh build` writes describes the same vertices in the
// same order: the mesh in each format, read back with our own
// readers (MeshFilePositions.h), has vertex i where the rig JSON's vertex i
// is, and the rig JSON names the mesh file it goes with. Before, the OBJ
// came from Assimp's exporter, which numbers vertices in the order faces
// first use them.
#include <gtest/gtest.h>

#include <nlohmann/json.hpp>

#include <algorithm>
#include <cmath>
#include <string>
#include <tuple>

#include "CliRunner.h"
#include "MeshFilePositions.h"

namespace rigmesh::test {
namespace {

struct MeshFormat {
    std::string extension;
    Positions (*read)(const std::filesystem::path&);
};

const std::vector<MeshFormat> kFormats = {
    {"obj", objPositions}, {"off", offPositions},       {"ply", plyPositions},
    {"glb", glbPositions}, {"gltf", gltfFilePositions}, {"fbx", fbxPositions},
    {"dae", daePositions},
};

// Sketches with junction patches (biped, star) and a bent tube (banana).
const std::vector<std::string> kSketches = {"banana", "biped", "star"};

class OutputOrder : public testing::TestWithParam<std::tuple<std::string, std::size_t>> {};

TEST_P(OutputOrder, MeshFileHasTheRigJsonsVerticesInTheSameOrder) {
    const auto& [sketch, formatIndex] = GetParam();
    const MeshFormat& format = kFormats[formatIndex];
    const auto mesh = scratch(sketch + "_order." + format.extension);
    const auto rig = scratch(sketch + "_order_" + format.extension + ".json");
    const std::filesystem::path input =
        std::filesystem::path(RIGMESH_SHARED_SKETCHES) / (sketch + ".json");
    const CliResult result =
        runCli("build " + quoted(input) + " -o " + quoted(mesh) + " --rig " + quoted(rig));
    ASSERT_EQ(result.exitCode, 0) << result.err;

    const auto json = nlohmann::json::parse(readWholeFile(rig));
    EXPECT_EQ(json.at("mesh"), mesh.filename().string());
    const auto& vertices = json.at("vertices");
    ASSERT_EQ(json.at("vertex_count").get<std::size_t>(), vertices.size());
    ASSERT_EQ(json.at("weights").size(), vertices.size());

    const Positions positions = format.read(mesh);
    ASSERT_EQ(positions.size(), vertices.size()) << format.extension;
    double extent = 0.0;
    for (const auto& v : vertices)
        for (int k = 0; k < 3; ++k)
            extent = std::max(extent, std::abs(v.at(k).get<double>()));
    // Float32 formats and six-digit text: well inside 1e-5 of the part's size.
    const double tolerance = 1e-5 * extent;
    int mismatched = 0;
    std::size_t first = 0;
    for (std::size_t i = 0; i < positions.size(); ++i) {
        double distance = 0.0;
        for (int k = 0; k < 3; ++k)
            distance = std::max(distance, std::abs(positions[i][static_cast<std::size_t>(k)] -
                                                   vertices[i].at(k).get<double>()));
        if (distance > tolerance && mismatched++ == 0)
            first = i;
    }
    EXPECT_EQ(mismatched, 0) << format.extension << ": " << mismatched << " of " << positions.size()
                             << " vertices elsewhere, first " << first;
}

std::string orderTestName(
    const testing::TestParamInfo<std::tuple<std::string, std::size_t>>& info) {
    return std::get<0>(info.param) + "_" + kFormats[std::get<1>(info.param)].extension;
}

INSTANTIATE_TEST_SUITE_P(SharedSketches, OutputOrder,
                         testing::Combine(testing::ValuesIn(kSketches),
                                          testing::Range(std::size_t{0}, kFormats.size())),
                         orderTestName);

}  // namespace
}  // namespace rigmesh::test
