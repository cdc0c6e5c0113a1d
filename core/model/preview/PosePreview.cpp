#include "model/preview/PosePreview.h"

#include "model/PoseChange.h"
#include "model/commands/SetPoseCommand.h"

namespace rigmesh::model {

PosePreview::PosePreview(Document& document, PartId id)
    : PartPreview(document, id, document.part(id).pose) {}

void PosePreview::put(const rigmesh::Pose& pose) {
    document_->setPose(id_, pose);
}

bool PosePreview::commit(JointId draggedJoint) {
    if (!previewing() || identicalPoses(current(), original()))
        return false;
    pushPoseChange(*document_, id_,
                   new SetPoseCommand(*document_, id_, original(), current(), draggedJoint,
                                      CommandMerging::Never));
    committed();
    return true;
}

}  // namespace rigmesh::model
