// Example content compiled into the binaries.
#pragma once

namespace rigmesh::resources {

// The example sketch (a biped silhouette) as the JSON text of a sketch file.
const char* exampleSketchJson();

}  // namespace rigmesh::resources
