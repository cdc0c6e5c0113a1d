// Tools > Weights, Blender's Weights menu on the selected part: Normalize
// All, Clean, Limit Total and Smooth All, each one undoable command that
// keeps locked bones, Recompute Weights (bone heat again, as a background
// job, asking first when the weights were painted by hand), and Check Rig
// (the Skin Weights panel lists what it finds).
#pragma once

#include <QObject>
#include <functional>

class QMenu;

namespace rigmesh::widgets {

class StudioHost;
class WeightsPanel;

class WeightsController : public QObject {
    Q_OBJECT
  public:
    WeightsController(StudioHost& host, WeightsPanel* panel, QObject* parent);

    // Adds the Weights submenu to `tools`.
    void addMenu(QMenu* tools);
    // Bone heat over the selected part again, as a background job.
    void recomputeWeights();

    // Asked before Recompute Weights replaces hand-painted weights (the
    // question in its argument); true goes on. A message box by default;
    // tests answer it.
    std::function<bool(const QString&)> confirmDiscard;

  private:
    StudioHost& host_;
    WeightsPanel* panel_;
};

}  // namespace rigmesh::widgets
