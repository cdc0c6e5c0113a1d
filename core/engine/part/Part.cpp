#include "part/Part.h"

#include "rig/BoneSegments.h"

namespace rigmesh {

std::vector<BoneSegment> Part::boneSegments() const {
    return segmentsOf(skeleton);
}

}  // namespace rigmesh
