#include "tools/PaintTool.h"

#include <QCheckBox>
#include <QComboBox>
#include <QDoubleSpinBox>
#include <QFormLayout>
#include <QLabel>

#include "UserAction.h"
#include "base/Error.h"
#include "model/BoneDisplayName.h"
#include "model/ErrorText.h"
#include "model/GuardedUndo.h"
#include "model/commands/PaintWeightsCommand.h"
#include "part/WeightLists.h"
#include "viewport/RenderScene.h"
#include "viewport/ViewMath.h"
#include "viewport/Viewport.h"

namespace rigmesh::widgets {

namespace {

// The bone the selected joint stands for (as the weight view shows it).
std::optional<BoneId> selectedBone(const model::Document& document) {
    const model::Selection selection = document.selection();
    const model::PartNode* node = document.findPart(selection.part);
    if (!node || !node->part)
        return std::nullopt;
    return boneForJoint(node->part->skeleton, selection.joint);
}

}  // namespace

QString PaintTool::hint() const {
    return tr(
        "Paint Weights: select a joint (its bone is painted, shown red to blue), then drag "
        "over the part; Ctrl + click samples a vertex; Tool Options set the brush; Esc puts "
        "the stroke back");
}

std::optional<WeightView> PaintTool::weightView() const {
    return WeightView::SelectedBone;
}

void PaintTool::press(Viewport& viewport, QMouseEvent* event) {
    model::Document& document = *viewport.document();
    if (viewport.weightView() != WeightView::SelectedBone)
        viewport.setWeightView(WeightView::SelectedBone);
    if (event->modifiers() & Qt::ControlModifier) {
        sample(viewport, event->position());
        return;
    }
    // The stroke paints the selected joint's part wherever the cursor
    // passes over it; it may start beside the part (as in Blender).
    const std::optional<BoneId> bone = selectedBone(document);
    if (!bone) {
        emit status(tr("Select a joint first: its bone is the one painted"));
        return;
    }
    const model::PartId part = document.selection().part;
    const Part& before = *document.part(part).part;
    if (before.lockedBones.contains(*bone)) {
        emit status(tr("%1 is locked: unlock it in the Skin Weights panel to paint it")
                        .arg(model::boneDisplayName(before, *bone)));
        return;
    }
    stroke_ = std::make_unique<model::SkinningPreview>(document, part);
    bone_ = *bone;
    working_ = std::make_shared<Part>(before);
    painter_ = std::make_unique<WeightPainter>(working_->mesh);
    dabs_.clear();
    dab(viewport, event->position());
    lastDab_ = event->position();
}

void PaintTool::move(Viewport& viewport, QMouseEvent* event) {
    cursor_ = event->position();
    if (!stroke_ || !(event->buttons() & Qt::LeftButton))
        return;
    // Dabs a third of the radius apart along the drag.
    if (QLineF(lastDab_, event->position()).length() < radiusPixels / 3.0) {
        viewport.update();
        return;
    }
    dab(viewport, event->position());
    lastDab_ = event->position();
}

void PaintTool::dab(Viewport& viewport, const QPointF& pixel) {
    model::Document& document = *viewport.document();
    const model::PartId part = stroke_->partId();
    if (!document.contains(part))
        return;
    const auto hit = viewport.surfaceAt(pixel);
    if (!hit || hit->part != part)
        return;
    const model::Placement placement = document.part(part).placement;
    const Vec3 local = working_->mesh.vertices[hit->vertex];
    const Vec3 centre = placement.toWorld(local);
    // The radius in pixels as a length at the surface's depth.
    const QVector3D at = toQt(centre);
    const double radius = (viewport.viewPlanePoint(pixel + QPointF(radiusPixels, 0.0), at) -
                           viewport.viewPlanePoint(pixel, at))
                              .length();
    WeightDab dab;
    dab.bone = bone_;
    dab.mode = mode;
    dab.falloff = falloff;
    dab.centre = centre;
    dab.radius = radius;
    dab.strength = strength;
    dab.value = value;
    dab.mirror = mirror;
    if (frontFacesOnly)
        dab.towardsViewer = -toEigen(viewport.camera().forward());
    WeightDab partDab = dab;
    partDab.centre = local;
    if (dab.towardsViewer)
        partDab.towardsViewer = placement.directionToLocal(*dab.towardsViewer);
    partDab.locked = working_->lockedBones;
    if (!runUserAction(
            name(), [this](const QString& failure) { emit status(failure); },
            [&] { painter_->paint(*working_, partDab); }))
        return;
    dabs_.push_back(dab);
    // A live preview; the stroke becomes one command on release.
    stroke_->preview(std::make_shared<const Part>(*working_));
}

void PaintTool::sample(Viewport& viewport, const QPointF& pixel) {
    const model::Document& document = *viewport.document();
    const auto hit = viewport.surfaceAt(pixel);
    if (!hit)
        return;
    viewport.setInspectedVertex(Viewport::SurfaceHit{hit->part, hit->vertex});
    const Part& part = *document.part(hit->part).part;
    const std::optional<BoneId> bone = selectedBone(document);
    if (!bone || hit->part != document.selection().part ||
        hit->vertex >= static_cast<int>(part.weights.perVertex.size())) {
        emit status(viewport.weightsAt(pixel));
        return;
    }
    value = weightOfBone(part.weights.perVertex[hit->vertex], *bone);
    if (valueBox_)
        valueBox_->setValue(value);
    emit status(tr("Sampled %1 = %2 at vertex %3: the Replace brush paints it")
                    .arg(model::boneDisplayName(part, *bone))
                    .arg(value, 0, 'f', 3)
                    .arg(hit->vertex));
}

void PaintTool::release(Viewport& viewport, QMouseEvent*) {
    if (!stroke_)
        return;
    model::Document& document = *viewport.document();
    const model::PartId part = stroke_->partId();
    if (document.contains(part) && dabs_.empty()) {
        emit status(
            tr("The stroke did not pass over %1: nothing painted").arg(document.part(part).name));
    } else if (document.contains(part)) {
        // The stroke as one command, painted again on the part as the stroke
        // found it.
        runUserAction(
            name(), [this](const QString& failure) { emit status(failure); },
            [&] {
                QString message;
                stroke_->commit([&]() -> std::unique_ptr<QUndoCommand> {
                    auto command = model::PaintWeightsCommand::create(document, part, dabs_);
                    const QString name = document.part(part).name;
                    if (command->changedVertices() == 0) {
                        // Nothing to undo: no step in the history for it.
                        message =
                            command->skippedOnlyBone() > 0
                                ? tr("The stroke changed no weights: %1 has one bone only, whose "
                                     "weight is 1 everywhere")
                                      .arg(name)
                            : command->skippedVertices() > 0
                                ? tr("The stroke changed no weights: every other bone there is "
                                     "locked")
                                : tr("The stroke changed no weights: they are already as it "
                                     "paints");
                        return nullptr;
                    }
                    message = tr("Painted %n dab(s), %1 vertices changed", nullptr,
                                 static_cast<int>(dabs_.size()))
                                  .arg(command->changedVertices());
                    if (command->skippedVertices() > 0)
                        message +=
                            tr("; %n vertex visit(s) skipped: every other bone there is locked",
                               nullptr, command->skippedVertices());
                    if (command->unpairedVertices() > 0)
                        message +=
                            tr("; %n vertex visit(s) painted on one side only: no mirror "
                               "partner there",
                               nullptr, command->unpairedVertices());
                    return command;
                });
                emit status(message);
            });
    }
    endStroke();
}

void PaintTool::cancel(Viewport&) {
    if (stroke_ && stroke_->previewing())
        emit status(tr("Stroke put back"));
    endStroke();
}

void PaintTool::endStroke() {
    stroke_.reset();  // reverts what was not committed
    dabs_.clear();
    painter_.reset();
    working_.reset();
}

void PaintTool::hover(Viewport& viewport, QMouseEvent* event) {
    cursor_ = event->position();
    cursorInView_ = true;
    viewport.update();  // the brush circle follows the cursor
}

void PaintTool::addOverlay(const Viewport& viewport, ColouredVertices& lines) const {
    if (!cursorInView_)
        return;
    // The brush circle, on the view plane under the cursor.
    const auto hit = viewport.surfaceAt(cursor_);
    const QVector3D through = hit ? toQt([&] {
        const model::PartNode& node = viewport.document()->part(hit->part);
        return Vec3(node.placement.toWorld(node.part->mesh.vertices[hit->vertex]));
    }())
                                  : viewport.sceneCentre();
    const QVector3D colour(1.0f, 1.0f, 1.0f);
    constexpr int kSegments = 48;
    for (int i = 0; i < kSegments; ++i) {
        for (int k = 0; k < 2; ++k) {
            const double a = 2.0 * M_PI * (i + k) / kSegments;
            lines.add(viewport.viewPlanePoint(
                          cursor_ + radiusPixels * QPointF(std::cos(a), std::sin(a)), through),
                      colour);
        }
    }
}

QWidget* PaintTool::optionsWidget() {
    if (options_)
        return options_;
    options_ = new QWidget;
    auto* form = new QFormLayout(options_);
    auto* modes = new QComboBox(options_);
    modes->setObjectName(QStringLiteral("paintMode"));
    modes->addItems({tr("Add"), tr("Subtract"), tr("Replace"), tr("Smooth")});
    connect(modes, &QComboBox::currentIndexChanged, this,
            [this](int index) { mode = static_cast<BrushMode>(index); });
    form->addRow(tr("Brush"), modes);
    auto* falloffs = new QComboBox(options_);
    falloffs->setObjectName(QStringLiteral("paintFalloff"));
    falloffs->addItems({tr("Smooth"), tr("Linear"), tr("Sharp"), tr("Constant")});
    falloffs->setToolTip(tr("How the brush's strength falls off from its centre to its rim"));
    connect(falloffs, &QComboBox::currentIndexChanged, this,
            [this](int index) { falloff = static_cast<BrushFalloff>(index); });
    form->addRow(tr("Falloff"), falloffs);
    auto* radius = new QDoubleSpinBox(options_);
    radius->setRange(2.0, 400.0);
    radius->setSuffix(tr(" px"));
    radius->setValue(radiusPixels);
    connect(radius, &QDoubleSpinBox::valueChanged, this, [this](double v) { radiusPixels = v; });
    form->addRow(tr("Radius"), radius);
    auto* strengthBox = new QDoubleSpinBox(options_);
    strengthBox->setRange(0.0, 1.0);
    strengthBox->setSingleStep(0.05);
    strengthBox->setValue(strength);
    connect(strengthBox, &QDoubleSpinBox::valueChanged, this, [this](double v) { strength = v; });
    form->addRow(tr("Strength"), strengthBox);
    valueBox_ = new QDoubleSpinBox(options_);
    valueBox_->setObjectName(QStringLiteral("paintValue"));
    valueBox_->setRange(0.0, 1.0);
    valueBox_->setSingleStep(0.05);
    valueBox_->setDecimals(3);
    valueBox_->setValue(value);
    valueBox_->setToolTip(tr("The weight the Replace brush paints towards (Ctrl + click samples)"));
    connect(valueBox_, &QDoubleSpinBox::valueChanged, this, [this](double v) { value = v; });
    form->addRow(tr("Weight"), valueBox_);
    auto* front = new QCheckBox(tr("Front faces only"), options_);
    front->setObjectName(QStringLiteral("paintFrontFacesOnly"));
    front->setChecked(frontFacesOnly);
    front->setToolTip(tr("Off: the brush also paints the far side of the part, through it"));
    connect(front, &QCheckBox::toggled, this, [this](bool on) { frontFacesOnly = on; });
    form->addRow(front);
    auto* mirrorBox = new QCheckBox(tr("X-mirror (left and right)"), options_);
    mirrorBox->setObjectName(QStringLiteral("paintMirror"));
    mirrorBox->setToolTip(
        tr("Also paints the other side, about the part's left-right mirror plane, on the bone's "
           "mirror image (Blender's X-mirror)"));
    connect(mirrorBox, &QCheckBox::toggled, this, [this](bool on) { mirror = on; });
    form->addRow(mirrorBox);
    return options_;
}

}  // namespace rigmesh::widgets
