#include "part/Part.h"

namespace rigmesh {

std::vector<BoneSegment> Part::boneSegments() const {
    std::vector<BoneSegment> segments;
    segments.reserve(skeleton.bones().size());
    for (const Bone& bone : skeleton.bones())
        segments.push_back(
            {skeleton.joint(bone.head).position, skeleton.joint(bone.tail).position});
    return segments;
}

}  // namespace rigmesh
