// A part posed live (a Pose tool drag, a rotation typed in the Properties
// panel): PartPreview.h over the part's Pose; commit() pushes one
// SetPoseCommand that never merges with its neighbours, keyed at the current
// frame too when auto-key is on (model/PoseChange.h).
#pragma once

#include "model/preview/PartPreview.h"

namespace rigmesh::model {

class PosePreview final : public PartPreview<rigmesh::Pose> {
  public:
    // Throws rigmesh::Error on an unknown part.
    PosePreview(Document& document, PartId id);
    ~PosePreview() { revert(); }

    // Pushes the change from the original pose to the previewed one as one
    // undo step named after `draggedJoint` (kNoJoint: the part); false
    // (nothing pushed) without a preview or when the pose is back where it
    // started. Throws rigmesh::Error (the preview stays) when auto-key
    // cannot key it.
    bool commit(JointId draggedJoint = kNoJoint);

  private:
    void put(const rigmesh::Pose& pose) override;
};

}  // namespace rigmesh::model
