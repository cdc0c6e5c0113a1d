// Recipes: a document's making as a list of steps, replayed headless with the
// very command classes of the studio's undo stack.
//
//   {"format": "rigmesh-recipe", "version": 3,
//    "steps": [ {"command": "...", ...}, ... ]}
//
// Steps ("part" is a part's name, which must be unique, or its index from 0;
// "joint" a joint id of that part's skeleton; quaternions are [w, x, y, z];
// every step may carry a "comment"; any other field is an error):
//   sketch        "stroke": "file.json|.svg" (relative to the recipe's folder)
//                 or "points": [[x, y], ...]; optional "name" (default: the
//                 sketch's name, or "Part <id>"), "placement":
//                 {"translation": [x, y, z], "rotation": [w, x, y, z]},
//                 "options": {"edgeLength": L (0 = automatic), "smoothing": bool,
//                 "mirrorJoints": bool (default true; false in recipes of
//                 version 1 and 2, made before it existed)}
//   delete        "part"
//   rename        "part", "name"
//   move          "part", "placement" (the fields given replace the current ones)
//   show, hide    "part"
//   rebuild       "part", optional "options" (the fields given replace the current ones)
//   rig           "part": an unrigged part (an imported mesh) gets a skeleton
//                 by mean curvature flow, bones by the sketches' CDP rule and
//                 bone heat weights; the mesh is repaired where safe
//   pose          "part" and either
//                   "joint" + "target": [x, y, z] in the part's frame: an IK drag
//                   as the studio's pose tool does (current pose, pinned joints
//                   kept), optional "reach": "limb" (default: the chain stops
//                   below the nearest junction, as a plain drag) or "body" (up
//                   to the root, as Alt + drag), or
//                   "rotations": {"<joint>": [w, x, y, z], ...} (per bone:
//                   the rotation of the bone ending at the joint about its
//                   head, relative to its parent bone; the root's turns the
//                   whole part about the root; version 1 recipes meant one
//                   rotation per joint turning every bone leaving it and are
//                   converted exactly, pose/LegacyPose.h), optional
//                   "rootTranslation": [x, y, z], optional "complete": true (the
//                   joints not listed go to rest, the translation to 0; without
//                   it they keep their current values), optional "joint" (the
//                   joint the change is about: consecutive poses of it merge
//                   into one undo step, as a drag does)
//   reset_pose    "part"
//   pin, unpin    "part", "joint"
//   key           "part", "time" (seconds): keys the current pose
//   delete_key    "part", "time"
//   move_key      "part", "from", "to" (seconds)
//   merge         "part" (the dragged part), "into" (the target), "mode":
//                 "snap" (default) | "split" | "connect", "joint" (of the
//                 dragged part) and "target" (of the target): a joint id or a
//                 point [x, y, z] in document coordinates (the nearest joint;
//                 for split the point projected on the target's nearest
//                 bone), optional "reskin": "local" (default) | "global"
//                 (paper 3.2; the merged part keeps the target's id and name)
//   cut           "part" and either "plane": {"point": [x, y, z], "normal":
//                 [x, y, z]} in document coordinates, or "stroke": [[x, y],
//                 ...] with "view": {"direction": [x, y, z], "up": [x, y, z]}
//                 (the stroke on the view plane through the part's centre, cut
//                 along the surface it sweeps in the view direction: a plane
//                 for a straight stroke); optional "style": "smooth" (default) | "sharp",
//                 "names": [behind, in front] (paper 3.1; the piece behind
//                 the plane keeps the part's id)
//   split_bone    "part" and "bone" (an id) or "at": [x, y, z] (document
//                 coordinates: the nearest bone); the bone is split at the
//                 point of it nearest to "at" (default: its middle) (3.3)
//   delete_bone   "part" and "bone" or "at": the bone's joints merge at its
//                 middle (3.3)
//   connect_bone  "part" and "bone" or "at": a disconnected bone's head
//                 moves onto its parent's tail (Edit > Connect Bone)
//   paint_weights "part", "bone" (id), and either "center": [x, y, z]
//                 (document coordinates) with "radius" (one dab) or "dabs":
//                 [{"center", "radius"}, ...] (a stroke: one undo step);
//                 optional "mode": "add" (default) | "subtract" | "replace"
//                 | "smooth", "falloff": "smooth" (default) | "linear" |
//                 "sharp" | "constant", "strength" (0..1, default 0.5),
//                 "value" (replace: the weight painted towards, default 1),
//                 "mirror" (X-mirror through the sketch plane),
//                 "frontFacesOnly": [x, y, z] (the direction towards the
//                 viewer: vertices facing away are not painted), "locked":
//                 [bone ids] (besides the part's locked bones)
//   normalize_weights "part"; clean_weights "part", optional "threshold"
//                 (default 0.01); limit_weights "part", optional "influences"
//                 (default 4); smooth_weights "part", optional "factor" (0..1,
//                 default 0.5), "iterations" (1..100, default 1): Blender's
//                 Normalize All, Clean, Limit Total and Smooth, keeping
//                 locked bones; recompute_weights "part": bone heat over the
//                 whole part again (paper 2.4), keeping locked bones
//   lock_bone, unlock_bone "part", "bone": painting and the clean-ups keep
//                 a locked bone's weights
//   clip_settings "part", optional "frameRate", "interpolation" ("constant" |
//                 "linear" | "smooth"), "playback" ("hold" | "loop" |
//                 "ping_pong"): of the part's active clip
//   move_keys     "part", "times": [seconds, ...], "by" (seconds): the keys
//                 move together (a timeline drag)
//   paste_keys    "part", "keys": [{"time", "rotations": {"<joint>": [w, x,
//                 y, z], ...}, optional "rootTranslation"}, ...]: whole poses
//                 keyed at their times (a timeline paste)
//   timeline      optional "start", "end" (whole frames), "frameRate": a new
//                 rate keeps every key on its frame
//   new_clip      "part", "name": a new empty clip, made active
//   duplicate_clip "part", "clip", "name": a copy of "clip", made active
//   rename_clip   "part", "clip", "name"
//   delete_clip   "part", "clip" (not the part's only clip)
//   active_clip   "part", "clip": key, play and pose from this clip
//
// Each step constructs one command and pushes it on the document's undo
// stack. A step that cannot be applied throws RecipeError ("step 3 (pose):
// part \"arm\" has no joint 42") and leaves the document as it was after the
// previous step.
#pragma once

