#include "model/commands/ClipListCommand.h"

#include <algorithm>

#include "base/Error.h"
#include "model/PartClips.h"

namespace rigmesh::model {

namespace {

void checkNewName(const PartNode& node, const std::string& name) {
    checkClipName(name);
    if (findClip(node, name))
        throw Error(MessageId::ClipNameTaken, node.name.toStdString(), name);
}

nlohmann::json step(const char* command, const Document& document, PartId id) {
    return {{"command", command}, {"part", document.indexOf(id)}};
}

QString q(const std::string& text) {
    return QString::fromStdString(text);
}

}  // namespace

ClipListCommand::Clips ClipListCommand::clipsOf(const PartNode& node) {
    return {node.clip, node.otherClips};
}

rigmesh::Clip& ClipListCommand::clipNamed(Clips& clips, const PartNode& node,
                                          const std::string& name) {
    if (clipName(clips.active) == name)
        return clips.active;
    for (rigmesh::Clip& clip : clips.others)
        if (clipName(clip) == name)
            return clip;
    throw Error(MessageId::NoClipNamed, node.name.toStdString(), name);
}

std::unique_ptr<ClipListCommand> ClipListCommand::make(Document& document, PartId id, Clips after,
                                                       nlohmann::json step, const QString& text) {
    return std::unique_ptr<ClipListCommand>(
        new ClipListCommand(document, id, std::move(after), std::move(step), text));
}

std::unique_ptr<ClipListCommand> ClipListCommand::create(Document& document, PartId id,
                                                         const std::string& name) {
    const PartNode& node = document.part(id);
    checkNewName(node, name);
    Clips after = clipsOf(node);
    after.others.push_back(std::move(after.active));
    after.active = rigmesh::Clip(document.timeline().framesPerSecond);
    after.active.name = name;
    nlohmann::json s = step("new_clip", document, id);
    s["name"] = name;
    return make(document, id, std::move(after), std::move(s),
                tr("New clip %1 of %2").arg(q(name), node.name));
}

std::unique_ptr<ClipListCommand> ClipListCommand::duplicate(Document& document, PartId id,
                                                            const std::string& source,
                                                            const std::string& name) {
    const PartNode& node = document.part(id);
    Clips after = clipsOf(node);
    rigmesh::Clip copy = clipNamed(after, node, source);
    checkNewName(node, name);
    copy.name = name;
    after.others.push_back(std::move(after.active));
    after.active = std::move(copy);
    nlohmann::json s = step("duplicate_clip", document, id);
    s["clip"] = source;
    s["name"] = name;
    return make(document, id, std::move(after), std::move(s),
                tr("Duplicate clip %1 of %2 as %3").arg(q(source), node.name, q(name)));
}

std::unique_ptr<ClipListCommand> ClipListCommand::rename(Document& document, PartId id,
                                                         const std::string& from,
                                                         const std::string& to) {
    const PartNode& node = document.part(id);
    Clips after = clipsOf(node);
    rigmesh::Clip& clip = clipNamed(after, node, from);
    if (from != to)
        checkNewName(node, to);
    clip.name = to;
    nlohmann::json s = step("rename_clip", document, id);
    s["clip"] = from;
    s["name"] = to;
    return make(document, id, std::move(after), std::move(s),
                tr("Rename clip %1 of %2 to %3").arg(q(from), node.name, q(to)));
}

std::unique_ptr<ClipListCommand> ClipListCommand::remove(Document& document, PartId id,
                                                         const std::string& name) {
    const PartNode& node = document.part(id);
    Clips after = clipsOf(node);
    clipNamed(after, node, name);  // it exists
    if (after.others.empty())
        throw Error(MessageId::DeleteOnlyClip, node.name.toStdString());
    if (clipName(after.active) == name) {
        after.active = std::move(after.others.front());  // others are sorted by name
        after.others.erase(after.others.begin());
    } else {
        std::erase_if(after.others, [&](const rigmesh::Clip& c) { return clipName(c) == name; });
    }
    nlohmann::json s = step("delete_clip", document, id);
    s["clip"] = name;
    return make(document, id, std::move(after), std::move(s),
                tr("Delete clip %1 of %2").arg(q(name), node.name));
}

std::unique_ptr<ClipListCommand> ClipListCommand::activate(Document& document, PartId id,
                                                           const std::string& name) {
    const PartNode& node = document.part(id);
    Clips after = clipsOf(node);
    rigmesh::Clip chosen = clipNamed(after, node, name);
    if (clipName(after.active) != name) {
        std::erase_if(after.others, [&](const rigmesh::Clip& c) { return clipName(c) == name; });
        after.others.push_back(std::move(after.active));
        after.active = std::move(chosen);
    }
    nlohmann::json s = step("active_clip", document, id);
    s["clip"] = name;
    return make(document, id, std::move(after), std::move(s),
                tr("Play clip %1 on %2").arg(q(name), node.name));
}

ClipListCommand::ClipListCommand(Document& document, PartId id, Clips after, nlohmann::json step,
                                 const QString& text)
    : document_(document),
      id_(id),
      before_(clipsOf(document.part(id))),
      after_(std::move(after)),
      step_(std::move(step)) {
    after_.others = sortedByName(std::move(after_.others));
    checkClipNamesUnique(after_.active, after_.others);
    // Choosing the active clip again, or renaming a clip to its name, is no step.
    setObsolete(identicalClips(before_.active, after_.active) &&
                std::equal(before_.others.begin(), before_.others.end(), after_.others.begin(),
                           after_.others.end(), &identicalClips));
    setText(text);
}

void ClipListCommand::redo() {
    document_.setClips(id_, after_.active, after_.others);
}

void ClipListCommand::undo() {
    document_.setClips(id_, before_.active, before_.others);
}

nlohmann::json ClipListCommand::recipeStep() const {
    return step_;
}

}  // namespace rigmesh::model
