// Rig an unrigged part (an imported mesh) automatically, as one undoable
// step: the mesh repaired where safe, a skeleton by mean
// curvature flow and the sketches' bone rules, bone heat weights
// (engine autorig/AutoRig). Recipe step {"command": "rig", "part"}. The
// engine work runs in rigged() on the part as it is, touching no document
// (a background job, widgets/jobs), and fromRigged() makes the command on
// the GUI thread; create() does both at once. Undo gives the unrigged part
// back exactly.
#pragma once

#include <QCoreApplication>
#include <QStringList>
#include <QUndoCommand>
#include <memory>

#include "autorig/AutoRig.h"
#include "model/Document.h"
#include "model/recipe/RecipeStepSource.h"

namespace rigmesh::model {

class RigPartCommand : public QUndoCommand, public RecipeStepSource {
    Q_DECLARE_TR_FUNCTIONS(RigPartCommand)
  public:
    struct Rigged {
        std::shared_ptr<const Part> from;
        std::shared_ptr<const Part> to;
        std::vector<Message> repairs;
        int verticesWithoutVisibleBone = 0;
    };
    // Throws rigmesh::Error (AutoRig* messages): a rigged part, a mesh that
    // cannot be repaired safely, cancelled through `progress`.
    static Rigged rigged(std::shared_ptr<const Part> part, const RigProgress& progress = {});
    // Throws rigmesh::Error when the part is gone or changed meanwhile.
    static std::unique_ptr<RigPartCommand> fromRigged(Document& document, PartId id,
                                                      const Rigged& result);
    static std::unique_ptr<RigPartCommand> create(Document& document, PartId id);

    void redo() override;
    void undo() override;
    nlohmann::json recipeStep() const override;
    // For the user: the bone count, what the repair did, vertices that saw
    // no bone from inside.
    QString summary() const;
    // The repairs, translated, one per entry (empty when none were needed).
    QStringList repairs() const;

  private:
    RigPartCommand(Document& document, PartId id, const Rigged& result);

    Document& document_;
    PartId id_;
    int index_;
    Rigged result_;
    BuildOptions options_;
};

}  // namespace rigmesh::model
