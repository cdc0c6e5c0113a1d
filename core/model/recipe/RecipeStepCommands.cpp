#include "model/recipe/RecipeStepCommands.h"

#include <cmath>
#include <functional>
#include <map>
#include <set>
#include <sstream>

#include "base/Error.h"
#include "model/ClipModes.h"
#include "model/PoseDrag.h"
#include "model/commands/BoneEditCommand.h"
#include "model/commands/ClipListCommand.h"
#include "model/commands/CreatePartCommand.h"
#include "model/commands/CutPartCommand.h"
#include "model/commands/DeleteKeyCommand.h"
#include "model/commands/DeletePartCommand.h"
#include "model/commands/ImportPartsCommand.h"
#include "model/commands/KeyPoseCommand.h"
#include "model/commands/MergePartsCommand.h"
#include "model/commands/MoveKeyCommand.h"
#include "model/commands/MoveKeysCommand.h"
#include "model/commands/MovePartCommand.h"
#include "model/commands/PasteKeysCommand.h"
#include "model/commands/RebuildPartCommand.h"
#include "model/commands/RenamePartCommand.h"
#include "model/commands/ResetPoseCommand.h"
#include "model/commands/RigPartCommand.h"
#include "model/commands/SetClipSettingsCommand.h"
#include "model/commands/SetJointPinnedCommand.h"
#include "model/commands/SetPartVisibleCommand.h"
#include "model/commands/SetPoseCommand.h"
#include "model/commands/SetTimelineCommand.h"
#include "model/recipe/RecipeJson.h"
#include "model/recipe/RecipePartRef.h"
#include "model/recipe/RecipeStepKind.h"
#include "model/recipe/RecipeWeightSteps.h"
#include "pose/LegacyPose.h"
#include "sketch/Sketch.h"

