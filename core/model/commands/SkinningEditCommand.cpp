#include "model/commands/SkinningEditCommand.h"

#include <string>

#include "base/Error.h"

namespace rigmesh::model {

SkinningEditCommand::SkinningEditCommand(Document& document, PartId part, MessageId noSkeleton)
    : document_(document),
      id_(part),
      index_(document.indexOf(part)),
      name_(document.part(part).name),
      before_(document.part(part).part) {
    if (!before_ || before_->skeleton.boneCount() == 0)
        throw Error(noSkeleton);
}

void SkinningEditCommand::setResult(std::shared_ptr<const Part> after, nlohmann::json step,
                                    int changed) {
    after_ = std::move(after);
    step_ = std::move(step);
    changed_ = changed;
}

void SkinningEditCommand::redo() {
    document_.replaceSkinning(id_, after_);
}

void SkinningEditCommand::undo() {
    document_.replaceSkinning(id_, before_);
}

}  // namespace rigmesh::model
