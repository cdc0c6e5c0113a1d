#include "model/commands/ImportPartsCommand.h"

#include <QFileInfo>
#include <algorithm>
#include <cmath>

#include <nlohmann/json.hpp>
#include "base/Error.h"

#include "model/ImportReader.h"

namespace rigmesh::model {

std::unique_ptr<ImportPartsCommand> ImportPartsCommand::create(Document& document,
                                                               const QString& path) {
    // Read in a child process (Assimp may crash or loop on a broken file).
    return fromRead(document, path, readImportedParts(path));
}

std::unique_ptr<ImportPartsCommand> ImportPartsCommand::fromRead(Document& document,
                                                                 const QString& path,
                                                                 std::vector<PartNode> nodes) {
    if (nodes.empty())
        throw Error(MessageId::ImportNoMesh, QFileInfo(path).fileName().toStdString());
    // Ids are taken last, once nothing can fail any more.
    for (PartNode& node : nodes)
        node.id = document.allocatePartId();
    return std::unique_ptr<ImportPartsCommand>(
        new ImportPartsCommand(document, path, std::move(nodes)));
}

namespace {

// The latest key time of any clip of `nodes` (0 without keys).
double lastKeyTime(const std::vector<PartNode>& nodes) {
    double last = 0.0;
    for (const PartNode& node : nodes) {
        if (node.clip.keyCount() > 0)
            last = std::max(last, node.clip.keyTimes().back());
        for (const rigmesh::Clip& clip : node.otherClips)
            if (clip.keyCount() > 0)
                last = std::max(last, clip.keyTimes().back());
    }
    return last;
}

}  // namespace

ImportPartsCommand::ImportPartsCommand(Document& document, QString path,
                                       std::vector<PartNode> nodes)
    : document_(document),
      path_(std::move(path)),
      nodes_(std::move(nodes)),
      timelineBefore_(document.timeline()),
      timelineAfter_(document.timeline()) {
    setText(tr("Import %1").arg(QFileInfo(path_).fileName()));
    // The frame that shows the last key (a key between frames rounds up),
    // within the timeline's limits (Timeline.h).
    const TimelineSettings& timeline = timelineBefore_;
    const double lastFrame = std::ceil(lastKeyTime(nodes_) * timeline.framesPerSecond - 1e-9);
    const double longest = std::min<double>(
        kMaxFrame, std::floor(rigmesh::Clip::kLongestKeyTime * timeline.framesPerSecond));
    if (lastFrame > timeline.endFrame)
        timelineAfter_.endFrame = static_cast<int>(std::min(lastFrame, longest));
}

void ImportPartsCommand::redo() {
    for (const PartNode& node : nodes_)
        document_.insertPart(document_.partCount(), node);
    document_.setTimeline(timelineAfter_);
}

void ImportPartsCommand::undo() {
    // Newest first, so each id given back is the most recently allocated one.
    for (auto it = nodes_.rbegin(); it != nodes_.rend(); ++it) {
        document_.removePart(it->id);
        document_.releasePartId(it->id);
    }
    document_.setTimeline(timelineBefore_);
}

nlohmann::json ImportPartsCommand::recipeStep() const {
    return {{"command", "import"}, {"file", path_.toStdString()}};
}

int ImportPartsCommand::unrigged() const {
    int count = 0;
    for (const PartNode& node : nodes_)
        count += node.part->skeleton.jointCount() == 0 ? 1 : 0;
    return count;
}

std::vector<PartId> ImportPartsCommand::partIds() const {
    std::vector<PartId> ids;
    for (const PartNode& node : nodes_)
        ids.push_back(node.id);
    return ids;
}

}  // namespace rigmesh::model
