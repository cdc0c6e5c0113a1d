#include "model/preview/SketchPreview.h"

#include "model/GuardedUndo.h"
#include "model/commands/CreatePartCommand.h"

namespace rigmesh::model {

SketchPreview::SketchPreview(Document& document)
    : PartPreview(document, document.nextPartId(), nullptr) {}

PartId SketchPreview::upcomingId() const {
    if (!document_)
        return kNoPart;
    return document_->contains(id_) ? id_ : document_->nextPartId();
}

void SketchPreview::put(const std::shared_ptr<const SketchedPart>& sketched) {
    if (!sketched) {
        if (document_->contains(id_)) {
            document_->removePart(id_);
            document_->releasePartId(id_);
        }
        return;
    }
    PartNode node = CreatePartCommand::nodeFromBuilt(sketched->name, sketched->stroke,
                                                     sketched->built, sketched->placement);
    if (document_->contains(id_)) {
        node.id = id_;
        document_->replaceNode(id_, std::move(node));
        return;
    }
    // Taken as CreatePartCommand::fromBuilt takes it, so the commit gets it
    // again once revert() has given it back.
    id_ = document_->allocatePartId();
    node.id = id_;
    document_->insertPart(document_->partCount(), std::move(node));
}

PartId SketchPreview::commit(const SketchedPart& sketched) {
    if (!document_)
        return kNoPart;
    revert();
    auto command = CreatePartCommand::fromBuilt(*document_, sketched.stroke, sketched.name,
                                                sketched.built, sketched.placement);
    const PartId id = command->partId();
    pushCommand(*document_, std::move(command));
    return id;
}

PartId SketchPreview::commit() {
    if (!previewing() || !current())
        return kNoPart;
    const std::shared_ptr<const SketchedPart> shown = current();
    return commit(*shown);
}

}  // namespace rigmesh::model
