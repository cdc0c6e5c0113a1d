#include "model/DocumentExport.h"

#include <Eigen/Geometry>

#include "base/Error.h"
#include "io/ExportFormat.h"
#include "pose/ForwardKinematics.h"
#include "pose/Skinning.h"

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

// The part with its current pose made its rest shape (for rigged formats,
// whose files carry a rest shape and a skeleton): skinned vertices, every
// joint at its posed place, weights and bookkeeping unchanged. The file then
// opens in that pose with an identity bind, and still deforms.
Part poseAsRest(const PartNode& node) {
    Part baked = *node.part;
    baked.mesh = posePart(*node.part, node.pose).mesh;
    const PosedSkeleton posed = forwardKinematics(node.part->skeleton, node.pose);
    const std::vector<Joint> joints = node.part->skeleton.joints();
    for (std::size_t j = 0; j < joints.size(); ++j)
        baked.skeleton.setJointPosition(joints[j].id, posed.jointPositions[j]);
    return baked;
}

}  // namespace

DocumentExportResult exportDocument(const Document& document, const std::string& path,
                                    const ExportOptions& options, bool visibleOnly) {
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

    // The current pose as the rest shape: OBJ poses its mesh itself; the
    // rigged formats get parts whose rest is that pose (their clips would be
    // relative to the old rest, so none is written).
    const bool bakePose = !options.restPose && isRiggedFormat(exportFormatFromPath(path));
    if (bakePose && options.animation)
        for (const PartNode* node : nodes)
            if (node->clip.keyCount() > 0)
                result.warnings << QObject::tr(
                                       "the clip of \"%1\" is not exported: the current "
                                       "pose is the file's rest shape")
                                       .arg(node->name);
    std::vector<Part> baked;
    baked.reserve(nodes.size());
    auto exportPart = [&](const PartNode& node) {
        ExportPart part = exportPartOf(node);
        if (bakePose) {
            baked.push_back(poseAsRest(node));
            part.part = &baked.back();
            part.pose = rigmesh::Pose{};
        }
        return part;
    };
    // Every part with its own clip (issue 18 item 3), in document order.
    std::vector<ExportPart> parts;
    for (const PartNode* node : nodes) {
        parts.push_back(exportPart(*node));
        if (!bakePose && node->clip.keyCount() > 0)
            parts.back().clip = &node->clip;
    }
    exportScene(parts, nullptr, path, options);
    return result;
}

}  // namespace rigmesh::model
