#include "controllers/RigController.h"

#include <QMessageBox>
#include <QPointer>
#include <QPushButton>
#include <algorithm>

#include "UserAction.h"
#include "base/Error.h"
#include "controllers/StudioHost.h"
#include "jobs/JobRunner.h"
#include "model/Document.h"
#include "model/ErrorText.h"
#include "model/GuardedUndo.h"
#include "model/commands/BoneEditCommand.h"
#include "model/commands/RigPartCommand.h"
#include "part/BoneConnection.h"

namespace rigmesh::widgets {

RigController::RigController(StudioHost& host, QObject* parent) : QObject(parent), host_(host) {}

void RigController::rigSelectedPart() {
    model::Document* document = host_.currentDocument();
    if (!document || !document->contains(document->selection().part)) {
        host_.showStatus(tr("Select a part to rig first"), 4000);
        return;
    }
    const model::PartNode& node = document->part(document->selection().part);
    if (node.part && node.part->skeleton.jointCount() > 0) {
        host_.showStatus(tr("%1 already has a skeleton; Auto-Rig is for parts without one, such as "
                            "imported meshes")
                             .arg(node.name),
                         8000);
        return;
    }
    rigParts(document, {node.id});
}

void RigController::connectSelectedBone() {
    model::Document* document = host_.currentDocument();
    const model::Selection selection = document ? document->selection() : model::Selection{};
    if (!document || !document->contains(selection.part) || selection.joint == kNoJoint) {
        host_.showStatus(tr("Select the joint of the bone to connect first"), 4000);
        return;
    }
    const Skeleton& skeleton = document->part(selection.part).part->skeleton;
    // The joint stands for the bone ending at it, or (a chain's root) for
    // the first bone leaving it; that bone's head is what moves.
    std::optional<BoneId> bone = boneForJoint(skeleton, selection.joint);
    if (skeleton.isAttached(selection.joint) && !skeleton.childrenOf(selection.joint).empty())
        bone = skeleton.childrenOf(selection.joint).front();
    if (!bone) {
        host_.showStatus(tr("The selected joint ends no bone"), 4000);
        return;
    }
    runUserAction(
        {},
        [this](const QString& failure) {
            host_.showStatus(tr("Bone not connected: %1").arg(failure), 8000);
        },
        [&] {
            auto command = model::BoneEditCommand::connect(*document, selection.part, *bone);
            const QString text = command->text();
            model::pushCommand(*document, std::move(command));
            host_.showStatus(text, 6000);
        });
}

void RigController::rigParts(model::Document* document, std::vector<model::PartId> ids) {
    std::erase_if(ids, [&](model::PartId id) { return !document || !document->contains(id); });
    if (ids.empty())
        return;
    // Several parts (an import's meshes) are rigged together as one figure,
    // joined in document order (RigPartCommand::fromRigged wants that order).
    std::sort(ids.begin(), ids.end(), [&](model::PartId a, model::PartId b) {
        return document->indexOf(a) < document->indexOf(b);
    });
    QPointer<model::Document> guarded(document);
    const QString name = document->part(ids.front()).name;
    const std::vector<model::RigPartCommand::Source> sources =
        model::RigPartCommand::sourcesOf(*document, ids);
    host_.jobs()->runWithProgress(
        tr("Rigging %1").arg(name),
        [=, this](JobProgress& progress) -> JobRunner::Apply {
            auto rigged = std::make_shared<model::RigPartCommand::Rigged>(
                model::RigPartCommand::rigged(sources, [&progress](double fraction) {
                    progress.setFraction(fraction);
                    return !progress.cancelled();
                }));
            return [=, this] {
                if (!guarded)
                    return;
                runUserAction(
                    {},
                    [this, name](const QString& failure) {
                        QMessageBox::warning(host_.dialogParent(), tr("Cannot rig %1").arg(name),
                                             failure);
                    },
                    [&] {
                        auto command = model::RigPartCommand::fromRigged(*guarded, ids, *rigged);
                        const QString summary = command->summary();
                        model::pushCommand(*guarded, std::move(command));
                        guarded->setSelection({ids.front(), kNoJoint});
                        host_.showStatus(summary, 10000);
                    });
            };
        },
        [this, name](const QString& reason) {
            QMessageBox::warning(host_.dialogParent(), tr("Cannot rig %1").arg(name), reason);
        },
        [this, name] { host_.showStatus(tr("Rigging %1 cancelled").arg(name), 6000); });
}

bool RigController::offerToRig(model::Document& document, const std::vector<model::PartId>& ids,
                               const QString& message) {
    QMessageBox box(QMessageBox::Question, tr("Imported without a rig"), message,
                    QMessageBox::NoButton, host_.dialogParent());
    box.setObjectName(QStringLiteral("offerToRig"));
    box.setInformativeText(
        tr("Auto-Rig gives the imported meshes one skeleton from their shape and skin weights, "
           "so the figure can be posed, animated and painted like a sketched part. You can also "
           "do it later with Tools > Auto-Rig Part."));
    QPushButton* rigNow = box.addButton(tr("Rig Now"), QMessageBox::AcceptRole);
    box.addButton(tr("Not Now"), QMessageBox::RejectRole);
    box.setDefaultButton(rigNow);
    box.exec();
    if (box.clickedButton() != rigNow)
        return false;
    rigParts(&document, ids);
    return true;
}

}  // namespace rigmesh::widgets
