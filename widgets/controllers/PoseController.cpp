#include "controllers/PoseController.h"

#include <QAction>
#include <QMenu>

#include "UserAction.h"
#include "base/Error.h"
#include "controllers/StudioHost.h"
#include "model/Document.h"
#include "model/ErrorText.h"
#include "model/PoseChange.h"
#include "model/commands/ResetPoseCommand.h"
#include "model/commands/SetPoseCommand.h"
#include "pose/PoseMirror.h"

namespace rigmesh::widgets {

PoseController::PoseController(StudioHost& host, QObject* parent) : QObject(parent), host_(host) {}

void PoseController::addMirrorAction(QMenu* edit) {
    QAction* mirror = edit->addAction(tr("&Mirror Pose"));
    mirror->setObjectName(QStringLiteral("mirrorPose"));
    mirror->setShortcut(QKeySequence(Qt::CTRL | Qt::SHIFT | Qt::Key_V));
    mirror->setToolTip(
        tr("Flip the selected part's pose left to right about its mirror plane, as Blender's "
           "Paste Pose Flipped"));
    connect(mirror, &QAction::triggered, this, &PoseController::mirrorPose);
}

void PoseController::addResetAction(QMenu* tools) {
    QAction* reset = tools->addAction(tr("&Reset Pose"));
    reset->setShortcut(QKeySequence(Qt::ALT | Qt::Key_R));
    reset->setToolTip(tr("Put the selected part back in its rest pose"));
    connect(reset, &QAction::triggered, this, &PoseController::resetPose);
}

void PoseController::resetPose() {
    model::Document* document = host_.currentDocument();
    if (!document || !document->contains(document->selection().part)) {
        host_.showStatus(tr("Select a part to reset its pose"), 4000);
        return;
    }
    const model::PartId id = document->selection().part;
    runUserAction(
        tr("&Reset Pose"), [this](const QString& failure) { host_.showStatus(failure); },
        [&] { model::pushPoseChange(*document, id, new model::ResetPoseCommand(*document, id)); });
}

void PoseController::mirrorPose() {
    model::Document* document = host_.currentDocument();
    if (!document || !document->contains(document->selection().part)) {
        host_.showStatus(tr("Select a part to mirror its pose"), 4000);
        return;
    }
    const model::PartId id = document->selection().part;
    const model::PartNode& node = document->part(id);
    if (!node.part || node.part->skeleton.boneCount() == 0) {
        host_.showStatus(tr("%1 has no skeleton to pose").arg(node.name), 4000);
        return;
    }
    const std::optional<PartSymmetry> symmetry = findPartSymmetry(*node.part);
    if (!symmetry) {
        host_.showStatus(
            tr("%1 has no left-right mirror plane: its two sides differ too much to mirror "
               "its pose")
                .arg(node.name),
            6000);
        return;
    }
    runUserAction(
        tr("&Mirror Pose"), [this](const QString& failure) { host_.showStatus(failure); },
        [&] {
            const Pose mirrored = mirroredPose(node.part->skeleton, node.pose, *symmetry);
            auto* command = new model::SetPoseCommand(*document, id, mirrored, kNoJoint,
                                                      model::CommandMerging::Never);
            command->setText(tr("Mirror Pose of %1").arg(node.name));
            model::pushPoseChange(*document, id, command);
            host_.showStatus(tr("Mirrored the pose of %1 left to right").arg(node.name), 4000);
        });
}

}  // namespace rigmesh::widgets
