#include "model/commands/MoveKeysCommand.h"

#include <cmath>
#include <nlohmann/json.hpp>

#include "base/Error.h"

namespace rigmesh::model {

ClipEdit movedKeysEdit(const rigmesh::Clip& clip, const std::vector<double>& times, double offset) {
    if (times.empty())
        throw Error(MessageId::NoKeysToMove);
    if (!std::isfinite(offset))
        throw Error(MessageId::KeyOffsetNotFinite);
    std::vector<double> around = times;
    for (const double time : times)
        around.push_back(time + offset);
    return localClipEdit(clip, around, [&](rigmesh::Clip& local) {
        // Take every moving key out first, then put each back at its new time.
        std::vector<std::pair<double, rigmesh::Pose>> moving;
        for (const double time : times) {
            const double exact = local.keyTime(time);
            moving.emplace_back(exact, local.key(exact));
            local.eraseExactKey(exact);
        }
        for (const auto& [time, pose] : moving)
            local.setKey(time + offset, pose);
    });
}

MoveKeysCommand::MoveKeysCommand(Document& document, PartId id, std::vector<double> times,
                                 double offset, QUndoCommand* parent)
    : ClipCommand(document, id, movedKeysEdit(document.part(id).clip, times, offset), parent),
      times_(std::move(times)),
      offset_(offset) {
    setText(tr("Move %n key(s) of %1 by %2 s", nullptr, static_cast<int>(times_.size()))
                .arg(document.part(id).name)
                .arg(offset));
}

nlohmann::json MoveKeysCommand::recipeStep() const {
    return {{"command", "move_keys"}, {"part", partIndex()}, {"times", times_}, {"by", offset_}};
}

}  // namespace rigmesh::model
