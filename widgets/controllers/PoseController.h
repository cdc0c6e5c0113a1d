// Pose actions on the selected part: Tools > Reset Pose (Alt+R) and
// Edit > Mirror Pose (Ctrl+Shift+V, Blender's Paste Pose Flipped): the pose
// seen in the part's left-right mirror (pose/PoseMirror), one undo step
// (keyed too with auto-key on, model/PoseChange).
#pragma once

#include <QObject>

class QMenu;

namespace rigmesh::widgets {

class StudioHost;

class PoseController : public QObject {
    Q_OBJECT
  public:
    PoseController(StudioHost& host, QObject* parent);

    // Edit > Mirror Pose and Tools > Reset Pose.
    void addMirrorAction(QMenu* edit);
    void addResetAction(QMenu* tools);
    void resetPose();
    void mirrorPose();

  private:
    StudioHost& host_;
};

}  // namespace rigmesh::widgets
