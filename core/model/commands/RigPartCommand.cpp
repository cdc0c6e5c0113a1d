#include "model/commands/RigPartCommand.h"

#include <nlohmann/json.hpp>

#include "base/Error.h"
#include "model/ErrorText.h"

namespace rigmesh::model {

RigPartCommand::Rigged RigPartCommand::rigged(std::shared_ptr<const Part> part,
                                              const RigProgress& progress) {
    if (!part)
        throw Error("There is no part to rig.");
    AutoRigResult result = autoRigPart(*part, {}, progress);
    Rigged rigged;
    rigged.from = std::move(part);
    rigged.to = std::make_shared<const Part>(std::move(result.part));
    rigged.repairs = std::move(result.repairs);
    rigged.verticesWithoutVisibleBone = result.verticesWithoutVisibleBone;
    return rigged;
}

std::unique_ptr<RigPartCommand> RigPartCommand::fromRigged(Document& document, PartId id,
                                                           const Rigged& result) {
    if (!document.contains(id))
        throw Error("The part is no longer in the document.");
    if (document.part(id).part != result.from)
        throw Error("The part changed while it was rigged; nothing was changed.");
    return std::unique_ptr<RigPartCommand>(new RigPartCommand(document, id, result));
}

std::unique_ptr<RigPartCommand> RigPartCommand::create(Document& document, PartId id) {
    if (!document.contains(id))
        throw Error("There is no such part.");
    return fromRigged(document, id, rigged(document.part(id).part));
}

RigPartCommand::RigPartCommand(Document& document, PartId id, const Rigged& result)
    : document_(document),
      id_(id),
      index_(document.indexOf(id)),
      result_(result),
      options_(document.part(id).options) {
    setText(tr("Rig %1").arg(document.part(id).name));
}

void RigPartCommand::redo() {
    document_.replacePart(id_, result_.to, options_);
}

void RigPartCommand::undo() {
    document_.replacePart(id_, result_.from, options_);
}

nlohmann::json RigPartCommand::recipeStep() const {
    return {{"command", "rig"}, {"part", index_}};
}

QStringList RigPartCommand::repairs() const {
    QStringList list;
    for (const Message& repair : result_.repairs)
        list << messageText(repair);
    return list;
}

QString RigPartCommand::summary() const {
    QString text = tr("%1 rigged with %n bone(s)", nullptr, result_.to->skeleton.boneCount())
                       .arg(document_.part(id_).name);
    const QStringList repaired = repairs();
    if (!repaired.isEmpty())
        text += tr("; repaired: %1").arg(repaired.join(QStringLiteral(", ")));
    if (result_.verticesWithoutVisibleBone > 0)
        text += tr("; %n vertex(es) saw no bone from inside and follow the closest one", nullptr,
                   result_.verticesWithoutVisibleBone);
    return text;
}

}  // namespace rigmesh::model
