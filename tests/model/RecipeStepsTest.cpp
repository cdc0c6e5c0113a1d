// Recipe steps one by one: each command applies through the studio's command
// classes (one undo step each), parts by name or index, and every error names
// the step number, its command and the reason.
#include <QDir>
#include <QFile>
#include <cmath>
#include <fstream>

#include "ModelTestSupport.h"
#include "PoseTestSupport.h"
#include "RecipeTestSupport.h"
#include "model/PoseDrag.h"
#include "sketch/Sketch.h"

namespace rigmesh::model::test {
namespace {

using nlohmann::json;

json sketchStep(const std::string& name, const std::vector<Vec2>& stroke) {
    return {{"command", "sketch"}, {"name", name}, {"points", pointsOf(stroke)}};
}

// "body" (an ellipse) and "arm" (the biped: a branching skeleton).
struct Sketched {
    Document document;
    Sketched() {
        runSteps(document, {sketchStep("body", ellipseStroke(1.0, 0.35)),
                            sketchStep("arm", sharedStroke("biped"))});
    }
    const PartNode& node(int index) const { return document.parts()[index]; }
    QUndoStack& stack() { return *document.undoStack(); }
    std::vector<JointId> ends() const { return endJoints(node(1).part->skeleton); }
};

TEST(RecipeSteps, SketchFromPointsWithNamePlacementAndOptions) {
    Document document;
    const std::vector<Vec2> stroke = ellipseStroke(1.0, 0.4);
    json step = sketchStep("torso", stroke);
    step["placement"] = {{"translation", {1.0, 2.0, -0.5}},
                         {"rotation", {std::sqrt(0.5), 0.0, std::sqrt(0.5), 0.0}}};
    step["options"] = {{"edgeLength", 0.12}, {"smoothing", false}};
    runSteps(document, {step});
    ASSERT_EQ(document.partCount(), 1);
    const PartNode& node = document.parts()[0];
    EXPECT_EQ(node.name, QStringLiteral("torso"));
    EXPECT_EQ(node.stroke, stroke);
    EXPECT_EQ(node.placement.translation, Vec3(1.0, 2.0, -0.5));
    EXPECT_EQ(node.placement.rotation.w(), std::sqrt(0.5));
    EXPECT_EQ(node.options.targetEdgeLength, 0.12);
    EXPECT_FALSE(node.options.smoothing);
    EXPECT_EQ(document.undoStack()->count(), 1);
    EXPECT_EQ(document.undoStack()->text(0), QStringLiteral("Create torso"));
}

TEST(RecipeSteps, SketchWithoutNameIsNamedLikeTheStudioDoes) {
    Document document;
    runSteps(document, {{{"command", "sketch"}, {"points", pointsOf(ellipseStroke(1.0, 0.3))}}});
    EXPECT_EQ(document.parts()[0].name, QStringLiteral("Part 1"));
}

TEST(RecipeSteps, SketchFromStrokeFilesRelativeToTheRecipe) {
    QTemporaryDir folder;
    ASSERT_TRUE(folder.isValid());
    const QString dir = folder.path();
    ASSERT_TRUE(QDir(dir).mkpath("sketches"));
    ASSERT_TRUE(
        QFile::copy(QString(RIGMESH_SHARED_SKETCHES) + "/tube.json", dir + "/sketches/tube.json"));
    {
        std::ofstream svg((dir + "/sketches/blob.svg").toStdString());
        svg << R"(<svg xmlns="http://www.w3.org/2000/svg"><polygon points=")";
        for (const Vec2& p : ellipseStroke(100.0, 40.0))
            svg << p.x() << ',' << p.y() << ' ';
        svg << R"("/></svg>)";
    }
    const json recipe =
        recipeWith({{{"command", "sketch"}, {"stroke", "sketches/tube.json"}},
                    {{"command", "sketch"}, {"stroke", "sketches/blob.svg"}, {"name", "blob"}}});
    const std::string path = (dir + "/recipe.json").toStdString();
    writeRecipeFile(recipe, path);
    Document document;
    std::vector<RecipeStepReport> reports;
    runRecipeFile(document, path, [&](const RecipeStepReport& r) { reports.push_back(r); });
    ASSERT_EQ(document.partCount(), 2);
    EXPECT_EQ(document.parts()[0].name, QStringLiteral("tube"));  // the sketch's own name
    EXPECT_EQ(document.parts()[0].stroke, sharedStroke("tube"));
    EXPECT_EQ(document.parts()[1].name, QStringLiteral("blob"));
    ASSERT_EQ(reports.size(), 2u);
    EXPECT_EQ(reports[0].number, 1);
    EXPECT_EQ(reports[0].command, "sketch");
    EXPECT_EQ(reports[0].summary.rfind("Create tube: ", 0), 0u) << reports[0].summary;
    EXPECT_NE(reports[0].summary.find(" vertices, "), std::string::npos);

