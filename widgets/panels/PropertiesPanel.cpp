#include "panels/PropertiesPanel.h"

#include <QCheckBox>
#include <QDoubleSpinBox>
#include <QFormLayout>
#include <QGroupBox>
#include <QLabel>
#include <QMessageBox>
#include <QPointer>
#include <QPushButton>
#include <QSignalBlocker>
#include <QVBoxLayout>
#include <algorithm>
#include <cmath>
#include <memory>

#include "UserAction.h"
#include "base/Error.h"
#include "jobs/JobRunner.h"
#include "model/CountText.h"
#include "model/Document.h"
#include "model/ErrorText.h"
#include "model/GuardedUndo.h"
#include "model/PartBuilder.h"
#include "model/commands/RebuildPartCommand.h"
#include "model/preview/PosePreview.h"

namespace rigmesh::widgets {
namespace {

// Blender's XYZ Euler of a rotation R = Rz Ry Rx, in degrees, with Y in
// [-90, 90] (Eigen's eulerAngles puts the first angle in [0, 180] instead,
// which shows (30, 0, -45) as (-150, -180, 135)). At Y = +-90 (gimbal lock)
// X is 0 and Z takes the whole turn.
Vec3 xyzEulerDegrees(const Eigen::Quaterniond& rotation) {
    const Eigen::Matrix3d r = rotation.normalized().toRotationMatrix();
    const double y = std::asin(std::clamp(-r(2, 0), -1.0, 1.0));
    double x = 0, z = 0;
    if (std::abs(r(2, 0)) < 1.0 - 1e-12) {
        x = std::atan2(r(2, 1), r(2, 2));
        z = std::atan2(r(1, 0), r(0, 0));
    } else {
        z = std::atan2(-r(0, 1), r(1, 1));
    }
    return Vec3(x, y, z) * (180.0 / M_PI);
}

}  // namespace

PropertiesPanel::PropertiesPanel(QWidget* parent) : QWidget(parent) {
    confirmDiscard = [this](const QString& question) {
        return QMessageBox::question(this, tr("Rebuild"), question,
                                     QMessageBox::Yes | QMessageBox::Cancel,
                                     QMessageBox::Cancel) == QMessageBox::Yes;
    };
    auto* layout = new QVBoxLayout(this);
    title_ = new QLabel(this);
    title_->setStyleSheet(QStringLiteral("font-weight: bold"));
    figures_ = new QLabel(this);
    figures_->setTextInteractionFlags(Qt::TextSelectableByMouse);
    // Long notes (an unrigged import) wrap instead of widening the dock.
    figures_->setWordWrap(true);
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
    poseBox_ = new QGroupBox(tr("Bone rotation (XYZ Euler)"), this);
    auto* poseForm = new QFormLayout(poseBox_);
    const char* axes[] = {QT_TR_NOOP("X"), QT_TR_NOOP("Y"), QT_TR_NOOP("Z")};
    for (int k = 0; k < 3; ++k) {
        euler_[k] = new QDoubleSpinBox(poseBox_);
        euler_[k]->setObjectName(QStringLiteral("jointRotation") + QLatin1Char("XYZ"[k]));
        euler_[k]->setRange(-180.0, 180.0);
        euler_[k]->setDecimals(1);
        euler_[k]->setWrapping(true);
        euler_[k]->setSuffix(QStringLiteral("\u00b0"));
        euler_[k]->setKeyboardTracking(false);  // one command per typed value
        euler_[k]->setToolTip(
            tr("The rotation from rest, in degrees, of the bone ending at the selected joint "
               "about its head, relative to its parent bone; at the root, of the whole part "
               "about the root"));
        poseForm->addRow(tr(axes[k]), euler_[k]);
        connect(euler_[k], &QDoubleSpinBox::valueChanged, this, &PropertiesPanel::setJointRotation);
    }
    layout->addWidget(poseBox_);
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
    refreshPose();
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
        // This document's own edge length, never the last one shown (of
        // another document's part).
        edgeLength_->setValue(document_ ? model::documentEdgeLength(*document_) : 0.0);
        return;
    }
    const Part& part = *node->part;
    title_->setText(node->name);
    figures_->setText(
        tr("%1 vertices, %2 faces\n%3, %4\n")
            .arg(part.mesh.vertexCount())
            .arg(part.mesh.faceCount())
            .arg(model::countText(part.skeleton.jointCount(), tr("1 joint"), tr("%1 joints")),
                 model::countText(part.skeleton.boneCount(), tr("1 bone"), tr("%1 bones"))) +
        (!node->stroke.empty() ? tr("stroke of %1 points").arg(node->stroke.size())
                               : tr("made by merging or importing: no stroke to rebuild from")) +
        (part.skeleton.jointCount() == 0
             ? tr("\nNot rigged: imported as a static mesh. Tools > Auto-Rig Part gives it "
                  "a skeleton and skin weights.")
             : QString()));
    edgeLength_->setValue(node->options.targetEdgeLength);
    // A merged or imported part was not made by this smoothing: unchecked.
    smoothing_->setChecked(rebuildable && node->options.smoothing);
}

