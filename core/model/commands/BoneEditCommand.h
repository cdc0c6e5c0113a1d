// Split or delete a bone (paper 3.3), or connect a disconnected one to its
// parent (Edit > Connect Bone, part/BoneConnection.h), as one undoable step.
// The engine edit (cut/BoneEdits.h) runs in the factories, before anything
// is pushed, so a refused edit throws rigmesh::Error and changes nothing. The part keeps its
// id, name and placement, loses its stroke (a rebuild would undo the edit)
// and keeps the pose, pins and keys of its surviving joints; undo restores
// it exactly.
#pragma once

#include <QCoreApplication>
#include <QUndoCommand>
#include <memory>

#include "cut/BoneEdits.h"
#include "model/Document.h"
#include "model/recipe/RecipeStepSource.h"

namespace rigmesh::model {

class BoneEditCommand : public QUndoCommand, public RecipeStepSource {
    Q_DECLARE_TR_FUNCTIONS(BoneEditCommand)
  public:
    // `at` in document coordinates: the split point on the bone.
    static std::unique_ptr<BoneEditCommand> split(Document& document, PartId part, BoneId bone,
                                                  const Vec3& at);
    static std::unique_ptr<BoneEditCommand> remove(Document& document, PartId part, BoneId bone);
    // The bone's head moves onto its parent's tail (the pose and keys of
    // the joint that goes are dropped).
    static std::unique_ptr<BoneEditCommand> connect(Document& document, PartId part, BoneId bone);

    void redo() override;
    void undo() override;
    nlohmann::json recipeStep() const override;
    // For the user: what was solved again and how long it took.
    QString summary() const;
    double milliseconds() const { return result_.milliseconds; }

  private:
    enum class Kind { Split, Delete, Connect };
    BoneEditCommand(Document& document, PartId part, BoneId bone, Kind kind, const Vec3* at,
                    BoneEditResult result);

    Document& document_;
    PartId id_;
    int index_;
    BoneId bone_;
    Kind kind_;
    Vec3 at_ = Vec3::Zero();  // document coordinates (split)
    PartNode before_, after_;
    BoneEditResult result_;
};

}  // namespace rigmesh::model
