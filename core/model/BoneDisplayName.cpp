#include "model/BoneDisplayName.h"

#include "model/PartNode.h"

namespace rigmesh::model {

QString boneDisplayName(const Part& part, BoneId bone) {
    const Bone& b = part.skeleton.bone(bone);
    const auto named = part.boneNames.find(bone);
    if (named != part.boneNames.end())
        return QString::fromStdString(named->second);
    return jointDisplayName(b.tail);
}

}  // namespace rigmesh::model
