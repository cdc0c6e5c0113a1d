// Merge one part into another (paper 3.2) as one undoable step: the engine
// merge (merge/MergeParts.h) runs in create(), before anything is pushed, so
// a refused merge throws rigmesh::Error and changes nothing. Redo replaces
// the target by the merged part (same id, name and placement) and removes the
// dragged part; undo restores both exactly. The target's pose, pins and keys
// carry over for the joints the merged skeleton keeps (RigCarryOver), the
// dragged part's onto their new joint ids where they still turn the same
// bones (MergeRigCarry); summary() says what of either was dropped.
#pragma once

#include <QCoreApplication>
#include <QUndoCommand>
#include <memory>
#include <variant>

#include "merge/MergeParts.h"
#include "model/Document.h"
#include "model/recipe/RecipeStepSource.h"

namespace rigmesh::model {

// A joint by id, or by a point in document coordinates (the nearest joint;
// for a split's target: the point projected on the nearest bone).
using JointChoice = std::variant<rigmesh::JointId, Vec3>;

struct MergeSpec {
    MergeMode mode = MergeMode::Snap;
    JointChoice draggedJoint = rigmesh::JointId{0};
    JointChoice target = rigmesh::JointId{0};
    Reskin reskin = Reskin::Local;
    bool compareGlobal = false;  // also time the global re-skin (stats)
};

// A merge computed but not yet a command: the spec with its joints resolved
// and the engine's result.
struct ComputedMerge {
    MergeSpec resolved;
    MergeResult result;
};

class MergePartsCommand : public QUndoCommand, public RecipeStepSource {
    Q_DECLARE_TR_FUNCTIONS(MergePartsCommand)
  public:
    // Throws rigmesh::Error: unknown parts or joints, a part merged into
    // itself, or a merge the engine refuses (with its reason).
    static std::unique_ptr<MergePartsCommand> create(Document& document, PartId dragged,
                                                     PartId target, const MergeSpec& spec);
    // create() in two halves, for a background job (widgets/jobs): the
    // engine merge of copies of the two nodes (touches no document; throws
    // as create() does), then the command on the GUI thread.
    static ComputedMerge compute(const PartNode& dragged, const PartNode& target,
                                 const MergeSpec& spec);
    static std::unique_ptr<MergePartsCommand> fromComputed(Document& document, PartId dragged,
                                                           PartId target, ComputedMerge computed);

    void redo() override;
    void undo() override;
    nlohmann::json recipeStep() const override;

    const MergeStats& stats() const { return stats_; }
    PartId mergedPart() const { return targetId_; }
    // For the user: what happened ("merged in 41 ms, 2 bones pruned") and
    // what of the poses, pins and keys was dropped.
    QString summary() const;

  private:
    MergePartsCommand(Document& document, PartId dragged, PartId target, const MergeSpec& spec,
                      MergeResult result);

    Document& document_;
    PartId draggedId_, targetId_;
    int draggedIndex_, targetIndex_;
    MergeSpec spec_;  // with joints resolved to ids (split target: the point)
    PartNode draggedNode_, targetNode_, mergedNode_;
    MergeStats stats_;
    int droppedJoints_ = 0;  // of the target
    QString draggedCarry_;   // what of the dragged part's rig was kept and dropped
};

}  // namespace rigmesh::model