void PropertiesPanel::refreshPose() {
    const model::PartNode* node =
        document_ ? document_->findPart(document_->selection().part) : nullptr;
    const JointId joint = document_ ? document_->selection().joint : kNoJoint;
    const bool shown = node && node->part && node->part->skeleton.hasJoint(joint);
    poseBox_->setVisible(shown);
    if (!shown)
        return;
    // A joint stands for the bone ending at it, whose rotation it keys
    // (pose/Pose.h); the root's rotation turns the whole part.
    const bool root = joint == node->part->skeleton.root();
    poseBox_->setTitle(root ? tr("Root joint %1: whole part (XYZ Euler)").arg(joint)
                            : tr("Bone to joint %1 (XYZ Euler)").arg(joint));
    const Vec3 xyz = xyzEulerDegrees(node->pose.rotation(joint));
    for (int k = 0; k < 3; ++k) {
        const QSignalBlocker blocker(euler_[k]);
        euler_[k]->setValue(xyz[k]);
    }
}

void PropertiesPanel::setJointRotation() {
    if (!document_)
        return;
    const model::Selection selection = document_->selection();
    const model::PartNode* node = document_->findPart(selection.part);
    if (!node || !node->part || !node->part->skeleton.hasJoint(selection.joint))
        return;
    const Eigen::Quaterniond rotation =
        Eigen::AngleAxisd(euler_[2]->value() * M_PI / 180.0, Vec3::UnitZ()) *
        Eigen::AngleAxisd(euler_[1]->value() * M_PI / 180.0, Vec3::UnitY()) *
        Eigen::AngleAxisd(euler_[0]->value() * M_PI / 180.0, Vec3::UnitX());
    rigmesh::Pose pose = node->pose;
    pose.setRotation(selection.joint, rotation.normalized());
    runUserAction(
        {},
        [this](const QString& failure) {
            emit statusMessage(tr("Not posed: %1").arg(failure), 8000);
            refreshPose();
        },
        [&] {
            // Each typed value is its own undo step, which never merges with
            // the previous one.
            model::PosePreview preview(*document_, selection.part);
            preview.preview(pose);
            preview.commit(selection.joint);
        });
}

void PropertiesPanel::rebuild() {
    if (!document_)
        return;
    const model::PartId id = document_->selection().part;
    model::BuildOptions options;
    options.targetEdgeLength = edgeLength_->value();
    options.smoothing = smoothing_->isChecked();
    // A rebuild recomputes the weights from the sketch: ask before painted
    // weights go.
    const model::PartNode* node = document_->findPart(id);
    if (node && node->part && node->part->weightsPainted &&
        !confirmDiscard(tr("%1 has hand-painted skin weights. Rebuilding recomputes them from "
                           "the sketch and the painting is lost (Undo brings it back). "
                           "Rebuild anyway?")
                            .arg(node->name))) {
        emit statusMessage(tr("Not rebuilt: the painted weights are kept"), 6000);
        return;
    }
    if (!node || !node->part) {
        emit statusMessage(tr("Select a part to rebuild"), 4000);
        return;
    }
    // Built off the GUI thread from copies of the stroke (a fine edge length
    // can take seconds); the command is made and pushed here when done.
    const std::vector<Vec2> stroke = node->stroke;
    const QString name = node->name;
    QPointer<model::Document> document(document_);
    JobRunner::runOn(
        jobs_, tr("Rebuilding %1").arg(name),
        [=, this]() -> JobRunner::Apply {
            std::shared_ptr<const Part> part = model::buildPart(stroke, name, options);
            return [=, this]() {
                if (!document || !document->contains(id))
                    return;
                auto command = model::RebuildPartCommand::fromBuilt(*document, id, part, options);
                const QString dropped = command->droppedMessage();
                model::pushCommand(*document, std::move(command));
                emit statusMessage(dropped.isEmpty() ? tr("Rebuilt %1").arg(name)
                                                     : tr("Rebuilt %1; %2").arg(name, dropped),
                                   8000);
            };
        },
        [this](const QString& reason) {
            emit statusMessage(tr("Not rebuilt: %1").arg(reason), 8000);
        },
        [this, name] { emit statusMessage(tr("Rebuild of %1 cancelled").arg(name), 6000); });
}

}  // namespace rigmesh::widgets
