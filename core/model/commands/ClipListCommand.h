// Edits to a part's list of named clips: new, duplicate, rename,
// delete, and choosing the active clip. Each keeps the part's clips before
// and after (these are rare, whole-clip edits; keying stays O(log n) through
// ClipCommand). Made by the static functions, which check everything first
// and throw rigmesh::Error with the reason, so nothing bad is ever pushed.
#pragma once

#include <QCoreApplication>
#include <QUndoCommand>
#include <memory>
#include <nlohmann/json.hpp>
#include <string>
#include <vector>

#include "model/Document.h"
#include "model/recipe/RecipeStepSource.h"

namespace rigmesh::model {

class ClipListCommand : public QUndoCommand, public RecipeStepSource {
    Q_DECLARE_TR_FUNCTIONS(ClipListCommand)
  public:
    // A new clip without keys, at the timeline's rate, made active.
    static std::unique_ptr<ClipListCommand> create(Document& document, PartId id,
                                                   const std::string& name);
    // A copy of the clip `source` named `name`, made active.
    static std::unique_ptr<ClipListCommand> duplicate(Document& document, PartId id,
                                                      const std::string& source,
                                                      const std::string& name);
    static std::unique_ptr<ClipListCommand> rename(Document& document, PartId id,
                                                   const std::string& from, const std::string& to);
    // Refused for a part's only clip. Deleting the active clip activates the
    // first of the others by name.
    static std::unique_ptr<ClipListCommand> remove(Document& document, PartId id,
                                                   const std::string& name);
    static std::unique_ptr<ClipListCommand> activate(Document& document, PartId id,
                                                     const std::string& name);

    void redo() override;
    void undo() override;
    nlohmann::json recipeStep() const override;
    PartId partId() const { return id_; }

  private:
    struct Clips {
        rigmesh::Clip active = rigmesh::Clip();
        std::vector<rigmesh::Clip> others;
    };
    ClipListCommand(Document& document, PartId id, Clips after, nlohmann::json step,
                    const QString& text);
    static Clips clipsOf(const PartNode& node);
    // The clip of that name as an editable value in `clips`; throws when none.
    static rigmesh::Clip& clipNamed(Clips& clips, const PartNode& node, const std::string& name);
    static std::unique_ptr<ClipListCommand> make(Document& document, PartId id, Clips after,
                                                 nlohmann::json step, const QString& text);

    Document& document_;
    PartId id_;
    Clips before_, after_;
    nlohmann::json step_;
};

}  // namespace rigmesh::model
