#include "model/commands/BoneEditCommand.h"

#include "model/CountText.h"

#include <QCoreApplication>

#include <nlohmann/json.hpp>

#include "base/Error.h"
#include "model/RigCarryOver.h"

namespace rigmesh::model {

namespace {

const Part& riggedPart(const Document& document, PartId id) {
    const PartNode& node = document.part(id);
    if (!node.part || node.part->skeleton.boneCount() == 0)
        throw Error(QCoreApplication::translate("rigmesh::model::BoneEditCommand",
                                                "The part has no skeleton to edit.")
                        .toStdString());
    return *node.part;
}

}  // namespace

std::unique_ptr<BoneEditCommand> BoneEditCommand::split(Document& document, PartId part,
                                                        BoneId bone, const Vec3& at) {
    const Placement& placement = document.part(part).placement;
    BoneEditResult result = splitBoneAt(riggedPart(document, part), bone, placement.toLocal(at));
    return std::unique_ptr<BoneEditCommand>(
        new BoneEditCommand(document, part, bone, &at, std::move(result)));
}

std::unique_ptr<BoneEditCommand> BoneEditCommand::remove(Document& document, PartId part,
                                                         BoneId bone) {
    BoneEditResult result = deleteBone(riggedPart(document, part), bone);
    return std::unique_ptr<BoneEditCommand>(
        new BoneEditCommand(document, part, bone, nullptr, std::move(result)));
}

BoneEditCommand::BoneEditCommand(Document& document, PartId part, BoneId bone, const Vec3* at,
                                 BoneEditResult result)
    : document_(document),
      id_(part),
      index_(document.indexOf(part)),
      bone_(bone),
      split_(at != nullptr),
      before_(document.part(part)),
      result_(std::move(result)) {
    if (at)
        at_ = *at;
    after_ = editedNode(before_, std::make_shared<const Part>(result_.part));
    setText(split_ ? tr("Split Bone %1 of %2").arg(bone).arg(before_.name)
                   : tr("Delete Bone %1 of %2").arg(bone).arg(before_.name));
}

QString BoneEditCommand::summary() const {
    return tr("%1 in %2 ms: %3 vertices and %4 re-skinned")
        .arg(text())
        .arg(result_.milliseconds, 0, 'f', 0)
        .arg(result_.reskinned.size())
        .arg(countText(result_.bonesInvolved, tr("1 bone"), tr("%1 bones")));
}

void BoneEditCommand::redo() {
    document_.replaceNode(id_, after_);
}

void BoneEditCommand::undo() {
    document_.replaceNode(id_, before_);
}

nlohmann::json BoneEditCommand::recipeStep() const {
    nlohmann::json step = {
        {"command", split_ ? "split_bone" : "delete_bone"}, {"part", index_}, {"bone", bone_}};
    if (split_)
        step["at"] = {at_.x(), at_.y(), at_.z()};
    return step;
}

}  // namespace rigmesh::model
