// The document: an ordered list of parts, a selection, one undo stack, a file
// path and a modified state (the undo stack's clean state).
//
// Views read through the const API and listen to the fine-grained signals.
// Every change to the content goes through a QUndoCommand (commands/), which
// calls the narrow mutation API below; nothing else should call it. The
// selection is not content: it changes directly, is not undoable and is not
// saved.
#pragma once

#include <QObject>
#include <QString>
#include <QUndoStack>
#include <map>
#include <memory>
#include <set>
#include <vector>

#include "model/ClipEdit.h"
#include "model/PartNode.h"
#include "model/Timeline.h"
#include "rig/Skeleton.h"

namespace rigmesh::model {

struct Selection {
    PartId part = kNoPart;
    JointId joint = kNoJoint;  // a joint of `part`, or none

    friend bool operator==(const Selection&, const Selection&) = default;
};

// What a document holds apart from its undo history: what the file stores.
struct DocumentContents {
    std::vector<PartNode> parts;
    PartId nextPartId = 1;  // greater than every id in use
    TimelineSettings timeline;
    // Saved with the document, but not content an undo step changes.
    int currentFrame = 0;
};

class Document : public QObject {
    Q_OBJECT
  public:
    enum class Change : unsigned {
        Name = 1u << 0,
        Placement = 1u << 1,
        Visibility = 1u << 2,
        Geometry = 1u << 3,  // the engine Part (mesh, skeleton, weights) was replaced
        Options = 1u << 4,   // the build options
        Pose = 1u << 5,      // the current pose (PartNode::pose)
        Pins = 1u << 6,      // the pinned joints (PartNode::pinnedJoints)
        Clip = 1u << 7,      // the animation clips (PartNode::clip, otherClips)
    };
    Q_DECLARE_FLAGS(Changes, Change)
    Q_FLAG(Changes)

    explicit Document(QObject* parent = nullptr);
    // A document holding `contents` (a loaded file), clean, with an empty history.
    explicit Document(DocumentContents contents, QObject* parent = nullptr);
    ~Document() override;

    // ---- Read API (views) ----
    const std::vector<PartNode>& parts() const { return contents_.parts; }
    int partCount() const { return static_cast<int>(contents_.parts.size()); }
    // Index in parts() of the part, or -1.
    int indexOf(PartId id) const;
    bool contains(PartId id) const { return indexOf(id) >= 0; }
    // Throws rigmesh::Error on an unknown id.
    const PartNode& part(PartId id) const;
    const PartNode* findPart(PartId id) const;
    PartId nextPartId() const { return contents_.nextPartId; }
    const DocumentContents& contents() const { return contents_; }

    QUndoStack* undoStack() { return &undoStack_; }
    const QUndoStack* undoStack() const { return &undoStack_; }

    QString filePath() const { return filePath_; }
    void setFilePath(const QString& path);
    // The file name, or for a document never saved its title ("Untitled" by
    // default; the studio numbers new documents and names examples).
    QString displayName() const;
    void setUntitledName(const QString& name);
    bool isModified() const { return !undoStack_.isClean(); }
    // After a successful save: sets the path and marks the undo stack clean.
    void markSaved(const QString& path);

    // ---- Timeline (DocumentTimeline.cpp) ----
    const TimelineSettings& timeline() const { return contents_.timeline; }
    int currentFrame() const { return contents_.currentFrame; }
    // The current frame in seconds, at the timeline's rate.
    double currentTime() const { return contents_.timeline.timeOfFrame(contents_.currentFrame); }
    // Not an undo step and not a modification (it is saved with the next
    // save): moves to `frame` and shows there the pose of every part whose
    // active clip has keys. Another pose a part
    // was given at the old frame is gone, as in Blender. Throws
    // rigmesh::Error on a frame outside [0, kMaxFrame].
    void setCurrentFrame(int frame);
    // The pose the part's active clip gives at the current frame, or its
    // current pose when the clip has no keys.
    rigmesh::Pose poseAtCurrentFrame(PartId id) const;
    // Auto-key (not saved, not undoable): pose changes made through
    // pushPoseChange (PoseChange.h) also key the pose at the current frame.
    bool autoKey() const { return autoKey_; }
    void setAutoKey(bool on);

    // ---- Selection (not undoable) ----
    Selection selection() const { return selection_; }
    // Unknown parts or joints select nothing.
    void setSelection(const Selection& selection);
    void clearSelection() { setSelection({}); }