    Document missing;
    const std::string error = stepError(
        missing, {{{"command", "sketch"}, {"stroke", (dir + "/none.json").toStdString()}}});
    EXPECT_EQ(error.rfind("step 1 (sketch): ", 0), 0u) << error;
}

TEST(RecipeSteps, DeleteRenameShowHide) {
    Sketched s;
    runSteps(s.document, {{{"command", "rename"}, {"part", "body"}, {"name", "torso"}},
                          {{"command", "hide"}, {"part", 1}}});
    EXPECT_EQ(s.node(0).name, QStringLiteral("torso"));
    EXPECT_FALSE(s.node(1).visible);
    runSteps(s.document, {{{"command", "show"}, {"part", "arm"}}});
    EXPECT_TRUE(s.node(1).visible);
    runSteps(s.document, {{{"command", "delete"}, {"part", "torso"}}});
    ASSERT_EQ(s.document.partCount(), 1);
    EXPECT_EQ(s.node(0).name, QStringLiteral("arm"));
    EXPECT_EQ(s.stack().count(), 6);
}

TEST(RecipeSteps, MoveReplacesTheGivenPlacementFields) {
    Sketched s;
    runSteps(
        s.document,
        {{{"command", "move"},
          {"part", 0},
          {"placement", {{"translation", {1.0, 0.0, 0.0}}, {"rotation", {0.0, 0.0, 1.0, 0.0}}}}},
         {{"command", "move"}, {"part", 0}, {"placement", {{"translation", {0.0, 3.0, 0.0}}}}}});
    EXPECT_EQ(s.node(0).placement.translation, Vec3(0.0, 3.0, 0.0));
    EXPECT_EQ(s.node(0).placement.rotation.coeffs(), Eigen::Quaterniond(0, 0, 1, 0).coeffs());
    EXPECT_EQ(s.stack().count(), 3);  // consecutive moves merge, as drags do
    runSteps(
        s.document,
        {{{"command", "move"}, {"part", 1}, {"placement", {{"rotation", {2.0, 0.0, 0.0, 0.0}}}}}});
    EXPECT_EQ(s.node(1).placement.rotation.coeffs(), Eigen::Quaterniond::Identity().coeffs());
}

TEST(RecipeSteps, RebuildKeepsTheOptionsNotGiven) {
    Sketched s;
    const double edgeLength = s.node(0).options.targetEdgeLength;
    runSteps(s.document,
             {{{"command", "rebuild"}, {"part", "body"}, {"options", {{"smoothing", false}}}}});
    EXPECT_FALSE(s.node(0).options.smoothing);
    EXPECT_EQ(s.node(0).options.targetEdgeLength, edgeLength);
    EXPECT_EQ(s.stack().text(s.stack().index() - 1), QStringLiteral("Rebuild body"));
}

TEST(RecipeSteps, PoseByIkDragMatchesThePoseTool) {
    Sketched s;
    const JointId joint = s.ends()[0];
    const Vec3 target = s.node(1).part->skeleton.joint(joint).position + Vec3(0.1, 0.2, 0.05);
    const rigmesh::Pose expected = dragPartJoint(s.node(1), joint, target).pose;
    std::vector<RecipeStepReport> reports;
    RecipeRunner(s.document)
        .run(recipeWith({{{"command", "pose"},
                          {"part", "arm"},
                          {"joint", joint},
                          {"target", {target.x(), target.y(), target.z()}}}}),
             [&](const RecipeStepReport& r) { reports.push_back(r); });
    EXPECT_TRUE(identicalPoses(s.node(1).pose, expected));
    ASSERT_EQ(reports.size(), 1u);
    EXPECT_NE(reports[0].summary.find("distance to target"), std::string::npos);
}

TEST(RecipeSteps, PoseReachBodyMatchesTheAltDragOfThePoseTool) {
    Sketched s;
    const JointId joint = s.ends()[0];
    const Vec3 target = s.node(1).part->skeleton.joint(joint).position + Vec3(0.1, 0.2, 0.05);
    const rigmesh::Pose body = dragPartJoint(s.node(1), joint, target, IkReach::Body).pose;
    runSteps(s.document, {{{"command", "pose"},
                           {"part", "arm"},
                           {"joint", joint},
                           {"reach", "body"},
                           {"target", {target.x(), target.y(), target.z()}}}});
    EXPECT_TRUE(identicalPoses(s.node(1).pose, body));
}

TEST(RecipeSteps, PoseByRotationsPartialOrComplete) {
    Sketched s;
    const Skeleton& skeleton = s.node(1).part->skeleton;
    const JointId root = skeleton.root();
    const JointId end = s.ends()[0];
    const double h = std::sqrt(0.5);
    runSteps(s.document, {{{"command", "pose"},
                           {"part", 1},
                           {"rotations", {{std::to_string(root), {h, h, 0.0, 0.0}}}},
                           {"rootTranslation", {0.0, 0.5, 0.0}}}});
    const rigmesh::Pose& pose = s.node(1).pose;
    EXPECT_EQ(pose.rotations.size(), static_cast<std::size_t>(skeleton.jointCount()));
    EXPECT_EQ(pose.rotation(root).coeffs(), Eigen::Quaterniond(h, h, 0, 0).coeffs());
    EXPECT_EQ(pose.rootTranslation, Vec3(0.0, 0.5, 0.0));

    runSteps(s.document, {{{"command", "pose"},
                           {"part", 1},
                           {"rotations", {{std::to_string(end), {0.0, 0.0, 0.0, 1.0}}}},
                           {"complete", true}}});
    ASSERT_EQ(s.node(1).pose.rotations.size(), 1u);
    EXPECT_EQ(s.node(1).pose.rotation(end).coeffs(), Eigen::Quaterniond(0, 0, 0, 1).coeffs());
    EXPECT_EQ(s.node(1).pose.rootTranslation, Vec3::Zero());
}

TEST(RecipeSteps, ResetPosePinUnpin) {
    Sketched s;
    const JointId end = s.ends()[0];
    runSteps(s.document,
             {{{"command", "pin"}, {"part", "arm"}, {"joint", end}},
              {{"command", "pose"},
               {"part", "arm"},
               {"rotations",
                {{std::to_string(s.node(1).part->skeleton.root()), {0.0, 1.0, 0.0, 0.0}}}}}});
    EXPECT_EQ(s.node(1).pinnedJoints, std::set<JointId>{end});
    runSteps(s.document, {{{"command", "reset_pose"}, {"part", "arm"}},
                          {{"command", "unpin"}, {"part", "arm"}, {"joint", end}}});
    EXPECT_TRUE(identicalPoses(s.node(1).pose, restPose(s.node(1).part->skeleton)));
    EXPECT_TRUE(s.node(1).pinnedJoints.empty());
}

TEST(RecipeSteps, KeyDeleteKeyMoveKeyAndClipSettings) {
    Sketched s;
    const JointId end = s.ends()[0];
    runSteps(s.document, {{{"command", "key"}, {"part", "arm"}, {"time", 0.0}},
                          {{"command", "pose"},
                           {"part", "arm"},
                           {"rotations", {{std::to_string(end), {0.0, 1.0, 0.0, 0.0}}}}},
                          {{"command", "key"}, {"part", "arm"}, {"time", 1.0}},
                          {{"command", "key"}, {"part", "arm"}, {"time", 2.0}},
                          {{"command", "delete_key"}, {"part", "arm"}, {"time", 2.0}},
                          {{"command", "move_key"}, {"part", "arm"}, {"from", 1.0}, {"to", 1.5}},
                          {{"command", "clip_settings"},
                           {"part", "arm"},
                           {"frameRate", 30},
                           {"playback", "loop"},
                           {"comment", "keep it smooth-free"}}});
    const rigmesh::Clip& clip = s.node(1).clip;
    EXPECT_EQ(clip.keyTimes(), (std::vector<double>{0.0, 1.5}));
    EXPECT_TRUE(identicalPoses(clip.key(1.5), s.node(1).pose));
    EXPECT_EQ(clip.framesPerSecond(), 30.0);
    EXPECT_EQ(clip.interpolation, Interpolation::Linear);
    EXPECT_EQ(clip.mode, PlaybackMode::Loop);
}

TEST(RecipeSteps, ErrorsNameTheStepItsCommandAndTheReason) {
    struct Case {
        json step;
        std::string message;
    };
    Sketched s;
    const std::vector<Case> cases = {
        {{{"command", "pose"}, {"part", "arm"}, {"joint", 424242}, {"target", {0, 0, 0}}},
         "step 1 (pose): part \"arm\" has no joint 424242"},
        {{{"command", "pin"}, {"part", "body"}, {"joint", 424242}},
         "step 1 (pin): part \"body\" has no joint 424242"},
        {{{"command", "rename"}, {"part", "leg"}, {"name", "x"}},
         "step 1 (rename): there is no part \"leg\""},
        {{{"command", "hide"}, {"part", 7}},
         "step 1 (hide): there is no part at index 7 (the document has 2 parts)"},
        {{{"command", "hide"}}, "step 1 (hide): the step needs \"part\""},
        {{{"command", "fly"}, {"part", 0}}, "step 1 (fly): unknown command \"fly\""},
        {{{"command", "hide"}, {"part", 0}, {"colour", "red"}},
         "step 1 (hide): unknown field \"colour\""},
        {{{"part", 0}}, "step 1 (?): the step has no \"command\""},
        {json::array({1, 2}), "step 1 (?): a step must be an object"},
        {{{"command", "sketch"}, {"points", {{0, 0}, {1, 0}}}}, "step 1 (sketch): "},
        {{{"command", "sketch"}}, "step 1 (sketch): the step needs either \"stroke\""},
        {{{"command", "sketch"}, {"points", {{0, 0}, {1}}}},
         "step 1 (sketch): \"points\" [2] must be a list of 2 numbers"},
        {{{"command", "move"}, {"part", 0}, {"placement", {{"rotation", {0, 0, 0, 0}}}}},
         "step 1 (move): \"placement\" \"rotation\" is a zero quaternion"},
        {{{"command", "rebuild"}, {"part", 0}, {"options", {{"edgeLength", -1}}}},
         "step 1 (rebuild): \"edgeLength\" must be 0 (automatic) or a positive length"},
        {{{"command", "pose"}, {"part", 1}}, "step 1 (pose): the step needs either \"joint\""},
        {{{"command", "pose"}, {"part", 1}, {"joint", 0}, {"target", {0, 0, 0}}, {"reach", "arm"}},
         "step 1 (pose): \"reach\" must be \"limb\" or \"body\""},
        {{{"command", "pose"}, {"part", 1}, {"rotations", json::object()}, {"reach", "body"}},
         "step 1 (pose): \"reach\" goes with \"target\""},
        {{{"command", "pose"}, {"part", 1}, {"rotations", {{"424242", {1, 0, 0, 0}}}}},
         "step 1 (pose): part \"arm\" has no joint 424242"},
        {{{"command", "pose"}, {"part", 1}, {"rotations", {{"x", {1, 0, 0, 0}}}}},
         "step 1 (pose): \"rotations\" \"x\" is not a joint id"},
        {{{"command", "key"}, {"part", 1}, {"time", "soon"}},
         "step 1 (key): \"time\" must be a number"},
        {{{"command", "delete_key"}, {"part", 1}, {"time", 3.0}},
         "step 1 (delete_key): There is no key at 3.000000 s to delete."},
        {{{"command", "move_key"}, {"part", 1}, {"from", 3.0}, {"to", 1.0}},
         "step 1 (move_key): There is no key at 3.000000 s to move."},
        {{{"command", "clip_settings"}, {"part", 1}, {"frameRate", 0}},
         "step 1 (clip_settings): A clip's frame rate must be a positive number"},
        {{{"command", "clip_settings"}, {"part", 1}, {"interpolation", "cubic"}},
         "step 1 (clip_settings): \"interpolation\" must be \"constant\", \"linear\" or "
         "\"smooth\""},
    };
    const QByteArray before = bytesOf(s.document);
    for (const Case& c : cases) {
        const std::string message = stepError(s.document, {c.step});
        EXPECT_EQ(message.rfind(c.message, 0), 0u) << "got: " << message;
        EXPECT_EQ(bytesOf(s.document), before) << c.message;
        EXPECT_EQ(s.stack().count(), 2) << c.message;
    }
}

TEST(RecipeSteps, StepsThatWouldLeaveNoValidResultAreRefusedWithTheReason) {
    struct Case {
        json step;
        std::string message;
    };
    Sketched s;
    runSteps(s.document, {{{"command", "key"}, {"part", 1}, {"time", 0.0}}});
    const BoneId bone = s.node(1).part->skeleton.bones().front().id;
    const std::vector<Case> cases = {
        // Keys before 0 s reached glTF files as negative animation times.
        {{{"command", "key"}, {"part", 1}, {"time", -1.0}},
         "step 1 (key): A key at -1 s is out of range: keys lie at 0 s or later."},
        {{{"command", "move_keys"}, {"part", 1}, {"times", {0.0}}, {"by", -0.25}},
         "step 1 (move_keys): A key at -0.25 s is out of range"},
        // Every bone id of a step is checked, "locked" as "bone".
        {{{"command", "paint_weights"},
          {"part", 1},
          {"bone", bone},
          {"locked", {99}},
          {"center", {0, 0, 0}},
          {"radius", 0.3}},
         "step 1 (paint_weights): The part has no bone 99 to lock."},
    };
    const QByteArray before = bytesOf(s.document);
    const int steps = s.stack().count();
    for (const Case& c : cases) {
        const std::string message = stepError(s.document, {c.step});
        EXPECT_EQ(message.rfind(c.message, 0), 0u) << "got: " << message;
        EXPECT_EQ(bytesOf(s.document), before) << c.message;
        EXPECT_EQ(s.stack().count(), steps) << c.message;
    }
}

TEST(RecipeSteps, RebuildingAPartWithoutAStrokeSaysWhy) {
    // It said "The stroke has only 0 distinct points".
    // A bone edit, like a merge, a cut or an import, leaves no stroke.
    Sketched s;
    const BoneId bone = s.node(0).part->skeleton.bones().front().id;
    runSteps(s.document, {{{"command", "split_bone"}, {"part", 0}, {"bone", bone}}});
    const std::string message = stepError(s.document, {{{"command", "rebuild"}, {"part", "body"}}});
    EXPECT_EQ(message.rfind("step 1 (rebuild): \"body\" cannot be rebuilt: it was not drawn as one "
                            "sketch",
                            0),
              0u)
        << message;
}

TEST(RecipeSteps, AmbiguousNamesMustBeReferredToByIndex) {
    Document document;
    const std::vector<Vec2> stroke = ellipseStroke(1.0, 0.3);
    runSteps(document, {sketchStep("leg", stroke), sketchStep("leg", stroke)});
    EXPECT_EQ(stepError(document, {{{"command", "hide"}, {"part", "leg"}}}),
              "step 1 (hide): 2 parts are named \"leg\"; refer to the part by its index");
    runSteps(document, {{{"command", "hide"}, {"part", 1}}});
    EXPECT_FALSE(document.parts()[1].visible);
}

TEST(RecipeSteps, ABadStepLeavesTheDocumentAsAfterThePreviousStep) {
    const std::vector<Vec2> stroke = ellipseStroke(1.0, 0.3);
    const std::vector<json> good = {
        sketchStep("a", stroke),
        {{"command", "key"}, {"part", "a"}, {"time", 0.0}},
        {{"command", "move"}, {"part", "a"}, {"placement", {{"translation", {1.0, 0.0, 0.0}}}}}};
    Document reference;
    runSteps(reference, good);

    std::vector<json> steps = good;
    steps.push_back(
        {{"command", "move"}, {"part", "a"}, {"placement", {{"translation", {1.0, "x", 0.0}}}}});
    steps.push_back({{"command", "delete"}, {"part", "a"}});
    Document document;
    try {
        runSteps(document, steps);
        FAIL() << "the bad step was accepted";
    } catch (const RecipeError& error) {
        EXPECT_EQ(error.step(), 4);
        EXPECT_EQ(error.command(), "move");
        EXPECT_EQ(error.reason(), "\"placement\" \"translation\" must be a number");
    }
    EXPECT_EQ(bytesOf(document), bytesOf(reference));
    EXPECT_EQ(document.undoStack()->count(), reference.undoStack()->count());
    EXPECT_EQ(document.undoStack()->index(), reference.undoStack()->index());
}

TEST(RecipeSteps, BadRecipesAreRejectedBeforeAnyStep) {
    Document document;
    const auto message = [&](const json& recipe) {
        try {
            RecipeRunner(document).run(recipe);
        } catch (const rigmesh::Error& error) {
            return std::string(error.what());
        }
        return std::string();
    };
    EXPECT_EQ(message(json::array()).rfind("this is not a RigMesh recipe", 0), 0u);
    const int newer = RecipeFile::kFormatVersion + 1;
    EXPECT_EQ(message({{"format", "rigmesh-recipe"}, {"version", newer}, {"steps", json::array()}})
                  .rfind("the recipe is of version " + std::to_string(newer), 0),
              0u);
    EXPECT_EQ(message({{"format", "rigmesh-recipe"}, {"version", 1}}),
              "the recipe has no list of \"steps\"");
    EXPECT_THROW(parseRecipe("{\"format\": ", "r.json"), rigmesh::Error);
    // A number beyond the double range is a JSON error, not a library exception.
    EXPECT_THROW(parseRecipe("{\"format\": 1e999}", "r.json"), rigmesh::Error);
    EXPECT_THROW(readRecipeFile("/nonexistent/recipe.json"), rigmesh::Error);
    EXPECT_EQ(document.partCount(), 0);
}

}  // namespace
}  // namespace rigmesh::model::test
