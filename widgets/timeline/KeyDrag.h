// A drag of selected keys along the timeline: previewed live by
// editing the clips in place (Document::editClip, no command), and on
// release put back and pushed as one undo step whose redo() moves the keys
// again (MoveKeysCommand; a macro of them when keys of several parts move),
// as model/preview/PartPreview.h does for parts. Offsets are whole
// frames. Cancelling puts every key back.
#pragma once

#include <map>
#include <vector>

#include "model/ClipEdit.h"
#include "model/Document.h"

namespace rigmesh::widgets {

class KeyDrag {
  public:
    // The exact times of the keys that move, per part (active clips).
    KeyDrag(model::Document& document, std::map<model::PartId, std::vector<double>> keys);
    ~KeyDrag();  // cancels a drag neither finished nor cancelled

    // Shows the keys moved by `frames` from where they started. An offset
    // that would put a key out of range is not taken (the last one stays).
    void moveTo(int frames);
    int offset() const { return offset_; }
    // Pushes the move as one undo step (nothing when the keys are back where
    // they started) and returns the keys' new exact times.
    std::map<model::PartId, std::vector<double>> finish();
    void cancel();

  private:
    void revert();
    double seconds(int frames) const;

    model::Document& document_;
    std::map<model::PartId, std::vector<double>> keys_;
    std::map<model::PartId, model::ClipEdit> applied_;
    int offset_ = 0;
    bool done_ = false;
};

}  // namespace rigmesh::widgets
