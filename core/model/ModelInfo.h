// Versions of the layers the CLI and the studio are built on.
#pragma once

#include <QString>

namespace rigmesh::model {

// Human-readable versions of the layers, e.g. "RigMesh Studio 0.1.0 (Qt 6.4.2)".
QString buildInfo();

}  // namespace rigmesh::model
