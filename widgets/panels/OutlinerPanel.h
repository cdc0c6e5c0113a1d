// The outliner: the active document's parts, skeletons and joints as a tree.
// Selection is synced both ways with the document (and so the viewport);
// names are edited in place and part visibility toggled by the check boxes
// (both become undoable commands in the item model; one that fails is said
// in the status bar, the document unchanged); Delete removes the selected
// part.
#pragma once

#include <QWidget>
#include <memory>

class QTreeView;

namespace rigmesh::model {
class Document;
class SceneItemModel;
}  // namespace rigmesh::model

namespace rigmesh::widgets {

class OutlinerPanel : public QWidget {
    Q_OBJECT
  public:
    explicit OutlinerPanel(QWidget* parent = nullptr);
    ~OutlinerPanel() override;
    void setDocument(model::Document* document);  // nullptr = none
    QTreeView* view() const { return view_; }

  signals:
    // A rename or visibility change that failed (widgets/UserAction.h).
    void statusMessage(const QString& message, int timeoutMs = 0);

  private:
    void documentSelectionChanged();
    void viewSelectionChanged();

    QTreeView* view_;
    model::Document* document_ = nullptr;
    std::unique_ptr<model::SceneItemModel> model_;
    bool syncing_ = false;
};

}  // namespace rigmesh::widgets
