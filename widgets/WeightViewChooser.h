// The skin weight views a user picks, like Blender's weight paint display:
// View > Weights and a list on the Weight View toolbar, kept in step. The
// window passes the choice on to the current document's viewport and shows
// that viewport's own view when the document changes (each keeps its own).
#pragma once

#include <QObject>

class QActionGroup;
class QComboBox;
class QMainWindow;
class QMenu;

namespace rigmesh::widgets {

enum class WeightView;  // viewport/RenderScene.h

class WeightViewChooser : public QObject {
    Q_OBJECT
  public:
    // Adds the Weights submenu to `viewMenu` and the Weight View toolbar to `window`.
    WeightViewChooser(QMenu* viewMenu, QMainWindow* window);

    // Shows `view` as the current choice without emitting chosen().
    void show(WeightView view);
    // Picks `view` as the user would: shown, and chosen() emitted.
    void choose(WeightView view);

  signals:
    void chosen(rigmesh::widgets::WeightView view);

  private:
    QActionGroup* group_;
    QComboBox* box_;
};

}  // namespace rigmesh::widgets
