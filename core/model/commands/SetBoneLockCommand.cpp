#include "model/commands/SetBoneLockCommand.h"

#include <nlohmann/json.hpp>

#include "base/Error.h"
#include "model/BoneDisplayName.h"

namespace rigmesh::model {

std::unique_ptr<SetBoneLockCommand> SetBoneLockCommand::create(Document& document, PartId part,
                                                               BoneId bone, bool locked) {
    std::unique_ptr<SetBoneLockCommand> command(new SetBoneLockCommand(document, part));
    if (!command->before().skeleton.hasBone(bone))
        throw Error(MessageId::PaintLockedNoSuchBone, bone);
    auto after = command->editableCopy();
    if (locked)
        after->lockedBones.insert(bone);
    else
        after->lockedBones.erase(bone);
    const QString name = boneDisplayName(*after, bone);
    command->setResult(std::move(after),
                       {{"command", locked ? "lock_bone" : "unlock_bone"},
                        {"part", command->partIndex()},
                        {"bone", bone}},
                       0);
    command->setText((locked ? tr("Lock Weights of %1 in %2") : tr("Unlock Weights of %1 in %2"))
                         .arg(name, command->partName()));
    return command;
}

}  // namespace rigmesh::model
