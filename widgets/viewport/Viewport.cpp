#include "viewport/Viewport.h"

#include <QContextMenuEvent>
#include <QCursor>

#include "viewport/BoneEditActions.h"

#include <algorithm>

#include <QGuiApplication>
#include <QOpenGLContext>

#include <Eigen/Geometry>
#include <QKeyEvent>
#include <QMouseEvent>
#include <QWheelEvent>
#include <limits>

#include "UserAction.h"
#include "model/OnionSkin.h"
#include "pose/ForwardKinematics.h"
#include "viewport/GlobalDifferences.h"
#include "viewport/SceneRenderer.h"
#include "viewport/ViewMath.h"
#include "viewport/ViewpointActions.h"
#include "viewport/ViewportTool.h"

namespace rigmesh::widgets {
namespace {

QMatrix4x4 placementMatrix(const model::Placement& placement) {
    Eigen::Affine3d affine = placement.affine();
    QMatrix4x4 m;
    for (int r = 0; r < 4; ++r)
        for (int c = 0; c < 4; ++c)
            m(r, c) = static_cast<float>(affine.matrix()(r, c));
    return m;
}

// Soft, distinct colours per part id.
QVector3D partColour(model::PartId id) {
    static const QVector3D palette[] = {{0.72f, 0.76f, 0.84f}, {0.80f, 0.74f, 0.66f},
                                        {0.68f, 0.80f, 0.70f}, {0.82f, 0.70f, 0.76f},
                                        {0.74f, 0.72f, 0.86f}, {0.84f, 0.80f, 0.62f}};
    return palette[id % (sizeof palette / sizeof palette[0])];
}

// Per bone: unit dual quaternion (real, dual) and 3x4 matrix rows of its
// skinning transform (world * inverse rest), for the GPU (Kavan et al. 2008).
void setSkinning(RenderPart& item, const PosedSkeleton& posed) {
    for (const RigidTransform& t : posed.boneTransforms) {
        const Eigen::Quaterniond& q = t.rotation;
        const Vec3& v = t.translation;
        // dual = 1/2 * (0, t) * q
        const Eigen::Quaterniond d(-0.5 * v.dot(q.vec()), 0, 0, 0);
        const Vec3 dualVector = 0.5 * (q.w() * v + v.cross(q.vec()));
        item.boneReal.emplace_back(float(q.x()), float(q.y()), float(q.z()), float(q.w()));
        item.boneDual.emplace_back(float(dualVector.x()), float(dualVector.y()),
                                   float(dualVector.z()), float(d.w()));
        const Eigen::Matrix3d r = q.toRotationMatrix();
        for (int row = 0; row < 3; ++row)
            item.boneRows.emplace_back(float(r(row, 0)), float(r(row, 1)), float(r(row, 2)),
                                       float(v[row]));
    }
}

// Runs `handler`, one of `tool`'s event handlers: what it throws (an undo
// step's redo(), the engine) is said in the status bar (widgets/UserAction.h)
// and the tool puts back what its drag previewed; the exception never
// reaches Qt's event loop. The document is as it was: the tools push
// through model/GuardedUndo.
template <typename Handler>
void runTool(Viewport& viewport, ViewportTool* tool, Handler&& handler) {
    const auto report = [&](const QString& failure) { emit viewport.statusMessage(failure); };
    if (runUserAction(tool->name(), report, std::forward<Handler>(handler)))
        return;
    runUserAction(tool->name(), report, [&] { tool->cancel(viewport); });
    viewport.update();
}

}  // namespace

const PosedSkeleton& Viewport::posedSkeleton(const model::PartNode& node) const {
    auto& cached = posedCache_[node.id];
    if (cached.part != node.part.get() || cached.pose.rotations != node.pose.rotations ||
        cached.pose.rootTranslation != node.pose.rootTranslation) {
        cached.part = node.part.get();
        cached.pose = node.pose;
        // A part without a skeleton (a static mesh imported unrigged) has
        // nothing to pose: it is drawn at rest.
        cached.posed = node.part->skeleton.jointCount() > 0
                           ? forwardKinematics(node.part->skeleton, node.pose)
                           : PosedSkeleton{};
    }
    return cached.posed;
}

bool Viewport::globalDifferencePending() const {
    return globalDifferences_->pending();
}

Viewport::Viewport(model::Document* document, QWidget* parent)
    : QOpenGLWidget(parent), document_(document), renderer_(std::make_unique<SceneRenderer>()) {
    QSurfaceFormat format = requiredFormat();
    format.setSamples(4);
    setFormat(format);
    setFocusPolicy(Qt::StrongFocus);
    setMouseTracking(true);
    globalDifferences_ = new GlobalDifferences(this);
    connect(globalDifferences_, &GlobalDifferences::ready, this, [this] { update(); });
    setMinimumSize(320, 240);
    auto refresh = [this] { update(); };
    auto changed = [this] {
        problemMark_.reset();
        update();
    };
    connect(document_, &model::Document::partInserted, this, changed);
    connect(document_, &model::Document::partRemoved, this, changed);
    connect(document_, &model::Document::partChanged, this, changed);
    connect(document_, &model::Document::selectionChanged, this, refresh);
    connect(document_, &model::Document::currentFrameChanged, this, refresh);
    camera_.setView(0, 0);
}

QString Viewport::unavailableReason() {
    // Probing with a context of our own: QOpenGLWidget on a platform without
    // OpenGL only warns, and Qt 6.4 then crashes on the first window flush.
    QOpenGLContext probe;
    probe.setFormat(requiredFormat());
    const QString platform = QGuiApplication::platformName();
    if (!probe.create())
        return tr("The 3D view needs OpenGL %1.%2 (core profile), which the \"%3\" display "
                  "platform does not provide. Run RigMesh Studio on a desktop (X11 or Wayland) "
                  "or under xvfb-run.")
            .arg(requiredFormat().majorVersion())
            .arg(requiredFormat().minorVersion())
            .arg(platform);
    const QSurfaceFormat got = probe.format();
    if (got.version() < requiredFormat().version())
        return tr("The 3D view needs OpenGL %1.%2, but the \"%3\" platform gives OpenGL %4.%5.")
            .arg(requiredFormat().majorVersion())
            .arg(requiredFormat().minorVersion())
            .arg(platform)
            .arg(got.majorVersion())
            .arg(got.minorVersion());
    return {};
}

QSurfaceFormat Viewport::requiredFormat() {
    QSurfaceFormat format;
    format.setVersion(3, 3);
    format.setProfile(QSurfaceFormat::CoreProfile);
    format.setDepthBufferSize(24);
    return format;
}

Viewport::~Viewport() {
    makeCurrent();
    renderer_->release();
    doneCurrent();
}

void Viewport::setTool(ViewportTool* tool) {
    if (tool_ && tool_ != tool)
        runTool(*this, tool_, [&] { tool_->cancel(*this); });
    tool_ = tool;
    if (tool_)
        emit statusMessage(tool_->hint());
}

void Viewport::setWireframe(bool on) {
    wireframe_ = on;
    update();
}

void Viewport::setDualQuaternionSkinning(bool on) {
    dualQuaternion_ = on;
    update();
}

void Viewport::setOnionSkin(bool on) {
    onionSkin_ = on;
    update();
}

void Viewport::setGridVisible(bool on) {
    gridVisible_ = on;
    update();
}

void Viewport::setStrokeOverlay(std::vector<QVector3D> points) {
    strokeOverlay_ = std::move(points);
    if (strokeOverlay_.size() == 1)
        problemMark_.reset();  // a new stroke begins
    update();
}

void Viewport::setProblemMark(std::optional<QVector3D> at) {
    problemMark_ = at;
    update();
}

void Viewport::initializeGL() {
    QString error;
    if (!renderer_->initialize(&error))
        emit statusMessage(tr("OpenGL 3.3 shaders failed: %1").arg(error));
}

void Viewport::paintGL() {
    // A document opened with parts is framed once, when first shown; a
    // sketch or an import later never moves the camera (Home does).
    if (!framedOnce_) {
        framedOnce_ = true;
        if (document_->partCount() > 0)
            frameAll();
    }
    if (!floorHeight_)
        floorHeight_ = floorHeight();  // an empty scene's floor, kept from now on
    renderer_->render(
        gatherScene(), camera_,
        QSize(int(width() * devicePixelRatioF()), int(height() * devicePixelRatioF())));
}

Eigen::AlignedBox3d Viewport::sceneBox(bool selectedOnly) const {
    Eigen::AlignedBox3d box;
    const auto selection = document_->selection();
    for (const model::PartNode& node : document_->parts()) {
        if (!node.visible || !node.part)
            continue;
        if (selectedOnly && node.id != selection.part)
            continue;
        if (selectedOnly && selection.joint != kNoJoint &&
            node.part->skeleton.hasJoint(selection.joint)) {
            const Vec3 p = node.placement.toWorld(
                posedSkeleton(node)
                    .jointPositions[node.part->skeleton.indexOfJoint(selection.joint)]);
            box.extend(p);
            continue;
        }
        box.extend(model::worldBounds(node));
    }
    return box;
}

QVector3D Viewport::sceneCentre() const {
    const auto box = sceneBox(false);
    return box.isEmpty() ? QVector3D(0, 0, 0) : toQt(box.center());
}

void Viewport::frameBox(const Eigen::AlignedBox3d& box) {
    if (box.isEmpty())
        return;
    const double radius = std::max(0.5 * box.diagonal().norm(), 1e-6);
    camera_.frame(toQt(box.center()), radius);
    update();
}

double Viewport::gridSpacing() const {
    // About 10 to 100 lines across the view's height.
    return std::pow(10.0,
                    std::floor(std::log10(std::max(camera_.halfHeightAtTarget(), 1e-30) / 2.0)));
}

double Viewport::floorHeight() const {
    // Before any framing (an empty scene): a floor in the lower part of the
    // view, seen from slightly above (not edge-on through the centre), while
    // the sketch plane stays the front plane through the centre.
    return floorHeight_.value_or(camera_.target().y() - 0.22 * camera_.distance());
}

void Viewport::frameAll() {
    const Eigen::AlignedBox3d box = sceneBox(false);
    frameBox(box);
    // The floor goes under the parts framed, and stays there.
    if (!box.isEmpty())
        floorHeight_ = box.min().y();
}

void Viewport::frameSelected() {
    auto box = sceneBox(true);
    if (box.isEmpty())
        box = sceneBox(false);
    if (!box.isEmpty() && box.diagonal().norm() == 0)
        box.extend(box.min() + Vec3::Constant(0.1 * camera_.distance()));
    frameBox(box);
}

RenderScene Viewport::gatherScene() const {
    RenderScene scene;
    scene.wireframe = wireframe_;
    scene.dualQuaternionSkinning = dualQuaternion_;
    scene.showGrid = gridVisible_;
    scene.weightView = weightView_;
    // The grid's spacing follows the zoom alone; its lines reach well past
    // the view.
    scene.gridSpacing = static_cast<float>(gridSpacing());
    scene.gridLines = std::clamp(
        static_cast<int>(std::ceil(4.0 * camera_.halfHeightAtTarget() / gridSpacing())), 5, 100);
    scene.gridCentre = camera_.target();
    const std::optional<AxisView> axis = camera_.orthographic() ? camera_.axisView() : std::nullopt;
    if (axis && axis != AxisView::Top && axis != AxisView::Bottom) {
        // An orthographic side view sees the floor edge-on: its grid is
        // the view's own plane through the target, as in Blender.
        scene.gridNormal = axis == AxisView::Front || axis == AxisView::Back ? 2 : 0;
    } else {
        // The floor keeps its height as parts come (a lower part does not
        // pull it down) and as the view zooms.
        scene.gridCentre.setY(static_cast<float>(floorHeight()));
    }
    const auto selection = document_->selection();
    const std::vector<ViewportTool::PartInFront> inFront =
        tool_ ? tool_->partsInFront(*this) : std::vector<ViewportTool::PartInFront>{};
    for (const model::PartNode& node : document_->parts()) {
        if (!node.visible || !node.part)
            continue;
        RenderPart item;
        item.part = node.part;
        item.model = placementMatrix(node.placement);
        item.colour = partColour(node.id);
        item.selected = node.id == selection.part;
        if (item.selected && selection.joint != kNoJoint)
            if (const auto bone = boneForJoint(node.part->skeleton, selection.joint))
                item.weightBone = node.part->skeleton.indexOfBone(*bone);
        if (weightView_ == WeightView::GlobalDifference)
            item.globalDifference = globalDifferences_->of(node.part);
        const PosedSkeleton& posed = posedSkeleton(node);
        setSkinning(item, posed);
        if (onionSkin_ && node.part->skeleton.jointCount() > 0) {
            // Previous key reddish, next key greenish, as onion skins tint them.
            const model::OnionPoses onion = model::onionPoses(*document_, node.id);
            for (const auto& [pose, colour] :
                 {std::pair{onion.previous, QVector3D(1.0f, 0.45f, 0.35f)},
                  std::pair{onion.next, QVector3D(0.4f, 0.85f, 0.45f)}}) {
                if (!pose)
                    continue;
                RenderPart ghost;
                ghost.part = node.part;
                ghost.model = item.model;
                ghost.colour = colour;
                ghost.opacity = 0.3f;
                setSkinning(ghost, forwardKinematics(node.part->skeleton, *pose));
                scene.ghosts.push_back(std::move(ghost));
            }
        }
        const auto front = std::find_if(inFront.begin(), inFront.end(),
                                        [&](const auto& f) { return f.part == node.id; });
        if (front == inFront.end()) {
            scene.parts.push_back(std::move(item));
        } else {
            item.opacity = 0.55f;
            if (front->resultOffset) {
                // Where the tool's action puts it, fainter.
                RenderPart result = item;
                QMatrix4x4 offset;
                offset.translate(toQt(*front->resultOffset));
                result.model = offset * item.model;
                result.opacity = 0.3f;
                scene.inFront.push_back(std::move(result));
            }
            scene.inFront.push_back(std::move(item));
        }

        const Skeleton& skeleton = node.part->skeleton;
        auto posedJoint = [&](JointId id) {
            return posed.jointPositions[skeleton.indexOfJoint(id)];
        };
        const QVector3D boneColour = node.id == selection.part ? QVector3D(0.95f, 0.85f, 0.45f)
                                                               : QVector3D(0.75f, 0.72f, 0.55f);
        // The selected joint stands for the bone ending at it (what its
        // rotation turns, pose/Pose.h): drawn in the selection's orange.
        const std::optional<BoneId> selectedBone =
            node.id == selection.part && selection.joint != skeleton.root()
                ? boneForJoint(skeleton, selection.joint)
                : std::nullopt;
        for (const Bone& bone : skeleton.bones()) {
            const QVector3D colour =
                selectedBone == bone.id ? QVector3D(1.0f, 0.55f, 0.1f) : boneColour;
            scene.lines.add(toQt(node.placement.toWorld(posedJoint(bone.head))), colour);
            scene.lines.add(toQt(node.placement.toWorld(posedJoint(bone.tail))), colour);
        }
        // A disconnected bone's head and its parent's tail: a dashed line, as
        // Blender draws the relationship (Skeleton.h: attached chains).
        for (const auto& [joint, parent] : skeleton.attachments()) {
            if (parent == kNoBone || !skeleton.hasBone(parent))
                continue;
            const Vec3 from = node.placement.toWorld(posedJoint(joint));
            const Vec3 to = node.placement.toWorld(posedJoint(skeleton.bone(parent).tail));
            constexpr int kDashes = 8;
            for (int k = 0; k < kDashes; ++k) {
                const double a = static_cast<double>(2 * k) / (2 * kDashes - 1);
                const double b = static_cast<double>(2 * k + 1) / (2 * kDashes - 1);
                scene.lines.add(toQt(Vec3(from + a * (to - from))), QVector3D(0.5f, 0.5f, 0.5f));
                scene.lines.add(toQt(Vec3(from + b * (to - from))), QVector3D(0.5f, 0.5f, 0.5f));
            }
        }
        for (const Joint& joint : skeleton.joints()) {
            const bool selected = node.id == selection.part && joint.id == selection.joint;
            const bool pinned = node.pinnedJoints.count(joint.id) > 0;
            const QVector3D colour = selected ? QVector3D(1.0f, 0.55f, 0.1f)
                                     : pinned ? QVector3D(0.85f, 0.15f, 0.15f)
                                              : QVector3D(0.2f, 0.2f, 0.22f);
            scene.points.add(toQt(node.placement.toWorld(posedJoint(joint.id))), colour);
        }
    }
    for (const QVector3D& p : strokeOverlay_)
        scene.stroke.add(p, QVector3D(1.0f, 0.45f, 0.2f));
    if (problemMark_) {
        // A cross on the view plane, a fortieth of the view's height.
        const float size = static_cast<float>(camera_.halfHeightAtTarget() / 20.0);
        const QVector3D red(1.0f, 0.15f, 0.15f);
        for (const QVector3D& d :
             {camera_.right() + camera_.up(), camera_.right() - camera_.up()}) {
            scene.lines.add(*problemMark_ - size * d, red);
            scene.lines.add(*problemMark_ + size * d, red);
        }
    }
    addInspectionMarks(scene);
    if (tool_)
        tool_->addOverlay(*this, scene.lines);
    return scene;
}

void Viewport::mousePressEvent(QMouseEvent* event) {
    lastMouse_ = event->position();
    navigation_ = navigationFor(mouseBindings_, event->button(), event->modifiers());
    if (navigation_ != Navigation::None) {
        navigationButton_ = event->button();
        return;
    }
    if (event->button() == Qt::LeftButton && tool_)
        runTool(*this, tool_, [&] { tool_->press(*this, event); });
}

void Viewport::mouseMoveEvent(QMouseEvent* event) {
    const QPointF delta = event->position() - lastMouse_;
    lastMouse_ = event->position();
    if (navigation_ != Navigation::None) {
        switch (navigationDuring(mouseBindings_, navigation_, event->modifiers())) {
            case Navigation::Pan:
                camera_.pan(delta, QSizeF(size()));
                break;
            case Navigation::Zoom:
                // Right or up zooms in; 60 pixels of drag are one wheel step.
                camera_.dolly((delta.x() - delta.y()) / 60.0);
                break;
            default:
                camera_.orbit(delta);
                leaveAutoOrthographic();
        }
        update();
        return;
    }
    if (!(event->buttons() & Qt::LeftButton) && weightView_ != WeightView::Off) {
        const QString weights = weightsAt(event->position());
        if (!weights.isEmpty())
            emit statusMessage(weights);
    }
    if (!tool_)
        return;
    if (event->buttons() & Qt::LeftButton)
        runTool(*this, tool_, [&] { tool_->move(*this, event); });
    else
        runTool(*this, tool_, [&] { tool_->hover(*this, event); });
}

void Viewport::mouseReleaseEvent(QMouseEvent* event) {
    if (navigation_ != Navigation::None && event->button() == navigationButton_) {
        navigation_ = Navigation::None;
        return;
    }
    if (event->button() == Qt::LeftButton && tool_)
        runTool(*this, tool_, [&] { tool_->release(*this, event); });
}

void Viewport::wheelEvent(QWheelEvent* event) {
    bool used = false;
    if (tool_)
        runTool(*this, tool_, [&] { used = tool_->wheel(*this, event); });
    if (used)
        return;
    camera_.dolly(event->angleDelta().y() / 120.0);
    update();
}

void Viewport::setWeightView(WeightView view) {
    if (view == weightView_)
        return;
    weightView_ = view;
    // The pinned vertex belongs to the weight views: it goes with them.
    if (view == WeightView::Off && inspected_)
        setInspectedVertex(std::nullopt);
    update();
    emit weightViewChanged(view);
}

void Viewport::contextMenuEvent(QContextMenuEvent* event) {
    // Alt + right drag zooms with Maya's bindings: no menu then.
    if (mouseBindings_ == MouseBindings::Maya && (event->modifiers() & Qt::AltModifier))
        return;
    if (!showBoneMenu(*this, event->pos(), event->globalPos()))
        QOpenGLWidget::contextMenuEvent(event);
}

bool Viewport::event(QEvent* event) {
    // The numpad's viewpoint keys belong to the view while it has the focus
    // (without Num Lock they are Home, End and the arrows, other actions'
    // shortcuts).
    if (event->type() == QEvent::ShortcutOverride &&
        isViewpointKey(*static_cast<QKeyEvent*>(event))) {
        event->accept();
        return true;
    }
    return QOpenGLWidget::event(event);
}

void Viewport::keyPressEvent(QKeyEvent* event) {
    if (handleViewpointKey(*this, *event)) {
        return;
    } else if (event->key() == Qt::Key_Home) {
        frameAll();
    } else if (event->key() == Qt::Key_Period && (event->modifiers() & Qt::KeypadModifier)) {
        frameSelected();
    } else if (event->key() == Qt::Key_K) {
        // Skeleton refinement (3.3) on the bone under the cursor.
        const QPointF cursor = mapFromGlobal(QCursor::pos());
        const bool done = (event->modifiers() & Qt::ShiftModifier) ? deleteBoneUnder(*this, cursor)
                                                                   : splitBoneUnder(*this, cursor);
        if (!done)
            emit statusMessage(tr("Point at a bone: K splits it there, Shift+K deletes it"));
    } else if (event->key() == Qt::Key_Escape && tool_) {
        // Esc cuts the tool's drag short: what it previewed is put back.
        runTool(*this, tool_, [&] { tool_->cancel(*this); });
        update();
    } else {
        QOpenGLWidget::keyPressEvent(event);
    }
}

}  // namespace rigmesh::widgets
