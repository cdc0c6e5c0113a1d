// The fuzz targets: sketch JSON, SVG sketches, recipes and .rigmesh
// documents, each from real seeds (FuzzHarness.h says how they run).
#include <gtest/gtest.h>

#include <unistd.h>
#include <QCoreApplication>
#include <cstdint>
#include <filesystem>
#include <fstream>

#include "FuzzChecks.h"
#include "FuzzHarness.h"
#include "base/ChildProcess.h"
#include "base/Error.h"
#include "mesh/MeshWriter.h"
#include "model/Document.h"
#include "model/DocumentExport.h"
#include "model/DocumentFile.h"
#include "model/ImportReader.h"
#include "model/commands/CreatePartCommand.h"
#include "model/recipe/RecipeFile.h"
#include "model/recipe/RecipeRunner.h"
#include "pipeline/SketchToPart.h"
#include "sketch/Sketch.h"

namespace rigmesh::fuzz {
namespace {

namespace fs = std::filesystem;

// The project's error with a message: an accepted rejection, if the
// message has the shape every message keeps (messageProblem).
FuzzVerdict rejected(const std::exception& error) {
    return {true, messageProblem(error.what())};
}

FuzzVerdict sketchVerdict(const Sketch& sketch) {
    const SketchToPartResult result = sketchToPart(sketch.points, sketch.name, {});
    return {false, partProblem(result.part, Topology::ClosedManifold)};
}

std::vector<std::string> seedsIn(const std::string& folder, const std::string& extension) {
    std::vector<std::string> seeds;
    for (const std::string& path : filesIn(folder, extension))
        seeds.push_back(readFile(path));
    return seeds;
}

TEST(Fuzz, SketchJson) {
    FuzzTarget target{"sketch_json", "json", InputKind::JsonText,
                      seedsIn(RIGMESH_SHARED_SKETCHES, "json"), [](const std::string& input) {
                          try {
                              return sketchVerdict(parseSketchJson(input, "fuzz.json"));
                          } catch (const Error& e) {
                              return rejected(e);
                          }
                      }};
    ASSERT_GT(target.seeds.size(), 5u);
    EXPECT_TRUE(runFuzzTarget(target).failures.empty());
}

TEST(Fuzz, SvgSketch) {
    std::vector<std::string> seeds = seedsIn(std::string(RIGMESH_TEST_DATA) + "/svg", "svg");
    // Small hand-written ones with each element kind, curves and transforms.
    seeds.push_back(R"svg(<svg xmlns="http://www.w3.org/2000/svg">
        <g transform="translate(10 5) scale(2)">
        <path d="M 0 0 C 20 -10 40 10 60 0 Q 70 20 60 40 L 0 40 Z"/></g></svg>)svg");
    seeds.push_back(R"svg(<svg xmlns="http://www.w3.org/2000/svg">
        <polygon points="0,0 100,0 100,20 60,20 60,80 40,80 40,20 0,20"/></svg>)svg");
    seeds.push_back(R"svg(<svg xmlns="http://www.w3.org/2000/svg"><defs><path d="M0 0"/></defs>
        <path d="m 10 10 a 30 20 0 1 0 60 0 a 30 20 0 1 0 -60 0 z"/></svg>)svg");
    FuzzTarget target{"svg_sketch", "svg", InputKind::SvgText, seeds, [](const std::string& input) {
                          try {
                              return sketchVerdict(parseSketchSvg(input, "fuzz.svg"));
                          } catch (const Error& e) {
                              return rejected(e);
                          }
                      }};
    EXPECT_TRUE(runFuzzTarget(target).failures.empty());
}

// A recipe leaves the document as after its last good step: that document
// must be valid too.
FuzzVerdict recipeVerdict(const std::string& input) {
    model::Document document;
    FuzzVerdict verdict;
    try {
        model::RecipeRunner(document, fs::path(RIGMESH_RESOURCES) / "recipes")
            .run(model::parseRecipe(input, "fuzz.json"));
    } catch (const Error& e) {
        verdict = rejected(e);
    }
    if (verdict.problem.empty())
        verdict.problem = documentProblem(document, Topology::ClosedManifold);
    return verdict;
}

TEST(Fuzz, Recipe) {
    const std::string sketches = RIGMESH_SHARED_SKETCHES;
    std::vector<std::string> seeds = {
        readFile(std::string(RIGMESH_RESOURCES) + "/recipes/camel.json")};
    // Every kind of step on two small parts.
    seeds.push_back(R"({"format": "rigmesh-recipe", "version": 1, "steps": [
        {"command": "sketch", "stroke": ")" +
                    sketches + R"(/tube.json", "name": "tube",
         "options": {"edgeLength": 0.2, "smoothing": false}},
        {"command": "sketch", "points": [[0, 0], [4, 0], [4, 1], [0, 1]], "name": "bar",
         "placement": {"translation": [0, 3, 0], "rotation": [1, 0, 0, 0]}},
        {"command": "rename", "part": 1, "name": "beam"},
        {"command": "move", "part": "beam", "translation": [1, 2, 3]},
        {"command": "hide", "part": 0}, {"command": "show", "part": 0},
        {"command": "pin", "part": "tube", "joint": 0},
        {"command": "key", "part": "tube", "time": 0},
        {"command": "pose", "part": "tube", "joint": 1, "target": [0.5, 2.0, 0.0]},
        {"command": "key", "part": "tube", "time": 1.5},
        {"command": "move_key", "part": "tube", "from": 1.5, "to": 2},
        {"command": "clip_settings", "part": "tube", "frameRate": 30,
         "interpolation": "smooth", "playback": "loop"},
        {"command": "unpin", "part": "tube", "joint": 0},
        {"command": "reset_pose", "part": "tube"},
        {"command": "delete_key", "part": "tube", "time": 0},
        {"command": "rebuild", "part": "beam", "options": {"edgeLength": 0.3}},
        {"command": "delete", "part": "beam"}]})");
    FuzzTarget target{"recipe", "json", InputKind::JsonText, seeds, &recipeVerdict};
    EXPECT_TRUE(runFuzzTarget(target).failures.empty());
}

