// Set a part's pose (an IK drag step, a typed rotation, a clip frame).
// Consecutive SetPoseCommands of the same part and the same dragged joint
// merge into one undo step (id() + mergeWith), so a drag undoes at once; a
// merge that lands back on the starting pose makes the command obsolete.
//
// Interactive drags preview poses live and push the command once, at the end
// (model/preview/PosePreview.h), with CommandMerging::Never: `from` is then
// the pose from before the preview.
#pragma once

#include <QCoreApplication>
#include <QUndoCommand>

#include "model/Document.h"
#include "model/commands/CommandIds.h"
#include "model/recipe/RecipeStepSource.h"

namespace rigmesh::model {

class SetPoseCommand : public QUndoCommand, public RecipeStepSource {
    Q_DECLARE_TR_FUNCTIONS(SetPoseCommand)
  public:
    // Throws rigmesh::Error on an unknown part, an unknown dragged joint or a
    // pose that does not fit the part's skeleton. From the part's current pose.
    SetPoseCommand(Document& document, PartId id, const rigmesh::Pose& to,
                   rigmesh::JointId draggedJoint = rigmesh::kNoJoint,
                   CommandMerging merging = CommandMerging::Consecutive,
                   QUndoCommand* parent = nullptr);
    // With an explicit `from` (the pose before a preview showed `to`).
    SetPoseCommand(Document& document, PartId id, const rigmesh::Pose& from,
                   const rigmesh::Pose& to, rigmesh::JointId draggedJoint, CommandMerging merging,
                   QUndoCommand* parent = nullptr);

    void redo() override;
    void undo() override;
    nlohmann::json recipeStep() const override;
    // A whole drag or typed value never merges.
    int id() const override { return merging_ == CommandMerging::Never ? -1 : SetPoseCommandId; }
    bool mergeWith(const QUndoCommand* other) override;

    PartId partId() const { return id_; }
    rigmesh::JointId draggedJoint() const { return joint_; }
    const rigmesh::Pose& fromPose() const { return from_; }
    const rigmesh::Pose& toPose() const { return to_; }

  private:
    Document& document_;
    PartId id_;
    int index_;
    rigmesh::JointId joint_;
    rigmesh::Pose from_, to_;
    CommandMerging merging_;
};

}  // namespace rigmesh::model
