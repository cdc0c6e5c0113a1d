// From one recipe step to the document command that does it: the very
// command classes of the studio's undo stack (see RecipeRunner.h for the
// step format).
#pragma once

#include <QUndoCommand>
#include <filesystem>
#include <memory>
#include <nlohmann/json.hpp>
#include <string>
#include <vector>

#include "model/Document.h"

namespace rigmesh::model::recipe {

struct StepCommand {
    std::unique_ptr<QUndoCommand> command;
    PartId part = kNoPart;           // the part the step works on (a new part's id for "sketch")
    std::string detail;              // what the step found out, for its summary ("" if nothing)
    nlohmann::json stats = nullptr;  // figures for `rigmesh run --stats` (null if none)
};

// How steps run beyond what the recipe says (command-line switches).
struct StepOptions {
    bool compareGlobalReskin = false;  // merges also time the global re-skin
    // The recipe's format version (RecipeFile::kFormatVersion by default): "pose" rotations of
    // version 1 turn every bone leaving their joint and are converted.
    int formatVersion = 3;
};

// The command for `step` (an object whose "command" is `name`) on the
// document as it is now; nothing is pushed. Stroke files are relative to
// `baseDirectory`. Throws rigmesh::Error with the reason only.
StepCommand commandForStep(Document& document, const std::string& name, const nlohmann::json& step,
                           const std::filesystem::path& baseDirectory,
                           const StepOptions& options = {});

// Every command name a step may have.
std::vector<std::string> stepCommandNames();

}  // namespace rigmesh::model::recipe
