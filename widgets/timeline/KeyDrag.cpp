#include "timeline/KeyDrag.h"

#include <QCoreApplication>
#include <QtGlobal>
#include <exception>
#include <memory>

#include "base/Error.h"
#include "model/GuardedUndo.h"
#include "model/commands/MoveKeysCommand.h"

namespace rigmesh::widgets {

KeyDrag::KeyDrag(model::Document& document, std::map<model::PartId, std::vector<double>> keys)
    : document_(document), keys_(std::move(keys)) {}

KeyDrag::~KeyDrag() {
    if (done_)
        return;
    // A destructor must not throw (it would end the program): a revert the
    // document refuses (Document::editClip) is told on the console, and the
    // keys stay where the drag left them.
    try {
        cancel();
    } catch (const std::exception& error) {
        qWarning("The key drag could not be taken back: %s", error.what());
    }
}

double KeyDrag::seconds(int frames) const {
    return frames / document_.timeline().framesPerSecond;
}

void KeyDrag::revert() {
    for (const auto& [part, edit] : applied_)
        if (document_.contains(part))
            document_.editClip(part, edit.inverse());
    applied_.clear();
}

void KeyDrag::moveTo(int frames) {
    if (frames == offset_ || done_)
        return;
    revert();
    std::map<model::PartId, model::ClipEdit> edits;
    try {
        for (const auto& [part, times] : keys_)
            if (document_.contains(part))
                edits[part] =
                    model::movedKeysEdit(document_.part(part).clip, times, seconds(frames));
    } catch (const Error&) {
        frames = offset_;  // out of range: keep the last good offset
        edits.clear();
        for (const auto& [part, times] : keys_)
            if (document_.contains(part) && frames != 0)
                edits[part] =
                    model::movedKeysEdit(document_.part(part).clip, times, seconds(frames));
    }
    for (const auto& [part, edit] : edits) {
        document_.editClip(part, edit);
        applied_[part] = edit;
    }
    offset_ = frames;
}

std::map<model::PartId, std::vector<double>> KeyDrag::finish() {
    done_ = true;
    std::map<model::PartId, std::vector<double>> moved;
    const double by = seconds(offset_);
    for (const auto& [part, times] : keys_)
        for (const double time : times)
            moved[part].push_back(offset_ == 0 ? time : time + by);
    if (offset_ == 0 || applied_.empty())
        return moved;
    // The commands are made on the clips as the drag found them and redo the
    // move when pushed.
    std::vector<model::PartId> parts;
    for (const auto& [part, edit] : applied_)
        parts.push_back(part);
    revert();
    std::unique_ptr<QUndoCommand> parent;
    if (applied_.size() > 1)
        parent = std::make_unique<QUndoCommand>(QCoreApplication::translate(
            "rigmesh::widgets::KeyDrag", "Move keys by %n frame(s)", nullptr, offset_));
    std::unique_ptr<QUndoCommand> single;
    for (const model::PartId part : parts) {
        auto* command =
            new model::MoveKeysCommand(document_, part, keys_.at(part), by, parent.get());
        if (!parent)
            single.reset(command);
    }
    model::pushCommand(document_, parent ? std::move(parent) : std::move(single));
    return moved;
}

void KeyDrag::cancel() {
    done_ = true;
    revert();
    offset_ = 0;
}

}  // namespace rigmesh::widgets