// The modelling, rigging and animation steps (merge, cut, bone edits,
// weight paint and clean-ups, clips, keys, the timeline, auto-rig), each
// seed a short session; the document after the last good step must be
// valid: surfaces made here closed, keys at 0 s or later, messages one line.
TEST(Fuzz, RecipeEdits) {
    // The auto-rig seed imports a plain OBJ of the star from here.
    const fs::path folder =
        fs::temp_directory_path() / ("rigmesh_recipe_edits_fuzz_" + std::to_string(::getpid()));
    fs::create_directories(folder);
    writeMesh(
        sketchToPart(readSketchFile(RIGMESH_SHARED_SKETCHES "/star.json").points, "star").part.mesh,
        (folder / "star.obj").string());
    // The seeds name the shared sketches as @SKETCHES@.
    std::vector<std::string> seeds;
    for (const std::string& path : filesIn(RIGMESH_FUZZ_SEEDS "/recipe_edits", "json")) {
        std::string seed = readFile(path);
        for (std::size_t at = seed.find("@SKETCHES@"); at != std::string::npos;
             at = seed.find("@SKETCHES@", at))
            seed.replace(at, 10, RIGMESH_SHARED_SKETCHES);
        seeds.push_back(std::move(seed));
    }
    ASSERT_GE(seeds.size(), 3u);
    FuzzTarget target{
        "recipe_edits", "json", InputKind::JsonText, seeds, [&](const std::string& input) {
            model::Document document;
            FuzzVerdict verdict;
            try {
                model::RecipeRunner(document, folder).run(model::parseRecipe(input, "fuzz.json"));
            } catch (const Error& e) {
                verdict = rejected(e);
            }
            if (verdict.problem.empty())
                verdict.problem = documentProblem(document, Topology::ClosedManifold);
            return verdict;
        }};
    // A seed runs 1-3 s on an idle machine (the auto-rig's flow the most).
    EXPECT_TRUE(runFuzzTarget(target, 20.0).failures.empty());
    fs::remove_all(folder);
}

