#include "model/commands/RigPartCommand.h"

#include <algorithm>
#include <nlohmann/json.hpp>
#include <stdexcept>

#include "base/Error.h"
#include "model/ErrorText.h"

namespace rigmesh::model {

namespace {

// The parts' meshes in the first one's frame, one after another. Their
// surface is a file's, maybe open, if any one's is (Part::surfaceFromFile).
Part joined(const std::vector<RigPartCommand::Source>& parts) {
    Part part;
    part.name = parts.front().part->name;
    part.surfaceFromFile = std::any_of(
        parts.begin(), parts.end(),
        [](const RigPartCommand::Source& source) { return source.part->surfaceFromFile; });
    const Placement& frame = parts.front().placement;
    const Eigen::Quaterniond toFrame = frame.rotation.conjugate();
    for (const RigPartCommand::Source& source : parts) {
        const int offset = part.mesh.vertexCount();
        for (const Vec3& v : source.part->mesh.vertices)
            part.mesh.vertices.push_back(
                toFrame *
                (source.placement.rotation * v + source.placement.translation - frame.translation));
        for (const auto& [a, b, c] : source.part->mesh.faces)
            part.mesh.faces.push_back({a + offset, b + offset, c + offset});
    }
    return part;
}

}  // namespace

RigPartCommand::Rigged RigPartCommand::rigged(std::vector<Source> parts,
                                              const RigProgress& progress) {
    if (parts.empty() ||
        std::any_of(parts.begin(), parts.end(), [](const Source& s) { return !s.part; }))
        throw Error(MessageId::RigNoPart);
    for (const Source& source : parts)
        if (source.part->skeleton.jointCount() > 0)
            throw Error(MessageId::AutoRigPartIsRigged, source.part->name);
    AutoRigResult result = parts.size() == 1 ? autoRigPart(*parts.front().part, {}, progress)
                                             : autoRigPart(joined(parts), {}, progress);
    Rigged rigged;
    rigged.from = std::move(parts);
    rigged.to = std::make_shared<const Part>(std::move(result.part));
    rigged.rigSurface = std::make_shared<const TriMesh>(std::move(result.rigSurface));
    rigged.repairs = std::move(result.repairs);
    rigged.verticesWithoutVisibleBone = result.verticesWithoutVisibleBone;
    return rigged;
}

RigPartCommand::Rigged RigPartCommand::rigged(std::shared_ptr<const Part> part,
                                              const RigProgress& progress) {
    return rigged(std::vector<Source>{{std::move(part), Placement{}}}, progress);
}

std::vector<RigPartCommand::Source> RigPartCommand::sourcesOf(const Document& document,
                                                              const std::vector<PartId>& ids) {
    std::vector<Source> sources;
    for (const PartId id : ids) {
        if (!document.contains(id))
            throw Error(MessageId::NoSuchPart);
        sources.push_back({document.part(id).part, document.part(id).placement});
    }
    return sources;
}

std::unique_ptr<RigPartCommand> RigPartCommand::fromRigged(Document& document,
                                                           const std::vector<PartId>& ids,
                                                           const Rigged& result) {
    if (ids.empty() || ids.size() != result.from.size())
        throw std::logic_error("The parts to rig do not match the rigged result.");
    for (std::size_t i = 0; i < ids.size(); ++i) {
        if (!document.contains(ids[i]))
            throw Error(MessageId::PartGone);
        const PartNode& node = document.part(ids[i]);
        // One part is rigged in its own frame, whatever its placement.
        if (node.part != result.from[i].part ||
            (ids.size() > 1 && !(node.placement == result.from[i].placement)))
            throw Error(MessageId::RigPartChanged);
    }
    for (std::size_t i = 1; i < ids.size(); ++i)
        if (document.indexOf(ids[i]) <= document.indexOf(ids[i - 1]))
            throw Error(MessageId::RigPartsOutOfOrder);
    return std::unique_ptr<RigPartCommand>(new RigPartCommand(document, ids, result));
}

std::unique_ptr<RigPartCommand> RigPartCommand::fromRigged(Document& document, PartId id,
                                                           const Rigged& result) {
    return fromRigged(document, std::vector<PartId>{id}, result);
}

std::unique_ptr<RigPartCommand> RigPartCommand::create(Document& document,
                                                       const std::vector<PartId>& ids) {
    return fromRigged(document, ids, rigged(sourcesOf(document, ids)));
}

std::unique_ptr<RigPartCommand> RigPartCommand::create(Document& document, PartId id) {
    return create(document, std::vector<PartId>{id});
}

RigPartCommand::RigPartCommand(Document& document, const std::vector<PartId>& ids,
                               const Rigged& result)
    : document_(document),
      ids_(ids),
      result_(result),
      options_(document.part(ids.front()).options) {
    for (const PartId id : ids)
        indices_.push_back(document.indexOf(id));
    for (std::size_t i = 1; i < ids.size(); ++i)
        removed_.push_back(document.part(ids[i]));
    const QString name = document.part(ids.front()).name;
    if (ids.size() == 1)
        setText(tr("Rig %1").arg(name));
    else
        setText(
            tr("Rig %1 with %n more part(s)", nullptr, static_cast<int>(ids.size() - 1)).arg(name));
}

void RigPartCommand::redo() {
    for (std::size_t i = 1; i < ids_.size(); ++i)
        document_.removePart(ids_[i]);
    document_.replacePart(ids_.front(), result_.to, options_);
}

void RigPartCommand::undo() {
    document_.replacePart(ids_.front(), result_.from.front().part, options_);
    // In index order, so each lands where it was.
    for (std::size_t i = 1; i < ids_.size(); ++i)
        document_.insertPart(indices_[i], removed_[i - 1]);
}

nlohmann::json RigPartCommand::recipeStep() const {
    if (indices_.size() == 1)
        return {{"command", "rig"}, {"part", indices_.front()}};
    return {{"command", "rig"}, {"parts", indices_}};
}

QStringList RigPartCommand::repairs() const {
    QStringList list;
    for (const Message& repair : result_.repairs)
        list << messageText(repair);
    return list;
}

QString RigPartCommand::summary() const {
    const QString name = document_.part(ids_.front()).name;
    QString text =
        ids_.size() == 1
            ? tr("%1 rigged with %n bone(s)", nullptr, result_.to->skeleton.boneCount()).arg(name)
            : tr("%1 and %2 more parts rigged as one with %n bone(s)", nullptr,
                 result_.to->skeleton.boneCount())
                  .arg(name)
                  .arg(ids_.size() - 1);
    const QStringList repaired = repairs();
    if (!repaired.isEmpty())
        text += QStringLiteral("; ") + repaired.join(QStringLiteral("; "));
    if (result_.verticesWithoutVisibleBone > 0)
        text += tr("; %n vertex(es) saw no bone from inside and follow the closest one", nullptr,
                   result_.verticesWithoutVisibleBone);
    return text;
}

}  // namespace rigmesh::model
