// Rig unrigged parts (imported meshes) automatically, as one undoable step
// (engine autorig/AutoRig): a skeleton from the mesh's shape, computed on
// the mesh or on a proxy wrapped around it, and bone heat weights; the
// part keeps its mesh as it was. Several parts from one file (a figure's
// body, eyes, clothes) are rigged together as one part with one skeleton,
// joined in document order in the first one's frame: what a person who
// imported one character expects. Recipe step {"command": "rig", "part"}
// or {"command": "rig", "parts": [...]}. The engine work runs in rigged()
// on the parts as they are, touching no document (a background job,
// widgets/jobs), and fromRigged() makes the command on the GUI thread;
// create() does both at once. Undo gives the unrigged parts back exactly.
#pragma once

#include <QCoreApplication>
#include <QStringList>
#include <QUndoCommand>
#include <memory>
#include <vector>

#include "autorig/AutoRig.h"
#include "model/Document.h"
#include "model/recipe/RecipeStepSource.h"

namespace rigmesh::model {

class RigPartCommand : public QUndoCommand, public RecipeStepSource {
    Q_DECLARE_TR_FUNCTIONS(RigPartCommand)
  public:
    // An unrigged part with its placement in the document.
    struct Source {
        std::shared_ptr<const Part> part;
        Placement placement;
    };
    struct Rigged {
        std::vector<Source> from;
        std::shared_ptr<const Part> to;  // in the first part's frame
        // The surface the skeleton and heat were computed on (the proxy
        // when the mesh needed one), in the first part's frame.
        std::shared_ptr<const TriMesh> rigSurface;
        std::vector<Message> repairs;
        int verticesWithoutVisibleBone = 0;
    };
    // Throws rigmesh::Error (AutoRig* messages): a rigged part, a mesh
    // nothing can be rigged from, cancelled through `progress`.
    static Rigged rigged(std::vector<Source> parts, const RigProgress& progress = {});
    static Rigged rigged(std::shared_ptr<const Part> part, const RigProgress& progress = {});
    // Throws rigmesh::Error when a part is gone, moved or changed meanwhile.
    static std::unique_ptr<RigPartCommand> fromRigged(Document& document,
                                                      const std::vector<PartId>& ids,
                                                      const Rigged& result);
    static std::unique_ptr<RigPartCommand> fromRigged(Document& document, PartId id,
                                                      const Rigged& result);
    static std::unique_ptr<RigPartCommand> create(Document& document,
                                                  const std::vector<PartId>& ids);
    static std::unique_ptr<RigPartCommand> create(Document& document, PartId id);
    // The parts and their placements, for rigged().
    static std::vector<Source> sourcesOf(const Document& document, const std::vector<PartId>& ids);

    void redo() override;
    void undo() override;
    nlohmann::json recipeStep() const override;
    // For the user: the bone count, what the rig worked around, vertices
    // that saw no bone from inside.
    QString summary() const;
    // The repairs and notes, translated, one per entry (empty when none).
    QStringList repairs() const;
    const Rigged& result() const { return result_; }

  private:
    RigPartCommand(Document& document, const std::vector<PartId>& ids, const Rigged& result);

    Document& document_;
    std::vector<PartId> ids_;  // the first keeps the rigged part
    std::vector<int> indices_;
    std::vector<PartNode> removed_;  // the others, as they were
    Rigged result_;
    BuildOptions options_;
};

}  // namespace rigmesh::model
