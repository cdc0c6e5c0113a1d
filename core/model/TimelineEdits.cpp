#include "model/TimelineEdits.h"

#include <QCoreApplication>
#include <algorithm>
#include <limits>
#include <memory>
#include <vector>

#include "model/GuardedUndo.h"
#include "model/commands/DeleteKeyCommand.h"
#include "model/commands/KeyPoseCommand.h"
#include "model/commands/PasteKeysCommand.h"

namespace rigmesh::model {

namespace {

// Pushes the commands made by `make` as one undo step: a macro `text` when
// there are several, the command itself when there is one.
template <typename Make>
void pushAsOneStep(Document& document, const QString& text, int count, Make make) {
    if (count == 0)
        return;
    if (count == 1) {
        pushCommand(document, make(nullptr));
        return;
    }
    auto parent = std::make_unique<QUndoCommand>(text);
    for (int i = 0; i < count; ++i)
        make(parent.get());
    pushCommand(document, std::move(parent));
}

}  // namespace

int insertKeys(Document& document, PartId part) {
    std::vector<PartId> parts;
    for (const PartNode& node : document.parts())
        if ((part == kNoPart || node.id == part) && node.part &&
            node.part->skeleton.jointCount() > 0)
            parts.push_back(node.id);
    const double time = document.currentTime();
    int next = 0;
    pushAsOneStep(document,
                  QCoreApplication::translate("rigmesh::model::TimelineEdits", "Key %n part(s)",
                                              nullptr, static_cast<int>(parts.size())),
                  static_cast<int>(parts.size()), [&](QUndoCommand* parent) {
                      return new KeyPoseCommand(document, parts[next++], time, parent);
                  });
    return static_cast<int>(parts.size());
}

int deleteKeys(Document& document, const KeySelection& keys) {
    std::vector<std::pair<PartId, double>> doomed;
    for (const auto& [part, times] : keys)
        if (const PartNode* node = document.findPart(part))
            for (const double time : times)
                if (node->clip.keys().contains(time))
                    doomed.emplace_back(part, time);
    std::size_t next = 0;
    pushAsOneStep(document,
                  QCoreApplication::translate("rigmesh::model::TimelineEdits", "Delete %n key(s)",
                                              nullptr, static_cast<int>(doomed.size())),
                  static_cast<int>(doomed.size()), [&](QUndoCommand* parent) {
                      const auto [part, time] = doomed[next++];
                      return new DeleteKeyCommand(document, part, time, parent);
                  });
    return static_cast<int>(doomed.size());
}

KeyClipboard copyKeys(const Document& document, const KeySelection& keys) {
    KeyClipboard out;
    double earliest = std::numeric_limits<double>::infinity();
    for (const auto& [part, times] : keys)
        if (const PartNode* node = document.findPart(part))
            for (const double time : times)
                if (node->clip.keys().contains(time))
                    earliest = std::min(earliest, time);
    for (const auto& [part, times] : keys)
        if (const PartNode* node = document.findPart(part))
            for (const double time : times)
                if (const auto it = node->clip.keys().find(time); it != node->clip.keys().end())
                    out.keys[part][time - earliest] = it->second;
    return out;
}

KeySelection pasteKeys(Document& document, const KeyClipboard& clipboard, PartId target) {
    std::map<PartId, std::map<double, rigmesh::Pose>> placed;
    const double now = document.currentTime();
    for (const auto& [part, keys] : clipboard.keys) {
        PartId into = part;
        if (clipboard.keys.size() == 1 && target != kNoPart && document.contains(target) &&
            PasteKeysCommand::fitsSkeleton(document.part(target), keys))
            into = target;
        if (!document.contains(into) || !PasteKeysCommand::fitsSkeleton(document.part(into), keys))
            continue;
        for (const auto& [offset, pose] : keys)
            placed[into][now + offset] = pose;
    }
    KeySelection pasted;
    for (const auto& [part, keys] : placed)
        for (const auto& entry : keys)
            pasted[part].insert(entry.first);
    auto next = placed.begin();
    int keyCount = 0;
    for (const auto& entry : placed)
        keyCount += static_cast<int>(entry.second.size());
    pushAsOneStep(document,
                  QCoreApplication::translate("rigmesh::model::TimelineEdits", "Paste %n key(s)",
                                              nullptr, keyCount),
                  static_cast<int>(placed.size()), [&](QUndoCommand* parent) {
                      const auto& [part, keys] = *next++;
                      return new PasteKeysCommand(document, part, keys, parent);
                  });
    return pasted;
}

}  // namespace rigmesh::model
