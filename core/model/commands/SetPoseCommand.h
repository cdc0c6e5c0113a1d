// Set a part's pose (an IK drag step, a typed rotation, a clip frame).
// Consecutive SetPoseCommands of the same part and the same dragged joint
// merge into one undo step (id() + mergeWith), so a drag undoes at once; a
// merge that lands back on the starting pose makes the command obsolete.
//
// Interactive drags may apply poses live with Document::previewPose and push
// the command at the end with `alreadyApplied`: `from` is then the pose from
// before the preview and the first redo() only records.
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
    // pose that does not fit the part's skeleton. `from` is the part's
    // current pose, or with `alreadyApplied` the pose before the live
    // preview (Document::posePreviewOrigin; the current pose without one).
    SetPoseCommand(Document& document, PartId id, const rigmesh::Pose& to,
                   rigmesh::JointId draggedJoint = rigmesh::kNoJoint, bool alreadyApplied = false,
                   QUndoCommand* parent = nullptr);
    // With an explicit `from` (the pose before a change the caller applied
    // itself with Document::setPose; then pass alreadyApplied = true).
    SetPoseCommand(Document& document, PartId id, const rigmesh::Pose& from,
                   const rigmesh::Pose& to, rigmesh::JointId draggedJoint, bool alreadyApplied,
                   QUndoCommand* parent = nullptr);

    void redo() override;
    void undo() override;
    nlohmann::json recipeStep() const override;
    // A command pushed with alreadyApplied is one whole drag: it never merges.
    int id() const override { return wholeDrag_ ? -1 : SetPoseCommandId; }
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
    bool skipRedo_;
    bool wholeDrag_;
};

}  // namespace rigmesh::model
