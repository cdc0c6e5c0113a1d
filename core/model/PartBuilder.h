// Builds the engine Part of a sketch with a part's build options. Runs
// before any command is pushed: a bad stroke throws rigmesh::Error (a user
// message) and the document is never touched.
#pragma once

#include <QString>
#include <memory>
#include <vector>

#include "base/Types.h"
#include "model/Document.h"
#include "model/PartNode.h"
#include "pipeline/SketchToPart.h"

namespace rigmesh::model {

SketchToPartOptions engineOptions(const BuildOptions& options);

// Throws rigmesh::Error when options.targetEdgeLength is not finite and >= 0
// (0 = automatic). How fine a length a sketch allows is the engine's call
// (pipeline/SurfaceLimits.h: at most kMaxSurfaceVertices vertices), checked
// when the part is built.
void checkBuildOptions(const std::vector<Vec2>& stroke, const BuildOptions& options);

// Throws rigmesh::Error with a user-readable reason on a bad stroke or options.
std::shared_ptr<const Part> buildPart(const std::vector<Vec2>& stroke, const QString& name,
                                      const BuildOptions& options);

struct BuiltPart {
    std::shared_ptr<const Part> part;
    BuildOptions options;  // with the edge length actually used (never 0)
};

// One resolution per document: a new sketch with the
// automatic edge length gets the document's (documentEdgeLength), so merged
// surfaces are uniform; the first part, or a sketch too small to build at
// that length, gets its own automatic length. The options returned record
// the length used. Throws as buildPart does.
BuiltPart buildPartForDocument(const Document& document, const std::vector<Vec2>& stroke,
                               const QString& name, const BuildOptions& options);
// The same given the document's edge length: touches no document, so a
// background job can run it (widgets/jobs).
BuiltPart buildPartAtDocumentLength(double documentLength, const std::vector<Vec2>& stroke,
                                    const QString& name, const BuildOptions& options);

// The edge length the document's sketched parts share: the first sketched
// part's; 0 if there is none or it was built with the automatic length by an
// older version. A part being previewed (`ignored`) does not count: it is
// not yet one of them.
double documentEdgeLength(const Document& document, PartId ignored = kNoPart);

}  // namespace rigmesh::model
