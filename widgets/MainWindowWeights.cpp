// MainWindow: Tools > Weights, Blender's Weights menu on
// the selected part: Normalize All, Clean, Limit Total and Smooth All, each
// one undoable command that keeps locked bones, Recompute Weights (bone heat
// again, as a background job), and Check Rig (the Weights panel lists what
// it finds).
#include <QAction>
#include <QActionGroup>
#include <QComboBox>
#include <QDockWidget>
#include <QLabel>
#include <QMenu>
#include <QPointer>
#include <QSignalBlocker>
#include <QToolBar>

#include "MainWindow.h"
#include "base/Error.h"
#include "jobs/JobRunner.h"
#include "model/Document.h"
#include "model/ErrorText.h"
#include "model/commands/WeightCleanupCommand.h"
#include "panels/WeightsPanel.h"
#include "viewport/RenderScene.h"

namespace rigmesh::widgets {

void MainWindow::showWeightView(WeightView view) {
    for (QAction* action : weightViewGroup_->actions())
        if (static_cast<WeightView>(action->data().toInt()) == view)
            action->setChecked(true);
    if (weightViewBox_) {
        const QSignalBlocker block(weightViewBox_);
        weightViewBox_->setCurrentIndex(weightViewBox_->findData(static_cast<int>(view)));
    }
}

void MainWindow::createWeightMenu(QMenu* tools) {
    // The weight views on a toolbar too: a list beside the
    // tools, in step with View > Weights.
    auto* bar = addToolBar(tr("Weight View"));
    bar->setObjectName(QStringLiteral("weightViewToolBar"));
    bar->addWidget(new QLabel(tr(" Weights: "), bar));
    weightViewBox_ = new QComboBox(bar);
    weightViewBox_->setObjectName(QStringLiteral("weightViewBox"));
    weightViewBox_->setToolTip(tr("Colour the surface by its skin weights (View > Weights)"));
    for (QAction* action : weightViewGroup_->actions())
        weightViewBox_->addItem(action->text().remove(QLatin1Char('&')), action->data());
    bar->addWidget(weightViewBox_);
    connect(weightViewBox_, &QComboBox::activated, this, [this](int index) {
        const QVariant view = weightViewBox_->itemData(index);
        for (QAction* action : weightViewGroup_->actions())
            if (action->data() == view)
                action->trigger();
    });

    auto* menu = tools->addMenu(tr("Weigh&ts"));
    auto cleanup = [this](auto make) {
        model::Document* document = currentDocument();
        if (!document || !document->contains(document->selection().part)) {
            showStatus(tr("Select a part first"), 4000);
            return;
        }
        try {
            auto command = make(*document, document->selection().part);
            const QString text = tr("%1: %n vertices changed", nullptr, command->changedVertices())
                                     .arg(command->text());
            document->undoStack()->push(command.release());
            showStatus(text, 6000);
        } catch (const Error& error) {
            showStatus(model::errorText(error), 6000);
        }
    };
    auto add = [&](const QString& text, auto make) {
        QAction* action = menu->addAction(text);
        connect(action, &QAction::triggered, this, [cleanup, make] { cleanup(make); });
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
    connect(recompute, &QAction::triggered, this, &MainWindow::recomputeWeights);
    menu->addSeparator();
    QAction* check = menu->addAction(tr("Check &Rig"));
    connect(check, &QAction::triggered, this, [this] {
        for (auto* dock : findChildren<QDockWidget*>())
            if (dock->widget() == weights_) {
                dock->show();
                dock->raise();
            }
        weights_->checkRig();
    });
}

void MainWindow::recomputeWeights() {
    model::Document* document = currentDocument();
    if (!document || !document->contains(document->selection().part)) {
        showStatus(tr("Select a part first"), 4000);
        return;
    }
    const model::PartId id = document->selection().part;
    const model::PartNode& node = document->part(id);
    if (!node.part || node.part->skeleton.boneCount() == 0) {
        showStatus(tr("%1 has no skeleton, so it has no weights to recompute").arg(node.name),
                   6000);
        return;
    }
    // A whole-part solve takes seconds on a large part: a background job
    // on the part as it is; the command is made and
    // pushed when it is done.
    if (node.part->weightsPainted &&
        !confirmDiscardWeights(
            tr("The weights of %1 were painted or cleaned up by hand. Recomputing them by bone "
               "heat replaces that work (locked bones keep theirs; Undo brings it back). "
               "Recompute anyway?")
                .arg(node.name))) {
        showStatus(tr("Weights not recomputed: the painted weights are kept"), 6000);
        return;
    }
    QPointer<model::Document> guarded(document);
    const std::shared_ptr<const Part> part = node.part;
    jobs_->run(
        tr("Recomputing the weights of %1").arg(node.name),
        [=, this]() -> JobRunner::Apply {
            auto result = std::make_shared<model::WeightCleanupCommand::Recomputed>(
                model::WeightCleanupCommand::recomputed(part));
            return [=, this] {
                if (!guarded)
                    return;
                try {
                    auto command =
                        model::WeightCleanupCommand::fromRecomputed(*guarded, id, *result);
                    const QString text =
                        tr("%1: %n vertices changed", nullptr, command->changedVertices())
                            .arg(command->text());
                    guarded->undoStack()->push(command.release());
                    showStatus(text, 6000);
                } catch (const Error& error) {
                    showStatus(model::errorText(error), 6000);
                }
            };
        },
        [this](const QString& reason) {
            showStatus(tr("Weights not recomputed: %1").arg(reason), 8000);
        });
}

}  // namespace rigmesh::widgets
