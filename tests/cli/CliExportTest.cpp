// `rigmesh export` end to end: a document saved by `rigmesh run` converts to
// every scene format through the studio's export; a bad document is a
// one-line reason with exit code 1 and no output file.
#include <gtest/gtest.h>
#include <unistd.h>

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <cstring>
#include <filesystem>
#include <fstream>
#include <limits>
#include <nlohmann/json.hpp>
#include <sstream>
#include <string>
#include <vector>

#include "CliRunner.h"

namespace fs = std::filesystem;
using nlohmann::json;
using rigmesh::test::quoted;
using rigmesh::test::readWholeFile;
using rigmesh::test::runCli;
using rigmesh::test::scratch;

namespace {

void writeFile(const fs::path& path, const std::string& bytes) {
    std::ofstream file(path, std::ios::binary);
    file << bytes;
}

// Two parts from the shared sketches, the second hidden; the first keyed at
// 0 s and 1 s with a bend between: what the studio would save.
const fs::path& savedDocument() {
    static const fs::path document = [] {
        const fs::path recipe = scratch("export_recipe.json");
        const std::string sketches = RIGMESH_SHARED_SKETCHES;
        writeFile(recipe, R"({"format": "rigmesh-recipe", "version": 1, "steps": [
            {"command": "sketch", "stroke": ")" +
                              sketches + R"(/tube.json", "name": "tube"},
            {"command": "sketch", "stroke": ")" +
                              sketches + R"(/y_branch.json", "name": "y",
             "placement": {"translation": [8, 0, 0]}},
            {"command": "hide", "part": "y"},
            {"command": "key", "part": "tube", "time": 0},
            {"command": "pose", "part": "tube", "joint": 1, "target": [0.5, 2.0, 0.0]},
            {"command": "key", "part": "tube", "time": 1}]})");
        const fs::path out = scratch("two_parts.rigmesh");
        fs::remove(out);
        const auto result = runCli("run " + quoted(recipe) + " -o " + quoted(out));
        EXPECT_EQ(result.exitCode, 0) << result.err;
        return out;
    }();
    return document;
}

// The JSON chunk of a binary glTF (header 12 bytes, then length + type).
json glbJson(const fs::path& path) {
    const std::string bytes = readWholeFile(path);
    if (bytes.size() < 20)
        return json();
    std::uint32_t length = 0;
    std::memcpy(&length, bytes.data() + 12, 4);
    return json::parse(bytes.substr(20, length));
}

class ExportFormat : public testing::TestWithParam<std::string> {};

TEST_P(ExportFormat, WritesTheDocumentThroughTheStudioExport) {
    const fs::path out = scratch("two_parts." + GetParam());
    fs::remove(out);
    const auto result = runCli("export " + quoted(savedDocument()) + " -o " + quoted(out));
    ASSERT_EQ(result.exitCode, 0) << result.err;
    EXPECT_TRUE(result.err.empty()) << result.err;
    EXPECT_NE(result.out.find("wrote " + out.string() + " (1 part)"), std::string::npos)
        << result.out;
    ASSERT_TRUE(fs::exists(out));
    EXPECT_GT(fs::file_size(out), 1000u);
}

INSTANTIATE_TEST_SUITE_P(CliExport, ExportFormat,
                         testing::Values("glb", "gltf", "fbx", "dae", "obj"));

TEST(CliExport, GlbCarriesTheVisiblePartsSkinAndClip) {
    const fs::path out = scratch("animated.glb");
    const auto result = runCli("export " + quoted(savedDocument()) + " -o " + quoted(out));
    ASSERT_EQ(result.exitCode, 0) << result.err;
    const json gltf = glbJson(out);
    EXPECT_EQ(gltf["meshes"].size(), 1u);  // the hidden part is left out, as in the studio
    EXPECT_EQ(gltf["skins"].size(), 1u);
    EXPECT_EQ(gltf["animations"].size(), 1u);
}

