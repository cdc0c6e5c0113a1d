// A part moved or turned live (the Select tool's drag, the Merge tool's
// drag): PartPreview.h over the part's Placement; commit() pushes one
// MovePartCommand that never merges with its neighbours, so two drags are
// two undo steps.
#pragma once

#include "model/preview/PartPreview.h"

namespace rigmesh::model {

class PlacementPreview final : public PartPreview<Placement> {
  public:
    // Throws rigmesh::Error on an unknown part.
    PlacementPreview(Document& document, PartId id);
    ~PlacementPreview() { revert(); }

    // Pushes the move from the original placement to the previewed one as
    // one undo step; false (nothing pushed) without a preview or when the
    // part is back where it started.
    bool commit();

  private:
    void put(const Placement& placement) override;
};

}  // namespace rigmesh::model
