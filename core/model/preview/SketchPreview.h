// A part being sketched, shown while the stroke is still open (Monster Mash
// and Teddy inflate under the pen): PartPreview.h over a part not yet in the
// document. preview() puts the built part in at the end of the list with the
// id the part will keep (the next free one) or swaps the one already shown;
// revert() takes it out again and gives the id back. commit() ends as the
// release of the stroke always did: one CreatePartCommand, with that id.
#pragma once

#include <QString>
#include <memory>
#include <vector>

#include "model/PartBuilder.h"
#include "model/preview/PartPreview.h"

namespace rigmesh::model {

// What a sketch becomes: the inputs of CreatePartCommand::fromBuilt.
struct SketchedPart {
    std::vector<Vec2> stroke;
    QString name;
    BuiltPart built;
    Placement placement;
};

class SketchPreview final : public PartPreview<std::shared_ptr<const SketchedPart>> {
  public:
    // Nothing shown yet (the original state is "no part").
    explicit SketchPreview(Document& document);
    ~SketchPreview() { revert(); }

    // The id the sketched part has while shown, or will get when it is shown
    // or committed now.
    PartId upcomingId() const;

    // Takes the preview out and pushes the CreatePartCommand of `sketched`
    // (one undo step), which gets the id the preview had: the previewed part
    // itself when the stroke did not change since it was shown. Returns the
    // new part's id.
    PartId commit(const SketchedPart& sketched);
    // The same for the part shown; kNoPart (nothing pushed) without one.
    PartId commit();

  private:
    void put(const std::shared_ptr<const SketchedPart>& sketched) override;
};

}  // namespace rigmesh::model
