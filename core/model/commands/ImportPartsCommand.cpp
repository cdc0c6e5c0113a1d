#include "model/commands/ImportPartsCommand.h"

#include <QFileInfo>

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

ImportPartsCommand::ImportPartsCommand(Document& document, QString path,
                                       std::vector<PartNode> nodes)
    : document_(document), path_(std::move(path)), nodes_(std::move(nodes)) {
    setText(tr("Import %1").arg(QFileInfo(path_).fileName()));
}

void ImportPartsCommand::redo() {
    for (const PartNode& node : nodes_)
        document_.insertPart(document_.partCount(), node);
}

void ImportPartsCommand::undo() {
    // Newest first, so each id given back is the most recently allocated one.
    for (auto it = nodes_.rbegin(); it != nodes_.rend(); ++it) {
        document_.removePart(it->id);
        document_.releasePartId(it->id);
    }
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
