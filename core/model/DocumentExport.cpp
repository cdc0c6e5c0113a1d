#include "model/DocumentExport.h"

#include <Eigen/Geometry>

#include <deque>

#include "base/Error.h"
#include "io/ExportFormat.h"
#include "model/PartClips.h"
#include "pose/ForwardKinematics.h"
#include "pose/Skinning.h"

namespace rigmesh::model {
namespace {

ExportPart exportPartOf(const PartNode& node) {
    ExportPart part;
    part.part = node.part.get();
    part.pose = node.pose;
    part.placement = node.placement.affine();
    part.name = node.name.toStdString();
    return part;
}

// The part with its current pose made its rest shape (for rigged formats,
// whose files carry a rest shape and a skeleton): skinned vertices, every
// joint at its posed place, weights and bookkeeping unchanged. The file then
// opens in that pose with an identity bind, and still deforms.
Part poseAsRest(const PartNode& node, SkinningMethod method) {
    Part baked = *node.part;
    baked.mesh = posePart(*node.part, node.pose, SkinningOptions{method}).mesh;
    const PosedSkeleton posed = forwardKinematics(node.part->skeleton, node.pose);
    const std::vector<Joint> joints = node.part->skeleton.joints();
    for (std::size_t j = 0; j < joints.size(); ++j)
        baked.skeleton.setJointPosition(joints[j].id, posed.jointPositions[j]);
    return baked;
}

}  // namespace

DocumentExportResult exportDocument(const Document& document, const std::string& path,
                                    const ExportOptions& options, bool visibleOnly) {
    return exportParts(document.parts(), path, options, visibleOnly);
}

DocumentExportResult exportParts(const std::vector<PartNode>& parts, const std::string& path,
                                 const ExportOptions& options, bool visibleOnly) {
    StagedDocumentExport staged = stageParts(parts, path, options, visibleOnly);
    staged.files.commit();
    return {staged.warnings};
}

StagedDocumentExport stageParts(const std::vector<PartNode>& documentParts, const std::string& path,
                                const ExportOptions& options, bool visibleOnly) {
    StagedDocumentExport result;
    std::vector<const PartNode*> nodes;
    for (const PartNode& node : documentParts)
        if (node.part && (node.visible || !visibleOnly))
            nodes.push_back(&node);
    if (nodes.empty())
        throw Error(MessageId::ExportNoParts);
    if (isRiggedFormat(exportFormatFromPath(path)))
        for (const PartNode* node : nodes)
            if (node->part->skeleton.jointCount() == 0)
                throw Error(MessageId::ExportPartNotRigged, node->name.toStdString());

    // The current pose as the rest shape: OBJ poses its mesh itself; the
    // rigged formats get parts whose rest is that pose (their clips would be
    // relative to the old rest, so none is written).
    // Or, with poseAsKey, the rest shape stays and each part's pose is a
    // one-key animation.
    const bool rigged = isRiggedFormat(exportFormatFromPath(path));
    const bool poseKey = !options.restPose && options.poseAsKey && rigged;
    const bool bakePose = !options.restPose && !poseKey && rigged;
    auto hasKeys = [](const PartNode& node) {
        for (const rigmesh::Clip* clip : clipsOf(node))
            if (clip->keyCount() > 0)
                return true;
        return false;
    };
    if ((bakePose || poseKey) && options.animation)
        for (const PartNode* node : nodes)
            if (hasKeys(*node))
                result.warnings << (bakePose
                                        ? QObject::tr("the clip of \"%1\" is not exported: "
                                                      "the current pose is the file's rest "
                                                      "shape")
                                        : QObject::tr("the clip of \"%1\" is not exported: "
                                                      "its current pose is the file's one key"))
                                       .arg(node->name);
    std::vector<rigmesh::Clip> poseClips;
    poseClips.reserve(nodes.size());
    std::vector<Part> baked;
    baked.reserve(nodes.size());
    auto exportPart = [&](const PartNode& node) {
        ExportPart part = exportPartOf(node);
        if (bakePose) {
            baked.push_back(poseAsRest(node, options.skinning));
            part.part = &baked.back();
            part.pose = rigmesh::Pose{};
        }
        return part;
    };
    // Every part with its own clips, in document order;
    // each clip by its name (an unnamed one is "Action"), so that the clips
    // of several parts with one name are one animation.
    std::deque<rigmesh::Clip> named;
    std::vector<ExportPart> parts;
    for (const PartNode* node : nodes) {
        parts.push_back(exportPart(*node));
        if (poseKey) {
            poseClips.emplace_back(node->clip.framesPerSecond());
            poseClips.back().name = node->name.toStdString() + "_pose";
            poseClips.back().setKey(0.0, node->pose);
            parts.back().clip = &poseClips.back();
            continue;
        }
        if (bakePose)
            continue;
        for (const rigmesh::Clip* clip : clipsOf(*node)) {
            if (clip->keyCount() == 0)
                continue;
            named.push_back(*clip);
            named.back().name = clipName(*clip);
            if (clip == &node->clip)
                parts.back().clip = &named.back();
            else
                parts.back().otherClips.push_back(&named.back());
        }
    }
    ExportOptions written = options;
    written.animation = options.animation || poseKey;  // the key is the pose itself
    result.files = stageScene(parts, nullptr, path, written);
    return result;
}

}  // namespace rigmesh::model
