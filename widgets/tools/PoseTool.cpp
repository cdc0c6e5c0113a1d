#include "tools/PoseTool.h"

#include <QCheckBox>
#include <QVBoxLayout>
#include <QtMath>
#include <cmath>

#include "UserAction.h"
#include "base/Error.h"
#include "model/ErrorText.h"
#include "model/GuardedUndo.h"
#include "model/PoseDrag.h"
#include "model/commands/SetJointPinnedCommand.h"
#include "pose/InverseKinematics.h"
#include "viewport/RenderScene.h"
#include "viewport/ViewMath.h"
#include "viewport/Viewport.h"

namespace rigmesh::widgets {
namespace {

// The rotation ring around the selected joint: its radius and the band
// either side of it that grabs it.
constexpr double kRingRadiusPixels = 44.0;
constexpr double kRingBandPixels = 6.0;

// The joint a bone ending at `joint` turns about: its parent, or the root
// itself (whose rotation turns the whole part), or an attached chain's root
// itself (its rotation turns its chain, pose/Pose.h).
JointId turnPivot(const Skeleton& skeleton, JointId joint) {
    const JointId parent = poseParent(skeleton, joint);
    return parent == kNoJoint || skeleton.isAttached(joint) ? joint : parent;
}

}  // namespace

QString PoseTool::hint() const {
    return tr(
        "Pose: drag a joint (IK, this limb only); Alt + drag reaches through the whole "
        "body; drag a bone, Ctrl + drag the joint it ends at or drag the selected bone's ring "
        "to turn it (FK); Shift + click pins or unpins a joint");
}

void PoseTool::press(Viewport& viewport, QMouseEvent* event) {
    model::Document& document = *viewport.document();
    const auto hit = viewport.jointAt(event->position());
    if (!hit && onRing(viewport, event->position())) {
        grabRing(viewport, event->position());
        return;
    }
    if (!hit) {
        if (const auto bone = viewport.boneAt(event->position()))
            grabBone(viewport, *bone, event->position());
        else
            emit status(tr("Click on a joint or a bone to pose the part"), 5000);
        return;
    }
    document.setSelection(*hit);
    const model::PartNode& node = document.part(hit->part);
    if (event->modifiers() & Qt::ShiftModifier) {
        const bool pinned = node.pinnedJoints.count(hit->joint) > 0;
        // What it throws goes to the viewport (widgets/UserAction.h).
        model::pushCommand(document, std::make_unique<model::SetJointPinnedCommand>(
                                         document, hit->part, hit->joint, !pinned));
        return;
    }
    Drag drag;
    drag.part = hit->part;
    drag.joint = hit->joint;
    drag.grabPoint = viewport.jointWorldPosition(hit->part, hit->joint);
    drag.startPixel = event->position();
    drag.startPose = node.pose;
    // Alt flips the tool option for this drag.
    drag.wholeBody = wholeBodyByDefault_ != ((event->modifiers() & Qt::AltModifier) != 0);
    if (event->modifiers() & Qt::ControlModifier) {
        // FK: the bone ending at the joint turns about its head.
        drag.forward = true;
        drag.pivot = poseParent(node.part->skeleton, hit->joint);
        if (node.part->skeleton.isAttached(hit->joint))
            drag.pivot = hit->joint;  // a chain's root turns its chain about itself
        if (drag.pivot == kNoJoint) {
            emit status(
                tr("The root joint ends no bone: drag its ring to turn the whole part, or drag "
                   "it without Ctrl to move the part"),
                5000);
            return;
        }
    }
    startDrag(*viewport.document(), drag);
}

std::optional<QPointF> PoseTool::ringCentre(const Viewport& viewport) const {
    const model::Document& document = *viewport.document();
    const model::Selection selection = document.selection();
    const model::PartNode* node = document.findPart(selection.part);
    if (!node || !node->visible || !node->part || !node->part->skeleton.hasJoint(selection.joint))
        return std::nullopt;
    const JointId pivot = turnPivot(node->part->skeleton, selection.joint);
    const QVector3D at = viewport.camera().project(
        viewport.jointWorldPosition(selection.part, pivot), QSizeF(viewport.size()));
    return QPointF(at.x(), at.y());
}

bool PoseTool::onRing(const Viewport& viewport, const QPointF& pixel) const {
    const auto centre = ringCentre(viewport);
    if (!centre)
        return false;
    const double d = std::hypot(pixel.x() - centre->x(), pixel.y() - centre->y());
    return std::abs(d - kRingRadiusPixels) <= kRingBandPixels;
}

void PoseTool::grabRing(Viewport& viewport, const QPointF& pixel) {
    // The ring turns the selected joint's bone (the one ending at it) about
    // its head and the view axis, carrying its descendants only (Blender's R
    // on a pose bone); on the root it turns the whole part.
    const model::Document& document = *viewport.document();
    const model::Selection selection = document.selection();
    const model::PartNode& node = document.part(selection.part);
    Drag drag;
    drag.part = selection.part;
    drag.joint = selection.joint;
    drag.pivot = turnPivot(node.part->skeleton, selection.joint);
    drag.grabPoint = viewport.jointWorldPosition(selection.part, selection.joint);
    drag.startPixel = pixel;
    drag.startPose = node.pose;
    drag.forward = true;
    drag.ring = true;
    startDrag(*viewport.document(), drag);
}

QWidget* PoseTool::optionsWidget() {
    if (options_)
        return options_;
    options_ = new QWidget;
    auto* layout = new QVBoxLayout(options_);
    auto* wholeBody = new QCheckBox(tr("IK reaches through the whole body"), options_);
    wholeBody->setObjectName(QStringLiteral("poseWholeBody"));
    wholeBody->setToolTip(
        tr("Off: a drag moves the limb up to the nearest junction or pinned "
           "joint. Alt + drag does the other for one drag."));
    connect(wholeBody, &QCheckBox::toggled, this, [this](bool on) { wholeBodyByDefault_ = on; });
    layout->addWidget(wholeBody);
    layout->addStretch();
    return options_;
}

void PoseTool::hover(Viewport& viewport, QMouseEvent* event) {
    const bool hovered = onRing(viewport, event->position());
    if (hovered != ringHovered_) {
        ringHovered_ = hovered;
        viewport.update();
    }
}

void PoseTool::addOverlay(const Viewport& viewport, ColouredVertices& lines) const {
    const auto centre = ringCentre(viewport);
    if (!centre)
        return;
    const model::Selection selection = viewport.document()->selection();
    const QVector3D through = viewport.jointWorldPosition(
        selection.part,
        turnPivot(viewport.document()->part(selection.part).part->skeleton, selection.joint));
    const bool active = ringHovered_ || (drag_ && drag_->ring);
    const QVector3D colour = active ? QVector3D(1.0f, 0.8f, 0.4f) : QVector3D(1.0f, 0.55f, 0.1f);
    // The ring on the view plane through the joint, as segments; two small
    // arrowheads on it say "turn".
    auto onScreen = [&](double angle, double radius) {
        return viewport.viewPlanePoint(
            QPointF(centre->x() + radius * std::cos(angle), centre->y() + radius * std::sin(angle)),
            through);
    };
    constexpr int kSegments = 64;
    for (int i = 0; i < kSegments; ++i) {
        lines.add(onScreen(2 * M_PI * i / kSegments, kRingRadiusPixels), colour);
        lines.add(onScreen(2 * M_PI * (i + 1) / kSegments, kRingRadiusPixels), colour);
    }
    for (const double angle : {M_PI / 4, M_PI + M_PI / 4}) {
        const QVector3D tip = onScreen(angle, kRingRadiusPixels);
        for (const double side : {-5.0, 5.0}) {
            lines.add(tip, colour);
            lines.add(onScreen(angle - 0.16, kRingRadiusPixels + side), colour);
        }
    }
}

void PoseTool::grabBone(Viewport& viewport, const BoneHit& bone, const QPointF& pixel) {
    // FK by the bone: it turns about its end nearer the
    // root by its own rotation, keyed by its other end (pose/Pose.h), which
    // becomes the selection (the joint standing for the bone).
    model::Document& document = *viewport.document();
    const model::PartNode& node = document.part(bone.part);
    const Skeleton& skeleton = node.part->skeleton;
    const bool reversed = poseParent(skeleton, bone.from) == bone.to;  // never reoriented
    Drag drag;
    drag.part = bone.part;
    drag.pivot = reversed ? bone.to : bone.from;
    drag.joint = reversed ? bone.from : bone.to;
    drag.grabPoint = viewport.jointWorldPosition(bone.part, drag.joint);
    drag.startPixel = pixel;
    drag.startPose = node.pose;
    drag.forward = true;
    document.setSelection({bone.part, drag.joint});
    startDrag(*viewport.document(), drag);
}

void PoseTool::move(Viewport& viewport, QMouseEvent* event) {
    if (!drag_ || !(event->buttons() & Qt::LeftButton))
        return;
    if (!viewport.document()->contains(drag_->part)) {
        endDrag();
        return;
    }
    if (drag_->forward)
        rotateWithFk(viewport, event->position());
    else
        dragWithIk(viewport, event->position());
}

void PoseTool::dragWithIk(Viewport& viewport, const QPointF& pixel) {
    model::Document& document = *viewport.document();
    const model::PartNode& node = document.part(drag_->part);
    // The target on the view plane through the joint, in the part's frame.
    const Vec3 world = toEigen(viewport.viewPlanePoint(pixel, drag_->grabPoint));
    const Vec3 target = node.placement.toLocal(world);
    // The same IK as the recipe's "pose" step (model::dragPartJoint).
    const IkResult result = model::dragPartJoint(
        node, drag_->joint, target, drag_->wholeBody ? model::IkReach::Body : model::IkReach::Limb);
    // A live preview, warm starting the next step; one command on release.
    preview_->preview(result.pose);
}

void PoseTool::rotateWithFk(Viewport& viewport, const QPointF& pixel) {
    model::Document& document = *viewport.document();
    const model::PartNode& node = document.part(drag_->part);
    // The angle swept around the pivot on screen, about the view direction.
    const QVector3D pivotWorld = viewport.jointWorldPosition(drag_->part, drag_->pivot);
    const QVector3D pivotScreen = viewport.camera().project(pivotWorld, QSizeF(viewport.size()));
    const double sweep =
        screenSweep(QPointF(pivotScreen.x(), pivotScreen.y()), drag_->startPixel, pixel);
    const Vec3 viewAxis = toEigen(viewport.camera().forward());
    // Screen y points down: a clockwise sweep on screen is a positive turn
    // about the view direction.
    const Eigen::Quaterniond worldTurn(Eigen::AngleAxisd(sweep, viewAxis));
    const Eigen::Quaterniond partTurn =
        node.placement.rotation.conjugate() * worldTurn * node.placement.rotation;
    // A bone's rotation composes in its parent bone's frame:
    // r' = W_parent^-1 R W_parent r (the root's in the part's frame).
    const PosedSkeleton& posed = viewport.posedSkeleton(node);
    Pose pose = drag_->startPose;
    const Skeleton& skeleton = node.part->skeleton;
    // The parent bone's world rotation: the transform of the bone ending at
    // the joint's parent in the pose (the pivot, or for an attached chain's
    // root the bone it hangs from), unchanged by the turn (it moves only the
    // bone's subtree); none for the root.
    const JointId frame = poseParent(skeleton, drag_->joint);
    const Eigen::Quaterniond parentWorld =
        frame == kNoJoint ? Eigen::Quaterniond::Identity()
                          : posed.jointTransforms[skeleton.indexOfJoint(frame)].rotation;
    pose.setRotation(drag_->joint, (parentWorld.conjugate() * partTurn * parentWorld *
                                    drag_->startPose.rotation(drag_->joint))
                                       .normalized());
    // A live preview; the drag becomes one command on release.
    preview_->preview(pose);
}

void PoseTool::release(Viewport&, QMouseEvent*) {
    if (!drag_)
        return;
    // One undo step per drag.
    runUserAction(
        {}, [this](const QString& failure) { emit status(tr("Not posed: %1").arg(failure)); },
        [&] { preview_->commit(drag_->joint); });
    endDrag();
}

void PoseTool::cancel(Viewport&) {
    // A drag cut short (tool switch) leaves the pose as it was.
    endDrag();
}

void PoseTool::startDrag(model::Document& document, const Drag& drag) {
    drag_ = drag;
    preview_ = std::make_unique<model::PosePreview>(document, drag.part);
}

void PoseTool::endDrag() {
    drag_.reset();
    preview_.reset();  // reverts what was not committed
}

}  // namespace rigmesh::widgets