TEST(CliExport, OptionsReachTheExport) {
    const fs::path out = scratch("options.glb");
    const auto result = runCli("export " + quoted(savedDocument()) + " -o " + quoted(out) +
                               " --hidden --no-animation --max-influences 2");
    ASSERT_EQ(result.exitCode, 0) << result.err;
    EXPECT_NE(result.out.find("(2 parts)"), std::string::npos) << result.out;
    const json gltf = glbJson(out);
    EXPECT_EQ(gltf["meshes"].size(), 2u);
    EXPECT_FALSE(gltf.contains("animations"));

    const auto bad = runCli("export " + quoted(savedDocument()) + " -o " + quoted(out) +
                            " --max-influences 1.5");
    EXPECT_EQ(bad.exitCode, 1);
    EXPECT_NE(bad.err.find("rigmesh: --max-influences must be a whole number"), std::string::npos)
        << bad.err;
}

TEST(CliExport, LinearBlendByDefaultDualQuaternionsWhenAsked) {
    // The biped's arm bent by a hand drag, baked: linear blend unless
    // --dual-quaternion, as the studio's view skins by default.
    const fs::path recipe = scratch("bend_recipe.json"), bent = scratch("bend.rigmesh");
    writeFile(recipe, R"({"format": "rigmesh-recipe", "version": 2, "steps": [
        {"command": "sketch", "stroke": ")" +
                          std::string(RIGMESH_SHARED_SKETCHES) + R"(/biped.json", "name": "biped"},
        {"command": "pose", "part": 0, "joint": 10, "target": [1.9, 1.6, 0.4]}]})");
    fs::remove(bent);
    const auto run = runCli("run " + quoted(recipe) + " -o " + quoted(bent));
    ASSERT_EQ(run.exitCode, 0) << run.err;
    const fs::path plain = scratch("skinning_default.obj"), linear = scratch("skinning_lbs.obj"),
                   dual = scratch("skinning_dqs.obj");
    const std::string document = quoted(bent);
    ASSERT_EQ(runCli("export " + document + " -o " + quoted(plain) + " --current-pose").exitCode,
              0);
    ASSERT_EQ(
        runCli("export " + document + " -o " + quoted(linear) + " --current-pose --linear-blend")
            .exitCode,
        0);
    ASSERT_EQ(
        runCli("export " + document + " -o " + quoted(dual) + " --current-pose --dual-quaternion")
            .exitCode,
        0);
    // The vertex lines (each file names its own .mtl).
    auto vertices = [](const fs::path& obj) {
        std::istringstream in(readWholeFile(obj));
        std::string all;
        for (std::string line; std::getline(in, line);)
            if (line.rfind("v ", 0) == 0)
                all += line + "\n";
        return all;
    };
    ASSERT_FALSE(vertices(linear).empty());
    EXPECT_EQ(vertices(plain), vertices(linear));
    EXPECT_NE(vertices(dual), vertices(linear));

    // An FBX's skin deformer records the skinning (SkinningType, for Maya).
    const fs::path fbxLinear = scratch("skinning_lbs.fbx"), fbxDual = scratch("skinning_dqs.fbx");
    ASSERT_EQ(runCli("export " + document + " -o " + quoted(fbxLinear)).exitCode, 0);
    ASSERT_EQ(
        runCli("export " + document + " -o " + quoted(fbxDual) + " --dual-quaternion").exitCode, 0);
    EXPECT_EQ(readWholeFile(fbxLinear).find("DualQuaternion"), std::string::npos);
    EXPECT_NE(readWholeFile(fbxDual).find("DualQuaternion"), std::string::npos);

    // A recipe replayed to FBX says the same (it said DualQuaternion, the
    // engine's own default, whatever the studio showed).
    const fs::path runLinear = scratch("run_lbs.fbx"), runDual = scratch("run_dqs.fbx");
    ASSERT_EQ(runCli("run " + quoted(recipe) + " -o " + quoted(runLinear)).exitCode, 0);
    ASSERT_EQ(
        runCli("run " + quoted(recipe) + " -o " + quoted(runDual) + " --dual-quaternion").exitCode,
        0);
    EXPECT_EQ(readWholeFile(runLinear).find("DualQuaternion"), std::string::npos);
    EXPECT_NE(readWholeFile(runDual).find("DualQuaternion"), std::string::npos);

    const auto both = runCli("export " + document + " -o " + quoted(scratch("both.fbx")) +
                             " --linear-blend --dual-quaternion");
    EXPECT_EQ(both.exitCode, 1);
    EXPECT_NE(both.err.find("rigmesh: choose one skinning"), std::string::npos) << both.err;
}

