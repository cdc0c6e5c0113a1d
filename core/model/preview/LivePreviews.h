// How many previews (PartPreview.h) a document shows now. A preview puts a
// state on the document that is no undo step yet (a drag, a brush stroke, a
// sketch under the pen) and is committed or reverted when the gesture ends;
// what is written for recovery (model/Autosave) waits while one is shown.
#pragma once

namespace rigmesh::model {

class Document;

void notePreviewShown(Document& document);
void notePreviewEnded(Document& document);
bool hasLivePreview(const Document& document);

}  // namespace rigmesh::model
