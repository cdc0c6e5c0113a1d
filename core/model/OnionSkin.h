// Onion skin: the keyed poses either side of the current frame,
// drawn as translucent ghosts. Blender offers this only for grease pencil;
// here it shows where a part comes from and goes to while posing between
// keys.
#pragma once

#include "model/Document.h"

namespace rigmesh::model {

struct OnionPoses {
    const rigmesh::Pose* previous = nullptr;  // the last key before the current frame
    const rigmesh::Pose* next = nullptr;      // the first key after it
};

// Keys of the part's active clip more than half a frame before or after the
// document's current time (a key on the current frame is the pose itself).
OnionPoses onionPoses(const Document& document, PartId part);

}  // namespace rigmesh::model
