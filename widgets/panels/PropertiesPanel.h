// The properties panel: figures of the selected part (vertices, faces,
// joints, bones, regions) and its build options; "Rebuild" rebuilds the part
// from its stroke with the edited options as one undoable command. With a
// joint selected, its pose rotation as XYZ Euler angles in degrees
// (Blender's default: X first, then Y, then Z, each about the parent's axes),
// editable: each edit is an undoable SetPoseCommand. A rebuild that would
// discard hand-painted weights asks first.
#pragma once

#include <QWidget>
#include <functional>

class QCheckBox;
class QDoubleSpinBox;
class QGroupBox;
class QLabel;
class QPushButton;

namespace rigmesh::model {
class Document;
}

namespace rigmesh::widgets {

class JobRunner;

class PropertiesPanel : public QWidget {
    Q_OBJECT
  public:
    explicit PropertiesPanel(QWidget* parent = nullptr);
    void setDocument(model::Document* document);
    // Where rebuilds run (widgets/jobs; the window's); null: on this thread.
    void setJobRunner(JobRunner* runner) { jobs_ = runner; }
    // Asks whether to go on with a rebuild that discards painted weights (a
    // Yes/Cancel message box; tests answer it themselves).
    std::function<bool(const QString& question)> confirmDiscard;

  signals:
    void statusMessage(const QString& message, int timeoutMs = 0);

  private:
    void refresh();
    void refreshPose();
    void rebuild();
    void setJointRotation();

    model::Document* document_ = nullptr;
    JobRunner* jobs_ = nullptr;
    QLabel* title_;
    QLabel* figures_;
    QDoubleSpinBox* edgeLength_;
    QCheckBox* smoothing_;
    QPushButton* rebuildButton_;
    QGroupBox* poseBox_;
    QDoubleSpinBox* euler_[3];
};

}  // namespace rigmesh::widgets
