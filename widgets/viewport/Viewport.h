// The 3D view of a document: a QOpenGLWidget (GL 3.3 core) that draws the
// document's parts with GPU skinning, the ground grid and the skeleton
// overlay, navigates like Blender (middle drag orbits, Shift + middle drag
// pans, wheel zooms, Home frames all, numpad period frames the selection,
// numpad 1 3 7 5 look along axes and switch the projection,
// ViewpointActions.h) or, by preference, like Maya (Alt + left / middle /
// right drag, MouseBindings.h) and hands left-button input to the active
// tool. The camera moves only when asked: a document with parts is framed
// when first shown, nothing re-frames later (Home does).
#pragma once

#include <QOpenGLWidget>
#include <map>
#include <memory>
#include <optional>

#include "model/Document.h"
#include "pose/ForwardKinematics.h"
#include "viewport/MouseBindings.h"
#include "viewport/OrbitCamera.h"
#include "viewport/RenderScene.h"

namespace rigmesh::widgets {

class SceneRenderer;
// A bone under the mouse: its part and its two joints (head, tail).
struct BoneHit {
    model::PartId part = model::kNoPart;
    JointId from = kNoJoint, to = kNoJoint;
};

class ViewportTool;
class JobRunner;
class GlobalDifferences;

class Viewport : public QOpenGLWidget {
    Q_OBJECT
  public:
    explicit Viewport(model::Document* document, QWidget* parent = nullptr);
    // The context every viewport needs: OpenGL 3.3 core with a depth buffer.
    // Applications set it as the default before creating any window.
    static QSurfaceFormat requiredFormat();
    // Why no viewport can be shown on this platform (empty if one can): the
    // platform has no OpenGL (Qt's "offscreen" and "minimal" plugins) or no
    // context of requiredFormat() can be made. Needs a QGuiApplication.
    static QString unavailableReason();
    ~Viewport() override;

    model::Document* document() const { return document_; }
    OrbitCamera& camera() { return camera_; }
    const OrbitCamera& camera() const { return camera_; }
    void setTool(ViewportTool* tool);  // not owned; nullptr = navigation only
    // Where long work goes (widgets/jobs; not owned; the window's): tools
    // and the sketch hand it their engine calls. Null: run them here.
    void setJobRunner(JobRunner* runner) { jobs_ = runner; }
    JobRunner* jobRunner() const { return jobs_; }
    ViewportTool* tool() const { return tool_; }

    void setWireframe(bool on);
    void setDualQuaternionSkinning(bool on);
    void setGridVisible(bool on);
    void setWeightView(WeightView view);
    // Ghosts of each part's previous and next keyed poses.
    void setOnionSkin(bool on);
    bool onionSkin() const { return onionSkin_; }
    WeightView weightView() const { return weightView_; }
    // True while the Difference from Global Weights view waits for a part's
    // global solve (GlobalDifferences; tests wait on it).
    bool globalDifferencePending() const;
    bool wireframe() const { return wireframe_; }
    bool dualQuaternionSkinning() const { return dualQuaternion_; }
    void setMouseBindings(MouseBindings bindings) { mouseBindings_ = bindings; }
    MouseBindings mouseBindings() const { return mouseBindings_; }
    // A drag that orbits, pans or zooms the view is under way.
    bool navigating() const { return navigation_ != Navigation::None; }

    // The stroke being sketched, in world space (drawn as an overlay).
    void setStrokeOverlay(std::vector<QVector3D> points);
    // A red cross where something went wrong (a stroke crossing itself),
    // until the next stroke begins or the document changes.
    void setProblemMark(std::optional<QVector3D> at);
    const std::optional<QVector3D>& problemMark() const { return problemMark_; }

    // The world-space point under a pixel on the plane through the scene
    // centre facing the camera: where sketches are drawn.
    QVector3D sketchPlanePoint(const QPointF& pixel) const;
    // The point under a pixel on the plane through `through` facing the camera.
    QVector3D viewPlanePoint(const QPointF& pixel, const QVector3D& through) const;
    // The frame of that plane: origin, right (x) and up (y) axes.
    model::Placement sketchPlacement() const;
    QVector3D sceneCentre() const;

    // The joint drawn nearest to a pixel (within a few pixels), if any.
    std::optional<model::Selection> jointAt(const QPointF& pixel) const;
    // The bone drawn nearest to a pixel (within a few pixels of its segment on
    // screen), if any.
    std::optional<BoneHit> boneAt(const QPointF& pixel) const;
    // The visible part under a pixel, if any.
    std::optional<model::PartId> partAt(const QPointF& pixel) const;
    // The visible surface under a pixel: the part and the nearest corner of
    // the face hit (rest shape), if any.
    struct SurfaceHit {
        model::PartId part = model::kNoPart;
        int vertex = -1;
    };
    std::optional<SurfaceHit> surfaceAt(const QPointF& pixel) const;
    // "Vertex 12 of arm: bone 3 0.82, bone 2 0.18": the weights under a
    // pixel, for the status bar while a weight view is on.
    QString weightsAt(const QPointF& pixel) const;

