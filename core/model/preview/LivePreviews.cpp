#include "model/preview/LivePreviews.h"

#include <QVariant>
#include <algorithm>

#include "model/Document.h"

namespace rigmesh::model {

namespace {

// Kept on the document itself (a dynamic property of the QObject), so the
// count lives and dies with it and needs nothing in Document.h.
constexpr const char* kCount = "rigmeshLivePreviews";

int count(const Document& document) {
    return document.property(kCount).toInt();
}

}  // namespace

void notePreviewShown(Document& document) {
    document.setProperty(kCount, count(document) + 1);
}

void notePreviewEnded(Document& document) {
    document.setProperty(kCount, std::max(0, count(document) - 1));
}

bool hasLivePreview(const Document& document) {
    return count(document) > 0;
}

}  // namespace rigmesh::model
