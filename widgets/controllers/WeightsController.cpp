#include "controllers/WeightsController.h"

#include <QAction>
#include <QDockWidget>
#include <QMenu>
#include <QMessageBox>
#include <QPointer>

#include "UserAction.h"
#include "base/Error.h"
#include "controllers/StudioHost.h"
#include "jobs/JobRunner.h"
#include "model/Document.h"
#include "model/ErrorText.h"
#include "model/GuardedUndo.h"
#include "model/commands/WeightCleanupCommand.h"
#include "panels/WeightsPanel.h"

namespace rigmesh::widgets {

WeightsController::WeightsController(StudioHost& host, WeightsPanel* panel, QObject* parent)
    : QObject(parent), host_(host), panel_(panel) {
    confirmDiscard = [this](const QString& question) {
        return QMessageBox::question(host_.dialogParent(), tr("Recompute Weights"), question,
                                     QMessageBox::Yes | QMessageBox::Cancel,
                                     QMessageBox::Cancel) == QMessageBox::Yes;
    };
}

void WeightsController::addMenu(QMenu* tools) {
    auto* menu = tools->addMenu(tr("Weigh&ts"));
    auto cleanup = [this](const QString& name, auto make) {
        model::Document* document = host_.currentDocument();
        if (!document || !document->contains(document->selection().part)) {
            host_.showStatus(tr("Select a part first"), 4000);
            return;
        }
        runUserAction(
            name, [this](const QString& failure) { host_.showStatus(failure, 6000); },
            [&] {
                auto command = make(*document, document->selection().part);
                const QString text =
                    tr("%1: %n vertices changed", nullptr, command->changedVertices())
                        .arg(command->text());
                model::pushCommand(*document, std::move(command));
                host_.showStatus(text, 6000);
            });
    };
    auto add = [&](const QString& text, auto make) {
        QAction* action = menu->addAction(text);
        connect(action, &QAction::triggered, this, [cleanup, text, make] { cleanup(text, make); });
        return action;
    };
    add(tr("&Normalize All"), [](model::Document& d, model::PartId id) {
        return model::WeightCleanupCommand::normalizeAll(d, id);
    });
    add(tr("&Clean (below 0.01)"), [](model::Document& d, model::PartId id) {
        return model::WeightCleanupCommand::clean(d, id, 0.01);
    });
    add(tr("&Limit Total (4 bones)"), [](model::Document& d, model::PartId id) {
        return model::WeightCleanupCommand::limitTotal(d, id, 4);
    });
    add(tr("&Smooth All"), [](model::Document& d, model::PartId id) {
        return model::WeightCleanupCommand::smoothAll(d, id, SmoothAllOptions{});
    })->setToolTip(tr("Every unlocked bone's weight halfway towards its neighbours' mean"));
    menu->addSeparator();
    QAction* recompute = menu->addAction(tr("&Recompute Weights (Bone Heat)"));
    recompute->setObjectName(QStringLiteral("recomputeWeights"));
    recompute->setToolTip(
        tr("Bone heat over the whole part again, as a new sketch gets it; locked bones keep "
           "their weights"));
    connect(recompute, &QAction::triggered, this, &WeightsController::recomputeWeights);
    menu->addSeparator();
    QAction* check = menu->addAction(tr("Check &Rig"));
    connect(check, &QAction::triggered, this, [this] {
        // The panel's dock comes to the front with the findings.
        if (auto* dock = qobject_cast<QDockWidget*>(panel_->parentWidget())) {
            dock->show();
            dock->raise();
        }
        panel_->checkRig();
    });
}

void WeightsController::recomputeWeights() {
    model::Document* document = host_.currentDocument();
    if (!document || !document->contains(document->selection().part)) {
        host_.showStatus(tr("Select a part first"), 4000);
        return;
    }
    const model::PartId id = document->selection().part;
    const model::PartNode& node = document->part(id);
    if (!node.part || node.part->skeleton.boneCount() == 0) {
        host_.showStatus(tr("%1 has no skeleton, so it has no weights to recompute").arg(node.name),
                         6000);
        return;
    }
    // A whole-part solve takes seconds on a large part: a background job
    // on the part as it is; the command is made and
    // pushed when it is done.
    if (node.part->weightsPainted &&
        !confirmDiscard(
            tr("The weights of %1 were painted or cleaned up by hand. Recomputing them by bone "
               "heat replaces that work (locked bones keep theirs; Undo brings it back). "
               "Recompute anyway?")
                .arg(node.name))) {
        host_.showStatus(tr("Weights not recomputed: the painted weights are kept"), 6000);
        return;
    }
    QPointer<model::Document> guarded(document);
    const std::shared_ptr<const Part> part = node.part;
    host_.jobs()->run(
        tr("Recomputing the weights of %1").arg(node.name),
        [=, this]() -> JobRunner::Apply {
            auto result = std::make_shared<model::WeightCleanupCommand::Recomputed>(
                model::WeightCleanupCommand::recomputed(part));
            return [=, this] {
                if (!guarded)
                    return;
                runUserAction(
                    tr("&Recompute Weights (Bone Heat)"),
                    [this](const QString& failure) { host_.showStatus(failure, 6000); },
                    [&] {
                        auto command =
                            model::WeightCleanupCommand::fromRecomputed(*guarded, id, *result);
                        const QString text =
                            tr("%1: %n vertices changed", nullptr, command->changedVertices())
                                .arg(command->text());
                        model::pushCommand(*guarded, std::move(command));
                        host_.showStatus(text, 6000);
                    });
            };
        },
        [this](const QString& reason) {
            host_.showStatus(tr("Weights not recomputed: %1").arg(reason), 8000);
        });
}

}  // namespace rigmesh::widgets
