// The Weights panel, after Blender's vertex group list and
// Vertex Weights panel: the selected part's bones with the vertices each
// leads and a lock box (an undoable SetBoneLockCommand; painting and the
// clean-ups keep a locked bone's weights); the weights of the pinned vertex
// (a click with a weight view on, or the paint tool's Ctrl + click); and
// Check Rig: unweighted vertices, bones that are no vertex's largest weight,
// vertices over N influences and sums off 1, each listed and selectable (a
// bone selects its joint, vertices are marked in the viewport and the
// clicked one pinned).
#pragma once

#include <QPointer>
#include <QWidget>

#include "model/Document.h"
#include "part/RigCheck.h"

class QLabel;
class QSpinBox;
class QTableWidget;
class QTreeWidget;
class QTreeWidgetItem;

namespace rigmesh::widgets {

class Viewport;

class WeightsPanel : public QWidget {
    Q_OBJECT
  public:
    explicit WeightsPanel(QWidget* parent = nullptr);
    // The active document and its viewport (nullptr = none).
    void setDocument(model::Document* document, Viewport* viewport);

    QTableWidget* bonesTable() const { return bones_; }
    QTableWidget* vertexTable() const { return vertex_; }
    QTreeWidget* checkResults() const { return check_; }

  public slots:
    // Runs Check Rig on the selected part and lists what it finds.
    void checkRig();

  signals:
    void statusMessage(const QString& message, int timeoutMs = 0);

  private:
    void refreshBones();
    void refreshVertex();
    void boneLockToggled(int row);
    void boneRowClicked(int row);
    void checkItemClicked(QTreeWidgetItem* item);
    const model::PartNode* selectedNode() const;

    QPointer<model::Document> document_;
    QPointer<Viewport> viewport_;
    QLabel* title_;
    QLabel* notes_;  // the weights' warnings (a bone that fell back), if any
    QTableWidget* bones_;
    QLabel* vertexTitle_;
    QTableWidget* vertex_;
    QSpinBox* maxInfluences_;
    QTreeWidget* check_;
    model::PartId checkedPart_ = model::kNoPart;
    bool refreshing_ = false;
};

}  // namespace rigmesh::widgets