    // Weight inspection: the vertex whose weights the
    // Weights panel shows (pinned by a click with a weight view on, or the
    // paint tool's Ctrl + click), and the vertices Check Rig selected; both
    // are drawn as marks where the posed surface has them.
    void setInspectedVertex(std::optional<SurfaceHit> vertex);
    const std::optional<SurfaceHit>& inspectedVertex() const { return inspected_; }
    void setMarkedVertices(model::PartId part, std::vector<int> vertices);
    const std::vector<int>& markedVertices() const { return marked_; }
    model::PartId markedPart() const { return markedPart_; }

    // World position of a joint of a part in its current placement and pose.
    QVector3D jointWorldPosition(model::PartId part, JointId joint) const;
    // The part's skeleton in its current pose (cached per part and pose).
    const PosedSkeleton& posedSkeleton(const model::PartNode& node) const;

    // Looks along an axis, orthographically unless the view was in
    // perspective by choice (Blender's Auto Perspective, ViewpointActions.h).
    void lookAlong(AxisView view);
    void setOrthographic(bool on);
    // Orbits by whole degrees (numpad 4 6 8 2).
    void orbitBy(double yawDegrees, double pitchDegrees);
    // The ground grid's line spacing: a power of ten set by the camera's
    // distance alone, so new parts never change it.
    double gridSpacing() const;
    // The floor grid's height (world y): set when the view is framed (first
    // shown, Home) and kept as parts come, go and move and as the view
    // zooms, as Blender's floor stays put.
    double floorHeight() const;

  public slots:
    void frameAll();
    void frameSelected();

  signals:
    // A tool's hint or a message for the status bar.
    void statusMessage(const QString& message);
    // setInspectedVertex() changed the pinned vertex.
    void inspectedVertexChanged();
    // setWeightView() changed how the surface is coloured.
    void weightViewChanged(rigmesh::widgets::WeightView view);
    // The viewpoint or projection changed by a key or menu.
    void viewChanged();

  protected:
    bool event(QEvent* event) override;
    void initializeGL() override;
    void paintGL() override;
    void mousePressEvent(QMouseEvent* event) override;
    void mouseMoveEvent(QMouseEvent* event) override;
    void mouseReleaseEvent(QMouseEvent* event) override;
    void wheelEvent(QWheelEvent* event) override;
    void keyPressEvent(QKeyEvent* event) override;
    void contextMenuEvent(QContextMenuEvent* event) override;

  private:
    RenderScene gatherScene() const;
    // The inspected and marked vertices, posed, as points (ViewportInspection.cpp).
    void addInspectionMarks(RenderScene& scene) const;
    void frameBox(const Eigen::AlignedBox3d& box);
    // Ends an orthographic view the camera chose itself once it is no longer
    // along an axis (ViewpointActions.cpp).
    void leaveAutoOrthographic();
    Eigen::AlignedBox3d sceneBox(bool selectedOnly) const;

    model::Document* document_;
    std::unique_ptr<SceneRenderer> renderer_;
    OrbitCamera camera_;
    ViewportTool* tool_ = nullptr;
    JobRunner* jobs_ = nullptr;
    std::vector<QVector3D> strokeOverlay_;
    std::optional<QVector3D> problemMark_;
    bool wireframe_ = false;
    bool dualQuaternion_ = true;
    bool gridVisible_ = true;
    bool onionSkin_ = false;
    WeightView weightView_ = WeightView::Off;
    GlobalDifferences* globalDifferences_ = nullptr;
    bool framedOnce_ = false;
    std::optional<double> floorHeight_;
    bool autoOrthographic_ = false;
    struct PosedCacheEntry {
        const Part* part = nullptr;
        Pose pose;
        PosedSkeleton posed;
    };
    mutable std::map<model::PartId, PosedCacheEntry> posedCache_;
    std::optional<SurfaceHit> inspected_;
    model::PartId markedPart_ = model::kNoPart;
    std::vector<int> marked_;
    QPointF lastMouse_;
    MouseBindings mouseBindings_ = MouseBindings::Blender;
    Navigation navigation_ = Navigation::None;  // of the drag under way
    Qt::MouseButton navigationButton_ = Qt::NoButton;
};

}  // namespace rigmesh::widgets
