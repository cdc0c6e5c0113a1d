// The example document the studio opens with: parts built from the sketches
// compiled into the binary, as a clean document with an empty history.
#pragma once

#include <memory>

#include "model/Document.h"

namespace rigmesh::studio {

std::unique_ptr<model::Document> makeExampleDocument();

}  // namespace rigmesh::studio
