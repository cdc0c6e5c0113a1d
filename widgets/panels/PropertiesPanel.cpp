#include "panels/PropertiesPanel.h"

#include <QCheckBox>
#include <QDoubleSpinBox>
#include <QFormLayout>
#include <QLabel>
#include <QPushButton>
#include <QVBoxLayout>

#include "base/Error.h"
#include "model/Document.h"
#include "model/commands/RebuildPartCommand.h"

namespace rigmesh::widgets {

PropertiesPanel::PropertiesPanel(QWidget* parent) : QWidget(parent) {
    auto* layout = new QVBoxLayout(this);
    title_ = new QLabel(this);
    title_->setStyleSheet(QStringLiteral("font-weight: bold"));
    figures_ = new QLabel(this);
    figures_->setTextInteractionFlags(Qt::TextSelectableByMouse);
    auto* form = new QFormLayout;
    edgeLength_ = new QDoubleSpinBox(this);
    edgeLength_->setDecimals(4);
    edgeLength_->setRange(0.0, 1e6);
    edgeLength_->setSpecialValueText(tr("automatic"));
    edgeLength_->setToolTip(
        tr("Target edge length of the surface; automatic = 1/60 of the sketch's size"));
    smoothing_ = new QCheckBox(tr("Least-squares smoothing"), this);
    rebuildButton_ = new QPushButton(tr("Rebuild"), this);
    form->addRow(tr("Edge length"), edgeLength_);
    form->addRow(QString(), smoothing_);
    layout->addWidget(title_);
    layout->addWidget(figures_);
    layout->addLayout(form);
    layout->addWidget(rebuildButton_);
    layout->addStretch();
    connect(rebuildButton_, &QPushButton::clicked, this, &PropertiesPanel::rebuild);
    refresh();
}

void PropertiesPanel::setDocument(model::Document* document) {
    if (document_)
        disconnect(document_, nullptr, this, nullptr);
    document_ = document;
    if (document_) {
        connect(document_, &model::Document::selectionChanged, this, &PropertiesPanel::refresh);
        connect(document_, &model::Document::partChanged, this, &PropertiesPanel::refresh);
        connect(document_, &model::Document::partRemoved, this, &PropertiesPanel::refresh);
    }
    refresh();
}

void PropertiesPanel::refresh() {
    const model::PartNode* node =
        document_ ? document_->findPart(document_->selection().part) : nullptr;
    const bool hasPart = node && node->part;
    // Only sketched parts can be rebuilt: they have a stroke.
    const bool rebuildable = hasPart && !node->stroke.empty();
    edgeLength_->setEnabled(rebuildable);
    smoothing_->setEnabled(rebuildable);
    rebuildButton_->setEnabled(rebuildable);
    if (!hasPart) {
        title_->setText(tr("No part selected"));
        figures_->setText(tr("Select a part in the viewport or the outliner."));
        return;
    }
    const Part& part = *node->part;
    title_->setText(node->name);
    figures_->setText(
        tr("%1 vertices, %2 faces\n%3 joints, %4 bones\nstroke of %5 points")
            .arg(part.mesh.vertexCount())
            .arg(part.mesh.faceCount())
            .arg(part.skeleton.jointCount())
            .arg(part.skeleton.boneCount())
            .arg(node->stroke.size()) +
        (part.skeleton.jointCount() == 0
             ? tr("\nNot rigged: imported as a static mesh. Rigging imported meshes is "
                  "not available yet.")
             : QString()));
    edgeLength_->setValue(node->options.targetEdgeLength);
    smoothing_->setChecked(node->options.smoothing);
}

void PropertiesPanel::rebuild() {
    if (!document_)
        return;
    const model::PartId id = document_->selection().part;
    model::BuildOptions options;
    options.targetEdgeLength = edgeLength_->value();
    options.smoothing = smoothing_->isChecked();
    try {
        auto command = model::RebuildPartCommand::create(*document_, id, options);
        const QString dropped = command->droppedMessage();
        document_->undoStack()->push(command.release());
        emit statusMessage(dropped.isEmpty()
                               ? tr("Rebuilt %1").arg(document_->part(id).name)
                               : tr("Rebuilt %1; %2").arg(document_->part(id).name, dropped),
                           8000);
    } catch (const rigmesh::Error& error) {
        emit statusMessage(tr("Not rebuilt: %1").arg(QString::fromStdString(error.what())), 8000);
    }
}

}  // namespace rigmesh::widgets
