// Rebuild a part from its stroke with other build options, as one undoable
// step. Use create(): the engine build runs there, before anything is pushed,
// so a failure throws rigmesh::Error and changes nothing. Joint ids may not
// survive the new skeleton: the rebuilt part gets its rest pose and no pins;
// undo restores the old pose and pins exactly.
#pragma once

#include <QCoreApplication>
#include <QUndoCommand>
#include <memory>
#include <set>

#include "model/Document.h"

namespace rigmesh::model {

class RebuildPartCommand : public QUndoCommand {
    Q_DECLARE_TR_FUNCTIONS(RebuildPartCommand)
  public:
    // Throws rigmesh::Error on an unknown id or when the build fails.
    static std::unique_ptr<RebuildPartCommand> create(Document& document, PartId id,
                                                      const BuildOptions& options);

    void redo() override;
    void undo() override;

  private:
    RebuildPartCommand(Document& document, PartId id, std::shared_ptr<const Part> part,
                       const BuildOptions& options);

    Document& document_;
    PartId id_;
    std::shared_ptr<const Part> oldPart_, newPart_;
    BuildOptions oldOptions_, newOptions_;
    rigmesh::Pose oldPose_, newPose_;
    std::set<rigmesh::JointId> oldPinned_;
};

}  // namespace rigmesh::model