TEST(CliExport, DetailLevelsReachTheExportAndBadOnesAreRefused) {
    const fs::path plain = scratch("plain.glb"), finer = scratch("finer.glb");
    ASSERT_EQ(
        runCli("export " + quoted(savedDocument()) + " -o " + quoted(plain) + " --no-leaf-bones")
            .exitCode,
        0);
    const auto result = runCli("export " + quoted(savedDocument()) + " -o " + quoted(finer) +
                               " --subdivide 1 --leaf-bones");
    ASSERT_EQ(result.exitCode, 0) << result.err;
    const json before = glbJson(plain), after = glbJson(finer);
    const auto count = [](const json& gltf) {
        return gltf["accessors"][gltf["meshes"][0]["primitives"][0]["attributes"]["POSITION"]
                                     .get<int>()]["count"]
            .get<int>();
    };
    EXPECT_GT(count(after), 3 * count(before));
    EXPECT_GT(after["nodes"].size(), before["nodes"].size());  // the end bones

    for (const char* option : {" --subdivide 5", " --decimate 2", " --decimate 10.5"}) {
        const auto bad =
            runCli("export " + quoted(savedDocument()) + " -o " + quoted(finer) + option);
        EXPECT_EQ(bad.exitCode, 1) << option;
        EXPECT_NE(bad.err.find("must be a whole number"), std::string::npos) << bad.err;
    }
}

// The names of a glb's nodes that end in "_end" (our end bones, ExportRig.h
// endBoneOf), each checked to be a joint of a skin and the child of the bone
// it is named after.
std::vector<std::string> endBones(const json& gltf) {
    std::vector<std::string> names;
    for (std::size_t n = 0; n < gltf["nodes"].size(); ++n) {
        const std::string name = gltf["nodes"][n].value("name", "");
        if (name.size() < 4 || name.compare(name.size() - 4, 4, "_end") != 0)
            continue;
        names.push_back(name);
        bool under = false;
        for (const json& node : gltf["nodes"])
            for (const json& child : node.value("children", json::array()))
                under = under || (child.get<std::size_t>() == n &&
                                  node.value("name", "") == name.substr(0, name.size() - 4));
        EXPECT_TRUE(under) << name << " is not under its leaf";
        bool joint = false;
        for (const json& skin : gltf.value("skins", json::array()))
            for (const json& j : skin["joints"])
                joint = joint || j.get<std::size_t>() == n;
        EXPECT_TRUE(joint) << name << " is no joint";
    }
    return names;
}

TEST(CliExport, EndBonesByDefaultAndNoLeafBonesLeavesThemOut) {
    // Blender's glTF and FBX importers give a leaf without an end bone its
    // parent's length (docs/EXCHANGE.md, "Leaf bones in Blender"), so every
    // command that writes a rigged file adds them unless told not to; the
    // tube has leaves.
    const fs::path byDefault = scratch("ends_default.glb"), asked = scratch("ends_asked.glb"),
                   without = scratch("ends_without.glb");
    const std::string document = quoted(savedDocument());
    ASSERT_EQ(runCli("export " + document + " -o " + quoted(byDefault)).exitCode, 0);
    ASSERT_EQ(runCli("export " + document + " -o " + quoted(asked) + " --leaf-bones").exitCode, 0);
    ASSERT_EQ(runCli("export " + document + " -o " + quoted(without) + " --no-leaf-bones").exitCode,
              0);
    const std::vector<std::string> ends = endBones(glbJson(byDefault));
    EXPECT_FALSE(ends.empty());
    EXPECT_EQ(endBones(glbJson(asked)), ends);
    EXPECT_TRUE(endBones(glbJson(without)).empty());
    EXPECT_EQ(glbJson(without)["nodes"].size() + ends.size(), glbJson(byDefault)["nodes"].size());

    const auto both = runCli("export " + document + " -o " + quoted(scratch("ends_both.glb")) +
                             " --leaf-bones --no-leaf-bones");
    EXPECT_EQ(both.exitCode, 1);
    EXPECT_NE(both.err.find("rigmesh: choose one: --leaf-bones or --no-leaf-bones"),
              std::string::npos)
        << both.err;

    // build and run write them too, and leave them out when told.
    const std::string tubePath = std::string(RIGMESH_SHARED_SKETCHES) + "/tube.json";
    const std::string tube = quoted(fs::path(tubePath));
    const fs::path built = scratch("ends_build.glb"), builtWithout = scratch("ends_build_no.glb");
    ASSERT_EQ(runCli("build " + tube + " -o " + quoted(built)).exitCode, 0);
    ASSERT_EQ(runCli("build " + tube + " -o " + quoted(builtWithout) + " --no-leaf-bones").exitCode,
              0);
    EXPECT_FALSE(endBones(glbJson(built)).empty());
    EXPECT_TRUE(endBones(glbJson(builtWithout)).empty());
    const fs::path recipe = scratch("ends_recipe.json"), ran = scratch("ends_run.glb"),
                   ranWithout = scratch("ends_run_no.glb");
    writeFile(recipe, R"({"format": "rigmesh-recipe", "version": 1, "steps": [
        {"command": "sketch", "stroke": ")" +
                          tubePath + R"(", "name": "tube"}]})");
    ASSERT_EQ(runCli("run " + quoted(recipe) + " -o " + quoted(ran)).exitCode, 0);
    ASSERT_EQ(
        runCli("run " + quoted(recipe) + " -o " + quoted(ranWithout) + " --no-leaf-bones").exitCode,
        0);
    EXPECT_EQ(endBones(glbJson(ran)).size(), endBones(glbJson(built)).size());
    EXPECT_TRUE(endBones(glbJson(ranWithout)).empty());
}

