// Exports a document's parts through the engine's exporter (io/SceneExport):
// every part at its placement and current pose, each its own skinned mesh
// animated by its own clips (its bones share one armature
// node, SceneExport.h). Every clip with keys is written; the clips of all
// parts with one name (clipName: "Action" when unnamed) are one animation.
#pragma once

#include <QStringList>
#include <string>

#include "io/SceneExport.h"
#include "model/Document.h"

namespace rigmesh::model {

struct DocumentExportResult {
    QStringList warnings;  // e.g. clips not written (the pose became the rest)
};

// Throws rigmesh::Error (no parts, unknown format, write failure).
DocumentExportResult exportDocument(const Document& document, const std::string& path,
                                    const ExportOptions& options = {}, bool visibleOnly = false);
// The same from a copy of the parts (a background job's snapshot).
DocumentExportResult exportParts(const std::vector<PartNode>& parts, const std::string& path,
                                 const ExportOptions& options = {}, bool visibleOnly = false);

// An export written but not yet in place (io/SceneExport.h: StagedExport):
// a background job stages it off the GUI thread, and the GUI thread commits
// it when the job is applied, or drops it when the user cancelled.
struct StagedDocumentExport {
    StagedExport files;
    QStringList warnings;
};
StagedDocumentExport stageParts(const std::vector<PartNode>& parts, const std::string& path,
                                const ExportOptions& options = {}, bool visibleOnly = false);

}  // namespace rigmesh::model