TEST(Fuzz, Document) {
    // A saved document with every field: the recipe seed above, run.
    model::Document source;
    model::RecipeRunner(source, fs::path(RIGMESH_RESOURCES) / "recipes")
        .run(model::parseRecipe(R"({"format": "rigmesh-recipe", "version": 1, "steps": [
            {"command": "sketch", "stroke": "../sketches/star.json", "name": "star"},
            {"command": "sketch", "points": [[0, 0], [4, 0], [4, 1], [0, 1]], "name": "bar",
             "placement": {"translation": [0, 3, 0], "rotation": [0.6, 0.8, 0, 0]}},
            {"command": "hide", "part": 1}, {"command": "pin", "part": 0, "joint": 0},
            {"command": "key", "part": 0, "time": 0},
            {"command": "pose", "part": 0, "joint": 2, "target": [0.5, 2.0, 0.0]},
            {"command": "key", "part": 0, "time": 1},
            {"command": "clip_settings", "part": 0, "frameRate": 30,
             "interpolation": "smooth", "playback": "loop"}]})",
                                "seed"));
    const QByteArray saved = model::DocumentFile::toBytes(source);
    FuzzTarget target{
        "document",
        "rigmesh",
        InputKind::Cbor,
        {std::string(saved.constData(), static_cast<std::size_t>(saved.size()))},
        [](const std::string& input) {
            try {
                const model::Document document(model::DocumentFile::fromBytes(
                    QByteArray(input.data(), static_cast<qsizetype>(input.size()))));
                return FuzzVerdict{false, documentProblem(document, Topology::ClosedManifold)};
            } catch (const model::DocumentFileError& e) {
                return rejected(e);
            }
        }};
    EXPECT_TRUE(runFuzzTarget(target).failures.empty());
}

// File > Import: our own export of a rigged part in each
// format Assimp reads for us, mutated and read through the child process.
// Every input gives valid parts or an Error with a message; the child's
// crashes, hangs and runaway allocations are contained (limits below the
// harness's per-input bound).
class ImportFuzz : public testing::TestWithParam<const char*> {};

constexpr double kImportSeconds = 4.0;

TEST_P(ImportFuzz, EveryMutatedFileGivesValidPartsOrAMessage) {
    const std::string extension = GetParam();
    const fs::path folder = fs::temp_directory_path() /
                            ("rigmesh_import_fuzz_" + std::to_string(::getpid()) + "_" + extension);
    fs::create_directories(folder);
    const fs::path seed = folder / ("seed." + extension);  // a .gltf's .bin stays beside it
    model::Document source;
    const Sketch sketch = readSketchFile(RIGMESH_SHARED_SKETCHES "/y_branch.json");
    source.undoStack()->push(
        model::CreatePartCommand::create(source, sketch.points, QStringLiteral("y_branch"))
            .release());
    if (extension == "ply" || extension == "off")
        writeMesh(source.parts().front().part->mesh, seed.string());
    else
        model::exportDocument(source, seed.string());

    const bool text = extension == "gltf" || extension == "dae";
    FuzzTarget target{"import_" + extension,
                      extension,
                      extension == "gltf"  ? InputKind::JsonText
                      : extension == "dae" ? InputKind::SvgText
                                           : InputKind::Bytes,
                      {readFile(seed.string())},
                      [&](const std::string& input) {
                          const fs::path path = folder / ("input." + extension);
                          std::ofstream(path, text ? std::ios::out : std::ios::binary) << input;
                          model::ImportLimits limits;
                          limits.seconds = kImportSeconds;
                          limits.addressSpaceBytes = std::uint64_t{2} << 30;
                          try {
                              for (const model::PartNode& node : model::readImportedParts(
                                       QString::fromStdString(path.string()), limits))
                                  if (!node.part->validate().empty())
                                      return FuzzVerdict{false, "an invalid part came back"};
                              return FuzzVerdict{};
                          } catch (const Error& e) {
                              return rejected(e);
                          }
                      }};
    // An import ends within its own limits whatever the machine's load: the
    // child is stopped after kImportSeconds of processor time, or
    // kWallClockFactor times that on the clock (base/ChildProcess.h). A
    // mutated count that makes Assimp allocate runs into the processor limit;
    // on a machine busy with other work that takes longer than the default
    // 5 s per input on the clock, so each input is held to the child's own cap.
    EXPECT_TRUE(runFuzzTarget(target, kImportSeconds * kWallClockFactor + 1.0).failures.empty());
    fs::remove_all(folder);
}

INSTANTIATE_TEST_SUITE_P(Formats, ImportFuzz,
                         testing::Values("glb", "gltf", "fbx", "dae", "obj", "ply", "off"),
                         [](const testing::TestParamInfo<const char*>& param) {
                             return std::string(param.param);
                         });

}  // namespace
}  // namespace rigmesh::fuzz

int main(int argc, char** argv) {
    QCoreApplication application(argc, argv);  // the commands translate their texts
    // Imports are read by the built rigmesh in a child process.
    rigmesh::model::setImportWorkerProgram(QStringLiteral(RIGMESH_CLI));
    testing::InitGoogleTest(&argc, argv);
    return RUN_ALL_TESTS();
}
