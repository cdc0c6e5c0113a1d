// Exports a document's parts through the engine's exporter (io/SceneExport):
// every part at its placement and current pose; the clip of one part (the
// preferred one if it has keys, else the first part with keys) animates it,
// since one skeleton's animation is what the formats carry per file.
#pragma once

#include <QStringList>
#include <string>

#include "io/SceneExport.h"
#include "model/Document.h"

namespace rigmesh::model {

struct DocumentExportResult {
    QStringList warnings;  // e.g. keys of other parts that were not exported
};

// Throws rigmesh::Error (no parts, unknown format, write failure).
DocumentExportResult exportDocument(const Document& document, const std::string& path,
                                    const ExportOptions& options = {},
                                    PartId preferredAnimatedPart = kNoPart,
                                    bool visibleOnly = false);

}  // namespace rigmesh::model
