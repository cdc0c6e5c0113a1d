#include "model/commands/BoneEditCommand.h"

#include "model/CountText.h"

#include <nlohmann/json.hpp>

#include "base/Error.h"
#include "model/RigCarryOver.h"
#include "part/BoneConnection.h"

namespace rigmesh::model {

namespace {

const Part& riggedPart(const Document& document, PartId id) {
    const PartNode& node = document.part(id);
    if (!node.part || node.part->skeleton.boneCount() == 0)
        throw Error(MessageId::BoneEditNoSkeleton);
    return *node.part;
}

}  // namespace

std::unique_ptr<BoneEditCommand> BoneEditCommand::split(Document& document, PartId part,
                                                        BoneId bone, const Vec3& at) {
    const Placement& placement = document.part(part).placement;
    BoneEditResult result = splitBoneAt(riggedPart(document, part), bone, placement.toLocal(at));
    return std::unique_ptr<BoneEditCommand>(
        new BoneEditCommand(document, part, bone, Kind::Split, &at, std::move(result)));
}

std::unique_ptr<BoneEditCommand> BoneEditCommand::remove(Document& document, PartId part,
                                                         BoneId bone) {
    BoneEditResult result = deleteBone(riggedPart(document, part), bone);
    return std::unique_ptr<BoneEditCommand>(
        new BoneEditCommand(document, part, bone, Kind::Delete, nullptr, std::move(result)));
}

std::unique_ptr<BoneEditCommand> BoneEditCommand::connect(Document& document, PartId part,
                                                          BoneId bone) {
    BoneEditResult result;
    result.part = connectBone(riggedPart(document, part), bone);
    return std::unique_ptr<BoneEditCommand>(
        new BoneEditCommand(document, part, bone, Kind::Connect, nullptr, std::move(result)));
}

BoneEditCommand::BoneEditCommand(Document& document, PartId part, BoneId bone, Kind kind,
                                 const Vec3* at, BoneEditResult result)
    : document_(document),
      id_(part),
      index_(document.indexOf(part)),
      bone_(bone),
      kind_(kind),
      before_(document.part(part)),
      result_(std::move(result)) {
    if (at)
        at_ = *at;
    after_ = editedNode(before_, std::make_shared<const Part>(result_.part));
    // An imported bone by the name its file gave it ("thigh.L"), others by id.
    const auto named = before_.part->boneNames.find(bone);
    const QString label = named != before_.part->boneNames.end()
                              ? QString::fromStdString(named->second)
                              : QString::number(bone);
    switch (kind_) {
        case Kind::Split:
            setText(tr("Split Bone %1 of %2").arg(label, before_.name));
            break;
        case Kind::Delete:
            setText(tr("Delete Bone %1 of %2").arg(label, before_.name));
            break;
        case Kind::Connect:
            setText(tr("Connect Bone %1 of %2").arg(label, before_.name));
            break;
    }
}

QString BoneEditCommand::summary() const {
    if (kind_ == Kind::Connect)
        return text();  // nothing is solved again
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
    const char* command = kind_ == Kind::Split    ? "split_bone"
                          : kind_ == Kind::Delete ? "delete_bone"
                                                  : "connect_bone";
    nlohmann::json step = {{"command", command}, {"part", index_}, {"bone", bone_}};
    if (kind_ == Kind::Split)
        step["at"] = {at_.x(), at_.y(), at_.z()};
    return step;
}

}  // namespace rigmesh::model
