#include <gtest/gtest.h>

#include "io/ExportFormat.h"
#include "io/InfluenceLimit.h"

namespace rigmesh {
namespace {

SkinWeights one(std::vector<std::pair<int, double>> list) {
    SkinWeights weights;
    weights.perVertex.push_back(std::move(list));
    return weights;
}

double sum(const std::vector<std::pair<int, double>>& list) {
    double s = 0;
    for (const auto& entry : list)
        s += entry.second;
    return s;
}

TEST(InfluenceLimit, KeepsVerticesWithinTheLimitUnchanged) {
    const auto out = limitInfluences(one({{0, 0.5}, {3, 0.25}, {7, 0.25}}), 4).perVertex[0];
    ASSERT_EQ(out.size(), 3u);
    EXPECT_DOUBLE_EQ(out[0].second, 0.5);
    EXPECT_DOUBLE_EQ(out[1].second, 0.25);
    EXPECT_EQ(out[2].first, 7);
}

TEST(InfluenceLimit, CutsToTheLimitNormalisedAndSortedByBone) {
    const auto out =
        limitInfluences(one({{5, 0.3}, {1, 0.25}, {2, 0.2}, {3, 0.15}, {4, 0.1}}), 4).perVertex[0];
    ASSERT_EQ(out.size(), 4u);
    EXPECT_NEAR(sum(out), 1.0, 1e-12);
    for (std::size_t i = 1; i < out.size(); ++i)
        EXPECT_LT(out[i - 1].first, out[i].first);
    // The largest dropped weight (0.1) is subtracted before renormalising.
    EXPECT_NEAR(out[3].second, (0.3 - 0.1) / (0.9 - 0.4), 1e-12);
}

TEST(InfluenceLimit, IsContinuousWhenWeightsSwapRankAcrossTheCut) {
    // Bone 4's weight grows past bone 3's: a plain top-4 cut would jump.
    double worst = 0;
    std::vector<std::pair<int, double>> previous;
    for (int step = 0; step <= 200; ++step) {
        const double s = 0.05 + 0.1 * step / 200.0;  // 0.05 .. 0.15 against 0.1
        std::vector<std::pair<int, double>> in = {{0, 0.4}, {1, 0.25}, {2, 0.15}, {3, 0.1}, {4, s}};
        const double total = sum(in);
        for (auto& entry : in)
            entry.second /= total;
        const auto out = limitInfluences(one(in), 4).perVertex[0];
        EXPECT_LE(out.size(), 4u);
        EXPECT_NEAR(sum(out), 1.0, 1e-12);
        std::vector<double> dense(5, 0.0);
        for (const auto& [bone, w] : out)
            dense[static_cast<std::size_t>(bone)] = w;
        if (!previous.empty())
            for (const auto& [bone, w] : previous)
                worst = std::max(worst, std::abs(w - dense[static_cast<std::size_t>(bone)]));
        previous.clear();
        for (int b = 0; b < 5; ++b)
            previous.emplace_back(b, dense[static_cast<std::size_t>(b)]);
    }
    EXPECT_LT(worst, 0.01);  // steps of 0.0005 in the input: no jump
}

TEST(InfluenceLimit, ZeroMeansEveryInfluenceAndEmptyStaysEmpty) {
    SkinWeights weights = one({{0, 1}, {1, 1}, {2, 1}, {3, 1}, {4, 1}, {5, 1}});
    weights.perVertex.push_back({});
    const SkinWeights out = limitInfluences(weights, 0);
    EXPECT_EQ(out.perVertex[0].size(), 6u);
    EXPECT_NEAR(out.perVertex[0][2].second, 1.0 / 6, 1e-12);
    EXPECT_TRUE(out.perVertex[1].empty());
}

TEST(InfluenceLimit, TiesAcrossTheCutFallBackToPlainRenormalising) {
    const auto out =
        limitInfluences(one({{0, 0.2}, {1, 0.2}, {2, 0.2}, {3, 0.2}, {4, 0.2}}), 4).perVertex[0];
    ASSERT_EQ(out.size(), 4u);
    EXPECT_NEAR(out[0].second, 0.25, 1e-12);
}

TEST(ExportFormat, ChoosesByExtensionAndRejectsOthers) {
    EXPECT_EQ(exportFormatFromPath("a/b.GLB"), ExportFormat::Glb);
    EXPECT_EQ(exportFormatFromPath("x.gltf"), ExportFormat::Gltf);
    EXPECT_EQ(exportFormatFromPath("x.fbx"), ExportFormat::Fbx);
    EXPECT_EQ(exportFormatFromPath("x.dae"), ExportFormat::Collada);
    EXPECT_EQ(exportFormatFromPath("x.obj"), ExportFormat::Obj);
    EXPECT_EQ(effectiveInfluenceLimit(ExportFormat::Glb, 0), 4);
    EXPECT_EQ(effectiveInfluenceLimit(ExportFormat::Glb, 8), 4);
    EXPECT_EQ(effectiveInfluenceLimit(ExportFormat::Fbx, 0), 0);
    EXPECT_EQ(effectiveInfluenceLimit(ExportFormat::Collada, 6), 6);
    try {
        exportFormatFromPath("x.stl");
        FAIL() << "no error";
    } catch (const std::exception& error) {
        EXPECT_NE(std::string(error.what()).find(".glb"), std::string::npos);
        EXPECT_NE(std::string(error.what()).find(".stl"), std::string::npos);
    }
}

}  // namespace
}  // namespace rigmesh
