#include "model/DocumentExport.h"

#include <Eigen/Geometry>

#include "base/Error.h"
#include "io/ExportFormat.h"

namespace rigmesh::model {
namespace {

ExportPart exportPartOf(const PartNode& node) {
    ExportPart part;
    part.part = node.part.get();
    part.pose = node.pose;
    part.placement = Eigen::Translation3d(node.placement.translation) * node.placement.rotation;
    part.name = node.name.toStdString();
    return part;
}

}  // namespace

DocumentExportResult exportDocument(const Document& document, const std::string& path,
                                    const ExportOptions& options, PartId preferredAnimatedPart,
                                    bool visibleOnly) {
    DocumentExportResult result;
    std::vector<const PartNode*> nodes;
    for (const PartNode& node : document.parts())
        if (node.part && (node.visible || !visibleOnly))
            nodes.push_back(&node);
    if (nodes.empty())
        throw Error("there are no parts to export");
    if (isRiggedFormat(exportFormatFromPath(path)))
        for (const PartNode* node : nodes)
            if (node->part->skeleton.jointCount() == 0)
                throw Error("\"" + node->name.toStdString() +
                            "\" is not rigged yet: export it as OBJ, or hide it and export the "
                            "visible parts");

    // exportScene animates part 0 with the clip: the animated part goes first.
    const PartNode* animated = nullptr;
    for (const PartNode* node : nodes)
        if (node->clip.keyCount() > 0 && (node->id == preferredAnimatedPart || !animated))
            animated = node;
    if (animated && options.animation) {
        for (const PartNode* node : nodes)
            if (node != animated && node->clip.keyCount() > 0)
                result.warnings << QObject::tr(
                                       "the keys of \"%1\" are not exported: one part's clip is")
                                       .arg(node->name);
    }
    std::vector<ExportPart> parts;
    if (animated)
        parts.push_back(exportPartOf(*animated));
    for (const PartNode* node : nodes)
        if (node != animated)
            parts.push_back(exportPartOf(*node));
    exportScene(parts, animated && options.animation ? &animated->clip : nullptr, path, options);
    return result;
}

}  // namespace rigmesh::model
