// File > Export: choose where and as what (glTF binary or text, FBX,
// COLLADA, OBJ) and the options the formats offer: influences per vertex,
// subdivision and decimation, the pose (rest, the current pose as the rest
// shape, or the current pose as one key), whether to write the animation,
// and leaf bones (on unless unticked; the choice is remembered when the
// dialog is accepted).
// The file gets the view's skinning (View > Dual Quaternion Skinning) where
// the format can carry it: baked poses and FBX's skin deformers. One line
// says when what the file's importers show differs from the view: glTF and
// COLLADA are skinned linearly by every importer, and Blender skins an FBX
// linearly whatever it records (docs/EXCHANGE.md, "Skinning in Blender").
#pragma once

#include <QDialog>

#include "io/SceneExport.h"

class QCheckBox;
class QComboBox;
class QLabel;
class QLineEdit;
class QSpinBox;

namespace rigmesh::widgets {

class ExportDialog : public QDialog {
    Q_OBJECT
  public:
    // `viewSkinning`: how the studio's view deforms posed parts.
    ExportDialog(const QString& suggestedPath, SkinningMethod viewSkinning,
                 QWidget* parent = nullptr);
    QString path() const;
    ExportOptions options() const;
    // The line on skinning; hidden when the file bends as the view does.
    const QLabel* skinningNote() const { return skinningNote_; }

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
    QLabel* skinningNote_;
    SkinningMethod viewSkinning_;
};

}  // namespace rigmesh::widgets
