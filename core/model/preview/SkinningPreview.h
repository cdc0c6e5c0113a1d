// A part's skin weights edited live (a weight paint stroke): PartPreview.h
// over the engine part, swapped with Document::replaceSkinning (same mesh and
// skeleton, pose and keys untouched). The stroke's command is made from the
// document as it was before the stroke, so commit() first puts that back and
// then pushes the command, whose redo() paints the stroke again.
#pragma once

#include <QUndoCommand>
#include <memory>

#include "model/preview/PartPreview.h"

namespace rigmesh::model {

class SkinningPreview final : public PartPreview<std::shared_ptr<const Part>> {
  public:
    // Throws rigmesh::Error on an unknown part.
    SkinningPreview(Document& document, PartId id);
    ~SkinningPreview() { revert(); }

    // Reverts the preview, then pushes `command` (made on the reverted
    // document by `make`) as one undo step. `make` returning nullptr pushes
    // nothing. Throws what `make` throws, with the preview reverted.
    template <typename Make>
    bool commit(Make&& make) {
        revert();
        std::unique_ptr<QUndoCommand> command = make();
        if (!command || !document_)
            return false;
        document_->undoStack()->push(command.release());
        return true;
    }

  private:
    void put(const std::shared_ptr<const Part>& part) override;
};

}  // namespace rigmesh::model
