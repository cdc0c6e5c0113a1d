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
#include <memory>
#include <vector>

#include "model/PartNode.h"
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
    // The file name, or "Untitled" for a new document.
    QString displayName() const;
    bool isModified() const { return !undoStack_.isClean(); }
    // After a successful save: sets the path and marks the undo stack clean.
    void markSaved(const QString& path);

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
    void setName(PartId id, const QString& name);
    void setPlacement(PartId id, const Placement& placement);
    void setVisible(PartId id, bool visible);
    void replacePart(PartId id, std::shared_ptr<const Part> part, const BuildOptions& options);

  signals:
    void partInserted(rigmesh::model::PartId id, int index);
    void partAboutToBeRemoved(rigmesh::model::PartId id, int index);
    void partRemoved(rigmesh::model::PartId id, int index);
    void partChanged(rigmesh::model::PartId id, rigmesh::model::Document::Changes what);
    void selectionChanged(const rigmesh::model::Selection& selection);
    void modifiedChanged(bool modified);
    void filePathChanged(const QString& path);

  private:
    PartNode& mutablePart(PartId id);

    DocumentContents contents_;
    Selection selection_;
    QUndoStack undoStack_;
    QString filePath_;
};

}  // namespace rigmesh::model

Q_DECLARE_OPERATORS_FOR_FLAGS(rigmesh::model::Document::Changes)