void expectBadDocument(const std::string& bytes, const std::string& reason) {
    const fs::path document = scratch("bad.rigmesh");
    writeFile(document, bytes);
    const fs::path out = scratch("bad.glb");
    fs::remove(out);
    const auto result = runCli("export " + quoted(document) + " -o " + quoted(out));
    EXPECT_EQ(result.exitCode, 1) << result.err;
    EXPECT_EQ(result.err.rfind("rigmesh: Cannot open", 0), 0u) << result.err;
    EXPECT_NE(result.err.find(reason), std::string::npos) << result.err;
    EXPECT_EQ(std::count(result.err.begin(), result.err.end(), '\n'), 1) << result.err;
    EXPECT_FALSE(fs::exists(out));
}

TEST(CliExport, BadDocumentsExitOneWithTheReason) {
    const std::string good = readWholeFile(savedDocument());
    expectBadDocument("not a document", "not a RigMesh Studio document");
    expectBadDocument(good.substr(0, good.size() / 2), "corrupt or truncated");

    json root = json::from_cbor(std::vector<std::uint8_t>(good.begin() + 3, good.end()));
    root["parts"][0]["part"]["mesh"]["vertices"][0] = std::numeric_limits<double>::quiet_NaN();
    std::vector<std::uint8_t> bytes = {0xD9, 0xD9, 0xF7};
    json::to_cbor(root, bytes);
    expectBadDocument(std::string(bytes.begin(), bytes.end()), "not finite");
}

TEST(CliExport, UsageErrorsExitOneBeforeReadingTheDocument) {
    const auto noOutput = runCli("export " + quoted(savedDocument()));
    EXPECT_EQ(noOutput.exitCode, 1);
    EXPECT_NE(noOutput.err.find("rigmesh: export needs an output file"), std::string::npos)
        << noOutput.err;

    const fs::path out = scratch("scene.stl");
    const auto unknown = runCli("export '/no/such/file.rigmesh' -o " + quoted(out));
    EXPECT_EQ(unknown.exitCode, 1);
    EXPECT_NE(unknown.err.find("rigmesh: cannot write " + out.string() + ": unknown format"),
              std::string::npos)
        << unknown.err;
    EXPECT_FALSE(fs::exists(out));

    const auto missing = runCli("export '/no/such/file.rigmesh' -o " + quoted(scratch("x.glb")));
    EXPECT_EQ(missing.exitCode, 1);
    EXPECT_NE(missing.err.find("rigmesh: Cannot open \"/no/such/file.rigmesh\""), std::string::npos)
        << missing.err;
}

TEST(CliExport, HelpListsTheCommand) {
    const auto help = runCli("--help");
    EXPECT_EQ(help.exitCode, 0);
    EXPECT_NE(help.out.find("export DOC.rigmesh -o OUT.glb"), std::string::npos);
}

}  // namespace
