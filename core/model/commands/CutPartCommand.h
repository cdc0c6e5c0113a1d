// Cut a part in two by a plane or a stroke (paper 3.1) as one undoable step:
// the engine cut (cut/CutPart.h) runs in create(), before anything is
// pushed, so a refused cut throws rigmesh::Error and changes nothing. Redo
// replaces the part by the larger piece (same id, name and selection, as an
// arm cut off leaves the body the body) and inserts the other after it (a new
// id, "<name> cut"); undo restores the part exactly. Both pieces keep the
// pose, pins and keys of the joints they still have.
#pragma once

#include <QCoreApplication>
#include <QUndoCommand>
#include <memory>
#include <vector>

#include "cut/CutPart.h"
#include "model/Document.h"
#include "model/recipe/RecipeStepSource.h"

namespace rigmesh::model {

struct CutSpec {
    Vec3 point = Vec3::Zero();  // the plane, in document coordinates
    Vec3 normal = Vec3::UnitX();
    // Or a stroke drawn in a view: points (right, up) on the view plane
    // through the part's centre, swept along the view direction (paper 3.1);
    // used when not empty.
    std::vector<Vec2> viewStroke;
    Vec3 viewDirection = -Vec3::UnitZ();
    Vec3 viewUp = Vec3::UnitY();
    CutStyle style = CutStyle::Smooth;
    // The pieces' names, behind the cut first (CutResult's order); empty:
    // the part's name for the larger piece, "<name> cut" for the other.
    QString names[2];
};

class CutPartCommand : public QUndoCommand, public RecipeStepSource {
    Q_DECLARE_TR_FUNCTIONS(CutPartCommand)
  public:
    // Throws rigmesh::Error: unknown part, or a cut the engine refuses.
    static std::unique_ptr<CutPartCommand> create(Document& document, PartId part,
                                                  const CutSpec& spec);

    void redo() override;
    void undo() override;
    nlohmann::json recipeStep() const override;
    PartId newPart() const { return pieces_[1].id; }
    double milliseconds() const { return milliseconds_; }

  private:
    CutPartCommand(Document& document, PartId part, const CutSpec& spec);

    Document& document_;
    PartId id_;
    int index_;
    CutSpec spec_;
    PartNode original_;
    PartNode pieces_[2];
    double milliseconds_ = 0.0;
};

}  // namespace rigmesh::model
