// The base of the commands that edit a part's animation clip (KeyPose,
// DeleteKey, MoveKey, MoveKeys, PasteKeys, SetClipSettings): each works out
// its edit up front (so a bad edit throws before anything is pushed) and
// keeps only that edit, the keys it takes out and puts in (ClipEdit.h): redo
// applies it, undo its inverse, so undo gives back the old clip exactly, and
// n key commands cost O(n log n) time and O(n) memory, not O(n^2).
#pragma once

#include <QUndoCommand>

#include "model/ClipEdit.h"
#include "model/Document.h"
#include "model/recipe/RecipeStepSource.h"

namespace rigmesh::model {

class ClipCommand : public QUndoCommand, public RecipeStepSource {
  public:
    void redo() override;
    void undo() override;

    PartId partId() const { return id_; }
    const ClipEdit& edit() const { return edit_; }

  protected:
    // Throws rigmesh::Error on an unknown id. Obsolete (dropped on push)
    // when the edit changes nothing.
    ClipCommand(Document& document, PartId id, ClipEdit edit, QUndoCommand* parent);
    // The part's index when the command was made (recipe steps).
    int partIndex() const { return index_; }

  private:
    Document& document_;
    PartId id_;
    int index_;
    ClipEdit edit_;
};

}  // namespace rigmesh::model