namespace rigmesh::model::recipe {

namespace {

using nlohmann::json;

StepCommand sketch(const Context& c) {
    if (c.has("stroke") == c.has("points"))
        throw Error(MessageId::RecipeStrokeOrPoints);
    std::vector<Vec2> points;
    QString name;
    if (c.has("stroke")) {
        std::filesystem::path path(readText(c.step["stroke"], "\"stroke\""));
        if (path.is_relative())
            path = c.baseDirectory / path;
        Sketch sketch = readSketchFile(path.string());
        points = std::move(sketch.points);
        name = QString::fromStdString(sketch.name);
    } else {
        points = readPoints(c.step["points"]);
    }
    if (c.has("name"))
        name = QString::fromStdString(readText(c.step["name"], "\"name\""));
    // Recipes of version 1 and 2 were made before symmetric outlines got
    // mirrored joints: they replay to the skeleton they were made with.
    BuildOptions defaults;
    defaults.mirrorJoints = c.options.formatVersion >= 3;
    const BuildOptions options =
        c.has("options") ? readOptions(c.step["options"], defaults) : defaults;
    const Placement placement =
        c.has("placement") ? readPlacement(c.step["placement"], {}) : Placement{};
    auto command =
        CreatePartCommand::create(c.document, std::move(points), name, options, placement);
    const PartId id = command->partId();
    return {std::move(command), id, {}};
}

StepCommand pose(const Context& c) {
    const PartId id = c.part();
    const PartNode& node = c.node(id);
    if (c.has("target") == c.has("rotations"))
        throw Error(MessageId::RecipeTargetOrRotations);
    if (c.has("target")) {
        for (const char* key : {"rootTranslation", "complete"}) {
            if (c.has(key))
                throw Error(MessageId::RecipeGoesWithRotations, key);
        }
        // "reach": "limb" (default, as the studio's drag) or "body" (Alt + drag).
        IkReach reach = IkReach::Limb;
        if (c.has("reach")) {
            const std::string value =
                c.step["reach"].is_string() ? c.step["reach"].get<std::string>() : "";
            if (value != "limb" && value != "body")
                throw Error(MessageId::RecipeReach);
            reach = value == "body" ? IkReach::Body : IkReach::Limb;
        }
        const JointId joint = c.joint(node);
        const Vec3 target = readVec3(c.step["target"], "\"target\"");
        const IkResult result = dragPartJoint(node, joint, target, reach);
        std::ostringstream detail;
        detail << (result.reached ? "reached" : "out of reach") << ", distance to target "
               << result.distanceToTarget;
        return {std::make_unique<SetPoseCommand>(c.document, id, result.pose, joint), id,
                detail.str()};
    }
    if (c.has("reach"))
        throw Error(MessageId::RecipeReachGoesWithTarget);
    const bool complete = c.has("complete") && readBool(c.step["complete"], "\"complete\"");
    rigmesh::Pose pose = complete ? rigmesh::Pose{} : node.pose;
    const std::map<JointId, Eigen::Quaterniond> rotations = readRotations(c.step["rotations"]);
    for (const auto& [joint, rotation] : rotations)
        Context::checkJoint(node, joint);
    if (c.options.formatVersion >= 2) {
        for (const auto& [joint, rotation] : rotations)
            pose.rotations[joint] = rotation;
    } else if (!rotations.empty()) {
        // Version 1: a joint's rotation turned every bone leaving it.
        setJointRotations(PoseHierarchy(node.part->skeleton), rotations, pose);
    }
    if (c.has("rootTranslation"))
        pose.rootTranslation = readVec3(c.step["rootTranslation"], "\"rootTranslation\"");
    const JointId joint = c.has("joint") ? c.joint(node) : rigmesh::kNoJoint;
    return make<SetPoseCommand>(id, c.document, id, pose, joint);
}

StepCommand clipSettings(const Context& c) {
    const PartId id = c.part();
    const rigmesh::Clip& clip = c.node(id).clip;
    const double fps = c.has("frameRate") ? c.number("frameRate") : clip.framesPerSecond();
    auto interpolation = clip.interpolation;
    if (c.has("interpolation")) {
        const auto named =
            interpolationFromName(readText(c.step["interpolation"], "\"interpolation\""));
        if (!named)
            throw Error(MessageId::RecipeInterpolation);
        interpolation = *named;
    }
    auto playback = clip.mode;
    if (c.has("playback")) {
        const auto named = playbackFromName(readText(c.step["playback"], "\"playback\""));
        if (!named)
            throw Error(MessageId::RecipePlayback);
        playback = *named;
    }
    return make<SetClipSettingsCommand>(id, c.document, id, fps, interpolation, playback);
}

// "times": [seconds, ...] of keys to move, "by": the offset in seconds.
StepCommand moveKeys(const Context& c) {
    const PartId id = c.part();
    const json& list = c.required("times");
    if (!list.is_array())
        throw Error(MessageId::RecipeTimes);
    std::vector<double> times;
    for (const json& time : list)
        times.push_back(readNumber(time, "\"times\""));
    return make<MoveKeysCommand>(id, c.document, id, std::move(times), c.number("by"));
}

// "keys": [{"time", "rotations", optional "rootTranslation"}, ...]: whole poses.
StepCommand pasteKeys(const Context& c) {
    const PartId id = c.part();
    const json& list = c.required("keys");
    if (!list.is_array())
        throw Error(MessageId::RecipeKeys);
    std::map<double, rigmesh::Pose> keys;
    for (const json& key : list) {
        if (!key.is_object() || !key.contains("time") || !key.contains("rotations"))
            throw Error(MessageId::RecipeKeyFields);
        rigmesh::Pose pose;
        for (const auto& [joint, rotation] : readRotations(key["rotations"])) {
            Context::checkJoint(c.node(id), joint);
            pose.rotations[joint] = rotation;
        }
        if (key.contains("rootTranslation"))
            pose.rootTranslation = readVec3(key["rootTranslation"], "\"rootTranslation\"");
        keys[readNumber(key["time"], "\"time\"")] = pose;
    }
    return make<PasteKeysCommand>(id, c.document, id, std::move(keys));
}

StepCommand timeline(const Context& c) {
    TimelineSettings settings = c.document.timeline();
    auto frame = [&](const char* key) {
        const double value = c.number(key);
        if (value != std::floor(value) || std::abs(value) > kMaxFrame)
            throw Error(MessageId::RecipeWholeFrame, key);
        return static_cast<int>(value);
    };
    if (c.has("start"))
        settings.startFrame = frame("start");
    if (c.has("end"))
        settings.endFrame = frame("end");
    if (c.has("frameRate"))
        settings.framesPerSecond = c.number("frameRate");
    return {std::make_unique<SetTimelineCommand>(c.document, settings), kNoPart, {}};
}

// The clip-list steps: "clip" names an existing clip, "name" a new name.
template <typename Make>
Builder clipListStep(Make make) {
    return [make](const Context& c) {
        const PartId id = c.part();
        auto text = [&](const char* key) {
            return readText(c.required(key), std::string("\"") + key + "\"");
        };
        return StepCommand{make(c.document, id, text), id, {}};
    };
}

// "import": the rigged parts of a file (relative to the recipe).
StepCommand importFile(const Context& c) {
    std::filesystem::path path(readText(c.required("file"), "\"file\""));
    if (path.is_relative())
        path = c.baseDirectory / path;
    auto command = ImportPartsCommand::create(c.document, QString::fromStdString(path.string()));
    const auto ids = command->partIds();
    return {std::move(command), ids.empty() ? kNoPart : ids.front(), {}};
}

// A joint by id (a number) or by a point in document coordinates.
JointChoice readJointChoice(const json& value, const std::string& what) {
    if (value.is_array())
        return readVec3(value, what);
    return readJointId(value, what);
}

json mergeStats(const MergeStats& s) {
    json stats = {{"vertices", s.vertices},
                  {"bones", s.bones},
                  {"vertices_involved", s.verticesInvolved},
                  {"bones_involved", s.bonesInvolved},
                  {"pruned_bones", s.prunedBones},
                  {"smoothed_vertices", s.smoothedVertices},
                  {"union_ms", s.unionMs},
                  {"smoothing_ms", s.smoothingMs},
                  {"reskin_ms", s.reskinMs},
                  {"total_ms", s.totalMs}};
    if (s.globalMs >= 0.0) {
        stats["global_ms"] = s.globalMs;
        stats["global_vertices_involved"] = s.vertices;
        stats["global_bones_involved"] = s.bones;
        stats["p90_weight_difference"] = s.p90WeightDifference;
        stats["p99_weight_difference"] = s.p99WeightDifference;
        stats["mean_weight_difference"] = s.meanWeightDifference;
    }
    return stats;
}

StepCommand merge(const Context& c) {
    const PartId dragged = c.part();
    const PartId into = resolvePart(c.document, c.required("into"));
    MergeSpec spec;
    const std::string mode = c.has("mode") ? readText(c.step["mode"], "\"mode\"") : "snap";
    if (mode != "snap" && mode != "split" && mode != "connect")
        throw Error(MessageId::RecipeMergeMode);
    spec.mode = mode == "snap"    ? MergeMode::Snap
                : mode == "split" ? MergeMode::Split
                                  : MergeMode::Connect;
    spec.draggedJoint = readJointChoice(c.required("joint"), "\"joint\"");
    spec.target = readJointChoice(c.required("target"), "\"target\"");
    const std::string reskin = c.has("reskin") ? readText(c.step["reskin"], "\"reskin\"") : "local";
    if (reskin != "local" && reskin != "global")
        throw Error(MessageId::RecipeReskin);
    spec.reskin = reskin == "local" ? Reskin::Local : Reskin::Global;
    spec.compareGlobal = c.options.compareGlobalReskin;
    auto command = MergePartsCommand::create(c.document, dragged, into, spec);
    const std::string detail = command->summary().toStdString();
    json stats = mergeStats(command->stats());
    return {std::move(command), into, detail, std::move(stats)};
}

// The cut: "plane": {"point", "normal"} in document coordinates, or
// "stroke" [[x, y], ...] drawn in "view" {"direction", "up"} on the view
// plane through the part's centre, swept along the view direction (paper
// 3.1: a plane for a straight stroke).
void readCutPlane(const Context& c, CutSpec& spec) {
    if (c.has("plane") == c.has("stroke"))
        throw Error(MessageId::RecipePlaneOrStroke);
    if (c.has("plane")) {
        const json& plane = c.step["plane"];
        if (!plane.is_object() || !plane.contains("point") || !plane.contains("normal"))
            throw Error(MessageId::RecipePlaneFields);
        spec.point = readVec3(plane["point"], "\"plane\" \"point\"");
        spec.normal = readVec3(plane["normal"], "\"plane\" \"normal\"");
        return;
    }
    spec.viewStroke = readPoints(c.step["stroke"]);
    const json& view = c.required("view");
    if (!view.is_object() || !view.contains("direction") || !view.contains("up"))
        throw Error(MessageId::RecipeViewFields);
    spec.viewDirection = readVec3(view["direction"], "\"view\" \"direction\"");
    spec.viewUp = readVec3(view["up"], "\"view\" \"up\"");
    if (spec.viewStroke.size() < 2)
        throw Error(MessageId::RecipeCutStrokeTooShort);
}

StepCommand cut(const Context& c) {
    const PartId id = c.part();
    CutSpec spec;
    readCutPlane(c, spec);
    const std::string style = c.has("style") ? readText(c.step["style"], "\"style\"") : "smooth";
    if (style != "smooth" && style != "sharp")
        throw Error(MessageId::RecipeJoinStyle);
    spec.style = style == "smooth" ? CutStyle::Smooth : CutStyle::Sharp;
    if (c.has("names")) {
        const json& names = c.step["names"];
        if (!names.is_array() || names.size() != 2)
            throw Error(MessageId::RecipeTwoNames);
        for (int k = 0; k < 2; ++k)
            spec.names[k] = QString::fromStdString(readText(names[k], "\"names\""));
    }
    auto command = CutPartCommand::create(c.document, id, spec);
    std::ostringstream detail;
    detail << "cut in " << static_cast<int>(command->milliseconds() + 0.5) << " ms";
    json stats = {{"ms", command->milliseconds()}};
    return {std::move(command), id, detail.str(), std::move(stats)};
}

// "bone": an id, or "at": a point in document coordinates (the nearest bone).
BoneId readBone(const Context& c, const PartNode& node) {
    if (!node.part || node.part->skeleton.boneCount() == 0)
        throw Error(MessageId::RecipePartHasNoSkeleton, node.name.toStdString());
    if (c.has("bone")) {
        const BoneId bone = readJointId(c.step["bone"], "\"bone\"");
        if (!node.part->skeleton.hasBone(bone))
            throw Error(MessageId::RecipePartHasNoBone, node.name.toStdString(), bone);
        return bone;
    }
    const Vec3 at = readVec3(c.required("at"), "\"at\"");
    return nearestBone(*node.part, node.placement.toLocal(at));
}

// "connect_bone": "part" and "bone" or "at" (part/BoneConnection.h).
StepCommand connectBoneStep(const Context& c) {
    const PartId id = c.part();
    auto command = BoneEditCommand::connect(c.document, id, readBone(c, c.node(id)));
    return {std::move(command), id, {}};
}

StepCommand boneEdit(const Context& c, bool split) {
    const PartId id = c.part();
    const PartNode& node = c.node(id);
    const BoneId bone = readBone(c, node);
    std::unique_ptr<BoneEditCommand> command;
    if (split) {
        // Without "at", the bone's middle.
        const Bone& b = node.part->skeleton.bone(bone);
        const Vec3 middle = 0.5 * (node.part->skeleton.joint(b.head).position +
                                   node.part->skeleton.joint(b.tail).position);
        const Vec3 at =
            c.has("at") ? readVec3(c.step["at"], "\"at\"") : node.placement.toWorld(middle);
        command = BoneEditCommand::split(c.document, id, bone, at);
    } else {
        command = BoneEditCommand::remove(c.document, id, bone);
    }
    const std::string detail = command->summary().toStdString();
    json stats = {{"ms", command->milliseconds()}};
    return {std::move(command), id, detail, std::move(stats)};
}

const std::map<std::string, StepKind>& stepKinds() {
    static const std::map<std::string, StepKind> kinds = withWeightSteps({
        {"sketch", {{"stroke", "points", "name", "placement", "options"}, sketch}},
        {"import", {{"file"}, importFile}},
        {"merge", {{"part", "into", "mode", "joint", "target", "reskin"}, merge}},
        {"cut", {{"part", "plane", "stroke", "view", "style", "names"}, cut}},
        {"split_bone",
         {{"part", "bone", "at"}, [](const Context& c) { return boneEdit(c, true); }}},
        {"delete_bone",
         {{"part", "bone", "at"}, [](const Context& c) { return boneEdit(c, false); }}},
        {"connect_bone", {{"part", "bone", "at"}, connectBoneStep}},
        {"delete",
         {{"part"},
          [](const Context& c) {
              const PartId id = c.part();
              return make<DeletePartCommand>(id, c.document, id);
          }}},
        {"rename",
         {{"part", "name"},
          [](const Context& c) {
              const PartId id = c.part();
              const QString name = QString::fromStdString(readText(c.required("name"), "\"name\""));
              return make<RenamePartCommand>(id, c.document, id, name);
          }}},
        {"move",
         {{"part", "placement"},
          [](const Context& c) {
              const PartId id = c.part();
              const Placement to = readPlacement(c.required("placement"), c.node(id).placement);
              return make<MovePartCommand>(id, c.document, id, to);
          }}},
        {"show",
         {{"part"},
          [](const Context& c) {
              const PartId id = c.part();
              return make<SetPartVisibleCommand>(id, c.document, id, true);
          }}},
        {"hide",
         {{"part"},
          [](const Context& c) {
              const PartId id = c.part();
              return make<SetPartVisibleCommand>(id, c.document, id, false);
          }}},
        {"rebuild",
         {{"part", "options"},
          [](const Context& c) {
              const PartId id = c.part();
              const BuildOptions& current = c.node(id).options;
              const BuildOptions options =
                  c.has("options") ? readOptions(c.step["options"], current) : current;
              return StepCommand{RebuildPartCommand::create(c.document, id, options), id, {}};
          }}},
        {"rig",
         {{"part", "parts"},
          [](const Context& c) {
              // One part, or several rigged together as one ("parts").
              std::vector<PartId> ids;
              if (c.has("parts")) {
                  if (c.has("part") || !c.step["parts"].is_array() || c.step["parts"].empty())
                      throw Error(MessageId::RecipePartsList);
                  for (const json& reference : c.step["parts"])
                      ids.push_back(resolvePart(c.document, reference));
              } else {
                  ids.push_back(c.part());
              }
              const PartId id = ids.front();
              auto command = RigPartCommand::create(c.document, ids);
              std::string detail = command->summary().toStdString();
              return StepCommand{std::move(command), id, std::move(detail)};
          }}},
        {"pose",
         {{"part", "joint", "target", "reach", "rotations", "rootTranslation", "complete"}, pose}},
        {"reset_pose",
         {{"part"},
          [](const Context& c) {
              const PartId id = c.part();
              return make<ResetPoseCommand>(id, c.document, id);
          }}},
        {"pin",
         {{"part", "joint"},
          [](const Context& c) {
              const PartId id = c.part();
              return make<SetJointPinnedCommand>(id, c.document, id, c.joint(c.node(id)), true);
          }}},
        {"unpin",
         {{"part", "joint"},
          [](const Context& c) {
              const PartId id = c.part();
              return make<SetJointPinnedCommand>(id, c.document, id, c.joint(c.node(id)), false);
          }}},
        {"key",
         {{"part", "time"},
          [](const Context& c) {
              const PartId id = c.part();
              return make<KeyPoseCommand>(id, c.document, id, c.number("time"));
          }}},
        {"delete_key",
         {{"part", "time"},
          [](const Context& c) {
              const PartId id = c.part();
              return make<DeleteKeyCommand>(id, c.document, id, c.number("time"));
          }}},
        {"move_key",
         {{"part", "from", "to"},
          [](const Context& c) {
              const PartId id = c.part();
              return make<MoveKeyCommand>(id, c.document, id, c.number("from"), c.number("to"));
          }}},
        {"clip_settings", {{"part", "frameRate", "interpolation", "playback"}, clipSettings}},
        {"move_keys", {{"part", "times", "by"}, moveKeys}},
        {"paste_keys", {{"part", "keys"}, pasteKeys}},
        {"timeline", {{"start", "end", "frameRate"}, timeline}},
        {"new_clip", {{"part", "name"}, clipListStep([](Document& d, PartId id, auto text) {
                          return ClipListCommand::create(d, id, text("name"));
                      })}},
        {"duplicate_clip",
         {{"part", "clip", "name"}, clipListStep([](Document& d, PartId id, auto text) {
              return ClipListCommand::duplicate(d, id, text("clip"), text("name"));
          })}},
        {"rename_clip",
         {{"part", "clip", "name"}, clipListStep([](Document& d, PartId id, auto text) {
              return ClipListCommand::rename(d, id, text("clip"), text("name"));
          })}},
        {"delete_clip", {{"part", "clip"}, clipListStep([](Document& d, PartId id, auto text) {
                             return ClipListCommand::remove(d, id, text("clip"));
                         })}},
        {"active_clip", {{"part", "clip"}, clipListStep([](Document& d, PartId id, auto text) {
                             return ClipListCommand::activate(d, id, text("clip"));
                         })}},
    });
    return kinds;
}

}  // namespace

StepCommand commandForStep(Document& document, const std::string& name, const json& step,
                           const std::filesystem::path& baseDirectory, const StepOptions& options) {
    const auto& kinds = stepKinds();
    const auto kind = kinds.find(name);
    if (kind == kinds.end())
        throw Error(MessageId::RecipeUnknownCommand, name);
    for (const auto& [key, value] : step.items()) {
        if (key != "command" && key != "comment" && !kind->second.fields.contains(key))
            throw Error(MessageId::RecipeUnknownField, key);
    }
    return kind->second.build(Context{document, step, baseDirectory, options});
}

std::vector<std::string> stepCommandNames() {
    std::vector<std::string> names;
    for (const auto& [name, kind] : stepKinds())
        names.push_back(name);
    return names;
}

}  // namespace rigmesh::model::recipe
