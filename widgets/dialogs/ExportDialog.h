// File > Export: choose where and as what (glTF binary or text, FBX,
// COLLADA, OBJ) and the options the formats offer: influences per vertex,
// the rest or the current pose (OBJ), and whether to write the animation.
#pragma once

#include <QDialog>

#include "io/SceneExport.h"

class QCheckBox;
class QComboBox;
class QLineEdit;
class QSpinBox;

namespace rigmesh::widgets {

class ExportDialog : public QDialog {
    Q_OBJECT
  public:
    explicit ExportDialog(const QString& suggestedPath, QWidget* parent = nullptr);
    QString path() const;
    ExportOptions options() const;

  private:
    void browse();
    void formatChanged();

    QLineEdit* path_;
    QComboBox* format_;
    QSpinBox* influences_;
    QComboBox* pose_;
    QCheckBox* animation_;
    QCheckBox* leafBones_;
    QSpinBox* subdivide_;
    QSpinBox* decimate_;
};

}  // namespace rigmesh::widgets