#include <filesystem>
#include <functional>
#include <nlohmann/json.hpp>
#include <string>

#include "model/Document.h"
#include "model/recipe/RecipeError.h"
#include "model/recipe/RecipeStepCommands.h"

namespace rigmesh::model {

struct RecipeStepReport {
    int number = 0;             // from 1
    std::string command;        // "sketch", "pose", ...
    std::string summary;        // one line: the command's undo text and what the step found
    double milliseconds = 0.0;  // building the command and pushing it
    nlohmann::json stats;       // the step's own figures (merges), null if none
};

class RecipeRunner {
  public:
    using StepCallback = std::function<void(const RecipeStepReport&)>;

    // Stroke files of "sketch" steps are looked up relative to
    // `baseDirectory` (the recipe file's folder; the working folder if empty).
    explicit RecipeRunner(Document& document, std::filesystem::path baseDirectory = {},
                          recipe::StepOptions options = {});

    // Checks the recipe's format and version (rigmesh::Error), then applies
    // the steps in order, calling `onStep` after each. Throws RecipeError on
    // the first bad step.
    void run(const nlohmann::json& recipe, const StepCallback& onStep = {});
    // Applies one step of a recipe of the current version; `number` names
    // it in messages. Throws RecipeError.
    RecipeStepReport apply(const nlohmann::json& step, int number);

  private:
    RecipeStepReport apply(const nlohmann::json& step, int number,
                           const recipe::StepOptions& options);

    Document& document_;
    std::filesystem::path baseDirectory_;
    recipe::StepOptions options_;
};

}  // namespace rigmesh::model
