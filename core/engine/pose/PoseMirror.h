// A pose seen in the mirror, as Blender's Paste Pose Flipped (Ctrl+Shift+V)
// gives it: every bone takes its mirror image's rotation reflected through
// the part's left-right plane (rig/MirrorSymmetry), the root translation
// reflected, so a left arm raised becomes a right arm raised. On a skeleton
// symmetric about the plane (rig/SkeletonSymmetry) the posed joints are the
// reflection of the pose's.
#pragma once

#include "pose/Pose.h"
#include "rig/MirrorSymmetry.h"

namespace rigmesh {

Pose mirroredPose(const Skeleton& skeleton, const Pose& pose, const PartSymmetry& symmetry);

}  // namespace rigmesh
