// The demo animation `rigmesh build --pose-demo` exports: a
// three-key clip, rest at 0 s, an IK bend of the end joint at 0.5 s, rest
// again at 1 s, so that every exported file carries an animation.
#pragma once

#include "part/Part.h"
#include "pose/Clip.h"

namespace rigmesh {

// The end joint is the leaf joint farthest from the root (by distance). It is
// dragged (InverseKinematics.h) sideways, perpendicular to its bone in the
// sketch plane, by half the length of its chain to the root, so that the
// whole chain bends. Linear interpolation, 24 frames per second. Throws Error
// on a part without bones.
Clip poseDemoClip(const Part& part);

// The pose of the demo clip at 0.5 s.
Pose poseDemoBend(const Part& part);

}  // namespace rigmesh
