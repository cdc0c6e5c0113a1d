// The user-facing name of a bone: the name an imported file gave it, or the
// joint it ends at ("Joint 3"), which is how the studio selects a bone (the
// outliner's joint rows, the weight views, the paint tool).
#pragma once

#include <QString>

#include "part/Part.h"

namespace rigmesh::model {

// Throws rigmesh::Error if the part has no such bone.
QString boneDisplayName(const Part& part, BoneId bone);

}  // namespace rigmesh::model
