// Locks or unlocks a bone's weights, as Blender's vertex
// group lock: painting and the weight clean-ups then keep that bone's
// weights bit for bit. Undoable; saved with the part (Part::lockedBones);
// the recipe steps "lock_bone" and "unlock_bone".
#pragma once

#include <QCoreApplication>
#include <memory>

#include "model/commands/SkinningEditCommand.h"

namespace rigmesh::model {

class SetBoneLockCommand : public SkinningEditCommand {
    Q_DECLARE_TR_FUNCTIONS(SetBoneLockCommand)
  public:
    // Throws rigmesh::Error if the part has no such bone.
    static std::unique_ptr<SetBoneLockCommand> create(Document& document, PartId part, BoneId bone,
                                                      bool locked);

  private:
    SetBoneLockCommand(Document& document, PartId part)
        : SkinningEditCommand(document, part, MessageId::LockNoSkeleton) {}
};

}  // namespace rigmesh::model
