#include "tools/PaintTool.h"

#include <QCheckBox>
#include <QComboBox>
#include <QDoubleSpinBox>
#include <QFormLayout>
#include <QLabel>

#include "base/Error.h"
#include "model/commands/PaintWeightsCommand.h"
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
        "over the part; Tool Options set the brush; Esc puts the stroke back");
}

void PaintTool::press(Viewport& viewport, QMouseEvent* event) {
    model::Document& document = *viewport.document();
    if (viewport.weightView() != WeightView::SelectedBone)
        viewport.setWeightView(WeightView::SelectedBone);
    const std::optional<BoneId> bone = selectedBone(document);
    const auto hit = viewport.surfaceAt(event->position());
    if (!bone || !hit || hit->part != document.selection().part) {
        emit viewport.statusMessage(
            tr("Select a joint of the part first (its bone is the one painted), then paint on "
               "that part"));
        return;
    }
    part_ = hit->part;
    bone_ = *bone;
    before_ = document.part(*part_).part;
    working_ = std::make_shared<Part>(*before_);
    dabs_.clear();
    dab(viewport, event->position());
    lastDab_ = event->position();
}

void PaintTool::move(Viewport& viewport, QMouseEvent* event) {
    cursor_ = event->position();
    if (!part_ || !(event->buttons() & Qt::LeftButton))
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
    if (!document.contains(*part_))
        return;
    const auto hit = viewport.surfaceAt(pixel);
    if (!hit || hit->part != *part_)
        return;
    const model::PartNode node = document.part(*part_);  // a copy: replacePart changes it
    const Vec3 local = working_->mesh.vertices[hit->vertex];
    const Vec3 centre = node.placement.rotation * local + node.placement.translation;
    // The radius in pixels as a length at the surface's depth.
    const QVector3D at = toQt(centre);
    const double radius = (viewport.viewPlanePoint(pixel + QPointF(radiusPixels, 0.0), at) -
                           viewport.viewPlanePoint(pixel, at))
                              .length();
    WeightDab dab;
    dab.bone = bone_;
    dab.mode = mode;
    dab.centre = centre;
    dab.radius = radius;
    dab.strength = strength;
    dab.value = value;
    dab.mirror = mirror && working_->mirror.size() == working_->mesh.vertices.size();
    WeightDab partDab = dab;
    partDab.centre = local;
    try {
        paintWeights(*working_, partDab);
    } catch (const Error& error) {
        emit viewport.statusMessage(QString::fromStdString(error.what()));
        return;
    }
    dabs_.push_back(dab);
    // A live preview; the stroke becomes commands on release.
    document.replacePart(*part_, std::make_shared<const Part>(*working_), node.options, node.pose,
                         node.pinnedJoints, node.clip);
}

void PaintTool::release(Viewport& viewport, QMouseEvent*) {
    if (!part_)
        return;
    model::Document& document = *viewport.document();
    const model::PartId part = *part_;
    part_.reset();
    if (!document.contains(part) || dabs_.empty())
        return;
    // Back to where the stroke started, then the dabs as commands: one undo
    // step, each dab a recipe step.
    const model::PartNode node = document.part(part);
    document.replacePart(part, before_, node.options, node.pose, node.pinnedJoints, node.clip);
    document.undoStack()->beginMacro(tr("Paint Weights of %1").arg(node.name));
    int changed = 0;
    for (const WeightDab& dab : dabs_) {
        auto command = model::PaintWeightsCommand::create(document, part, dab);
        changed += command->changedVertices();
        document.undoStack()->push(command.release());
    }
    document.undoStack()->endMacro();
    emit viewport.statusMessage(
        tr("Painted %n dab(s), %1 vertex changes", nullptr, static_cast<int>(dabs_.size()))
            .arg(changed));
    dabs_.clear();
    working_.reset();
    before_.reset();
}

void PaintTool::cancel(Viewport& viewport) {
    if (part_ && viewport.document()->contains(*part_)) {
        const model::PartNode node = viewport.document()->part(*part_);
        viewport.document()->replacePart(*part_, before_, node.options, node.pose,
                                         node.pinnedJoints, node.clip);
        emit viewport.statusMessage(tr("Stroke put back"));
    }
    part_.reset();
    dabs_.clear();
    working_.reset();
    before_.reset();
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
        return Vec3(node.placement.rotation * node.part->mesh.vertices[hit->vertex] +
                    node.placement.translation);
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
    auto* weight = new QDoubleSpinBox(options_);
    weight->setRange(0.0, 1.0);
    weight->setSingleStep(0.05);
    weight->setValue(value);
    weight->setToolTip(tr("The weight the Replace brush paints towards"));
    connect(weight, &QDoubleSpinBox::valueChanged, this, [this](double v) { value = v; });
    form->addRow(tr("Weight"), weight);
    auto* mirrorBox = new QCheckBox(tr("X-mirror (through the sketch plane)"), options_);
    connect(mirrorBox, &QCheckBox::toggled, this, [this](bool on) { mirror = on; });
    form->addRow(mirrorBox);
    return options_;
}

}  // namespace rigmesh::widgets
