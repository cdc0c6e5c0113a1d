// Rebuild a part from its stroke with other build options, as one undoable
// step. Use create(): the engine build runs there, before anything is pushed,
// so a failure throws rigmesh::Error and changes nothing. The pose, pins and
// keys carry over for the joints the new skeleton keeps (RigCarryOver.h);
// droppedMessage() says what was dropped. Undo restores the old pose, pins
// and clip exactly.
#pragma once

#include <QCoreApplication>
#include <QUndoCommand>
#include <memory>
#include <set>

#include "model/Document.h"
#include "model/recipe/RecipeStepSource.h"

namespace rigmesh::model {

class RebuildPartCommand : public QUndoCommand, public RecipeStepSource {
    Q_DECLARE_TR_FUNCTIONS(RebuildPartCommand)
  public:
    // Throws rigmesh::Error on an unknown id, a part without a stroke (merged,
    // cut, bone-edited or imported) or when the build fails.
    static std::unique_ptr<RebuildPartCommand> create(Document& document, PartId id,
                                                      const BuildOptions& options);

    // The command for a part already built from the node's stroke with
    // `options` (buildPart, e.g. by a background job).
    static std::unique_ptr<RebuildPartCommand> fromBuilt(Document& document, PartId id,
                                                         std::shared_ptr<const Part> part,
                                                         const BuildOptions& options);

    void redo() override;
    void undo() override;
    nlohmann::json recipeStep() const override;
    // For the user: what of the pose, pins and keys the rebuild dropped
    // (empty when nothing was).
    QString droppedMessage() const;

  private:
    RebuildPartCommand(Document& document, PartId id, std::shared_ptr<const Part> part,
                       const BuildOptions& options);

    Document& document_;
    PartId id_;
    int index_;
    std::shared_ptr<const Part> oldPart_, newPart_;
    BuildOptions oldOptions_, newOptions_;
    rigmesh::Pose oldPose_, newPose_;
    std::set<rigmesh::JointId> oldPinned_, newPinned_;
    rigmesh::Clip oldClip_, newClip_ = rigmesh::Clip();
    std::vector<rigmesh::Clip> oldOtherClips_, newOtherClips_;
    int droppedJoints_ = 0;
};

}  // namespace rigmesh::model
