// Live edits of one part (a drag, a brush stroke) shown before they become
// one undo step, after Krita's KisTransaction: preview() puts a state on the
// document without a command, revert() puts back the state from before the
// first preview, and the kind's commit() pushes one command from that state
// to the previewed one. That command's redo() runs again on push and sets
// what is already there (Qt's undo framework pattern), so no command needs to
// know that a preview applied it. A preview destroyed uncommitted reverts.
//
// The kinds: PlacementPreview (Select and Merge drags), PosePreview (Pose
// tool drags, typed rotations), SkinningPreview (weight paint strokes) and
// SketchPreview (a part being sketched, not yet in the document).
#pragma once

#include <QPointer>
#include <utility>

#include "model/Document.h"
#include "model/preview/LivePreviews.h"

namespace rigmesh::model {

template <typename State>
class PartPreview {
  public:
    PartPreview(const PartPreview&) = delete;
    PartPreview& operator=(const PartPreview&) = delete;

    PartId partId() const { return id_; }
    // The state from before the first preview.
    const State& original() const { return original_; }
    // The last state previewed (the original before any).
    const State& current() const { return current_; }
    // A preview is on the document and neither reverted nor committed.
    bool previewing() const { return previewing_ && document_ && document_->contains(id_); }

    // Shows `state` at once. Throws rigmesh::Error (nothing changed) when
    // the document refuses it or the part is gone.
    void preview(const State& state) {
        if (!document_)
            return;
        put(state);
        current_ = state;
        previewing_ = true;
        if (!counted_) {
            notePreviewShown(*document_);
            counted_ = true;
        }
    }
    // Puts the original state back (nothing when not previewing).
    void revert() {
        if (previewing())
            put(original_);
        previewing_ = false;
        current_ = original_;
        uncount();
    }

  protected:
    PartPreview(Document& document, PartId id, State original)
        : document_(&document), id_(id), original_(original), current_(std::move(original)) {}
    // Derived destructors call revert(): put() is theirs.
    ~PartPreview() = default;

    // Sets `state` on the document without a command.
    virtual void put(const State& state) = 0;
    // After a commit: the command holds the change now.
    void committed() {
        previewing_ = false;
        original_ = current_;
        uncount();
    }

    // Guarded: a preview may outlive its document (a background job's).
    QPointer<Document> document_;
    PartId id_;

  private:
    // The document no longer counts this preview as shown (LivePreviews.h).
    void uncount() {
        if (counted_ && document_)
            notePreviewEnded(*document_);
        counted_ = false;
    }

    State original_;
    State current_;
    bool previewing_ = false;
    bool counted_ = false;  // counted by the document as a live preview
};

}  // namespace rigmesh::model
