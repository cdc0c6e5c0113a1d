#include "model/preview/SkinningPreview.h"

namespace rigmesh::model {

SkinningPreview::SkinningPreview(Document& document, PartId id)
    : PartPreview(document, id, document.part(id).part) {}

void SkinningPreview::put(const std::shared_ptr<const Part>& part) {
    document_->replaceSkinning(id_, part);
}

}  // namespace rigmesh::model
