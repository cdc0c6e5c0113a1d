// The document model layer. It will hold the scene graph of parts, the clip,
// the selection and the undo stack (studio issue); for now it only reports
// what it is built on, so the CLI can link the same layers the studio will.
#pragma once

#include <QString>

namespace rigmesh::model {

// Human-readable versions of the layers, e.g. "RigMesh Studio 0.1.0 (Qt 6.4.2)".
QString buildInfo();

}  // namespace rigmesh::model
