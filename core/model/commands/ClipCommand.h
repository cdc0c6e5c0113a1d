// The base of the commands that edit a part's animation clip (KeyPose,
// DeleteKey, MoveKey, SetClipSettings): each builds the new clip up front
// (so a bad edit throws before anything is pushed) and swaps whole clips on
// redo and undo, so undo gives back the old clip exactly.
#pragma once

#include <QUndoCommand>

#include "model/Document.h"
#include "model/recipe/RecipeStepSource.h"

namespace rigmesh::model {

class ClipCommand : public QUndoCommand, public RecipeStepSource {
  public:
    void redo() override;
    void undo() override;

    PartId partId() const { return id_; }
    const rigmesh::Clip& fromClip() const { return from_; }
    const rigmesh::Clip& toClip() const { return to_; }

  protected:
    // Throws rigmesh::Error on an unknown id or a clip spanning more than
    // kMaxClipFrames (ClipLimits.h). Obsolete (dropped on push)
    // when `to` is exactly the part's clip.
    ClipCommand(Document& document, PartId id, rigmesh::Clip to, QUndoCommand* parent);
    // The part's index when the command was made (recipe steps).
    int partIndex() const { return index_; }

  private:
    Document& document_;
    PartId id_;
    int index_;
    rigmesh::Clip from_, to_;
};

}  // namespace rigmesh::model