    // ---- Mutation API: for commands only ----
    // Reserves a fresh id (never used before in this document's live state).
    PartId allocatePartId();
    // Gives back the most recently allocated id when the command that
    // allocated it is undone (its part is gone and every later command has
    // been undone too), so undo restores nextPartId() exactly.
    void releasePartId(PartId id);
    // Inserts at `index` (clamped). The node's id must not be in use.
    void insertPart(int index, PartNode node);
    // Removes and returns the node.
    PartNode removePart(PartId id);
    // Swaps the whole node of part `id` for `node` (same id, same place in
    // parts()): one partChanged with every Change that differs (a different
    // stroke counts as Options: what the part is built from). The selection
    // stays on the part, and on its joint if the new skeleton has it. Throws
    // rigmesh::Error (nothing changed) on another id, or a pose, pins or
    // clips that do not fit the new part's skeleton.
    void replaceNode(PartId id, PartNode node);
    // Puts back `contents` and `selection` taken from this document earlier
    // (model/GuardedUndo's snapshot of a change that failed): parts it lacks
    // go, the others come back in their order with one partChanged each for
    // what differs (nothing for an equal node), and the part id counter,
    // timeline and current frame are as they were. The poses come from
    // `contents`: the frame is set without re-posing from the clips.
    void restoreContents(const DocumentContents& contents, const Selection& selection);
    void setName(PartId id, const QString& name);
    void setPlacement(PartId id, const Placement& placement);
    void setVisible(PartId id, bool visible);
    // Swaps the engine part, its options, pose, pins and clip at once (one
    // partChanged with every flag that applies). `pose`, `pinned` and `clip`
    // must fit the new part's skeleton (throws rigmesh::Error otherwise).
    void replacePart(PartId id, std::shared_ptr<const Part> part, const BuildOptions& options,
                     const rigmesh::Pose& pose, std::set<JointId> pinned,
                     const rigmesh::Clip& clip);
    // As above; when the part changes, the pose goes back to rest, the pins
    // are cleared and the clip loses its keys (keeping its settings): joint
    // ids may not survive a new skeleton.
    void replacePart(PartId id, std::shared_ptr<const Part> part, const BuildOptions& options);
    // Swaps the engine part for one with the same mesh and skeleton whose
    // skin weights or bone locks differ (paint, weight clean-ups, locks):
    // pose, pins and keys stay as they are.
    // Throws rigmesh::Error (nothing changed) if the new part's skeleton or
    // vertex count differs.
    void replaceSkinning(PartId id, std::shared_ptr<const Part> part);
    // Throws rigmesh::Error when the pose names a joint the part's skeleton
    // does not have or holds a non-finite or zero quaternion / translation.
    // Live drags go through model/preview/PosePreview.h.
    void setPose(PartId id, const rigmesh::Pose& pose);
    // Throws rigmesh::Error on a joint the part's skeleton does not have.
    void setPinnedJoints(PartId id, std::set<JointId> pinned);
    // As above, also setting the part's other clips (sorted by name here):
    // for edits that change the skeleton and every clip with it (rebuild).
    void replacePart(PartId id, std::shared_ptr<const Part> part, const BuildOptions& options,
                     const rigmesh::Pose& pose, std::set<JointId> pinned, const rigmesh::Clip& clip,
                     std::vector<rigmesh::Clip> otherClips);
    // Throws rigmesh::Error when a key names a joint the part's skeleton does
    // not have or holds a pose that is not finite.
    void setClip(PartId id, const rigmesh::Clip& clip);
    // Sets the active clip and the others at once (sorted by name here).
    // Throws rigmesh::Error as setClip does, or when two clips share a name.
    void setClips(PartId id, const rigmesh::Clip& active, std::vector<rigmesh::Clip> others);
    // Throws rigmesh::Error on settings checkTimelineSettings refuses.
    void setTimeline(const TimelineSettings& settings);
    // Applies `edit` to the part's clip in place, in O(log n) per key it
    // changes. Throws rigmesh::Error (nothing changed) when an added key names
    // a joint the skeleton does not have or the edit does not fit the clip
    // (ClipEdit::applyTo).
    void editClip(PartId id, const ClipEdit& edit);

  signals:
    void partInserted(rigmesh::model::PartId id, int index);
    void partAboutToBeRemoved(rigmesh::model::PartId id, int index);
    void partRemoved(rigmesh::model::PartId id, int index);
    void partChanged(rigmesh::model::PartId id, rigmesh::model::Document::Changes what);
    void selectionChanged(const rigmesh::model::Selection& selection);
    void modifiedChanged(bool modified);
    void filePathChanged(const QString& path);
    void currentFrameChanged(int frame);
    void timelineChanged(const rigmesh::model::TimelineSettings& settings);
    void autoKeyChanged(bool on);

  private:
    PartNode& mutablePart(PartId id);

    DocumentContents contents_;
    Selection selection_;
    QUndoStack undoStack_;
    QString filePath_;
    QString untitledName_;
    bool autoKey_ = false;
};

}  // namespace rigmesh::model

Q_DECLARE_OPERATORS_FOR_FLAGS(rigmesh::model::Document::Changes)
