// File > Export says in one line when the file will bend otherwise than the
// view (View > Dual Quaternion Skinning), and the file gets the view's
// skinning where it can carry it.
#include <gtest/gtest.h>

#include <QComboBox>
#include <QLabel>

#include "dialogs/ExportDialog.h"

namespace rigmesh::test {
namespace {

using widgets::ExportDialog;

// The note's text for each format of the dialog's list ("" when hidden).
QString noteFor(ExportDialog& dialog, const char* suffix) {
    auto* format = dialog.findChild<QComboBox*>();
    const int index = format->findData(QString::fromLatin1(suffix));
    EXPECT_GE(index, 0) << suffix;
    format->setCurrentIndex(index);
    return dialog.skinningNote()->isHidden() ? QString() : dialog.skinningNote()->text();
}

TEST(ExportDialogSkinning, LinearBlendInTheViewNeedsNoNote) {
    ExportDialog dialog(QStringLiteral("/tmp/biped.glb"), SkinningMethod::LinearBlend);
    for (const char* suffix : {"glb", "gltf", "fbx", "dae", "obj"})
        EXPECT_TRUE(noteFor(dialog, suffix).isEmpty()) << suffix;
    EXPECT_EQ(dialog.options().skinning, SkinningMethod::LinearBlend);
}

TEST(ExportDialogSkinning, DualQuaternionsInTheViewAreNotedForLinearFormats) {
    ExportDialog dialog(QStringLiteral("/tmp/biped.glb"), SkinningMethod::DualQuaternion);
    for (const char* suffix : {"glb", "gltf", "dae"})
        EXPECT_TRUE(noteFor(dialog, suffix).contains(QStringLiteral("skinned linearly"))) << suffix;
    // FBX records the view's skinning; Blender still skins it linearly.
    EXPECT_TRUE(noteFor(dialog, "fbx").contains(QStringLiteral("Preserve Volume")));
    // An OBJ is the pose baked as the view shows it.
    EXPECT_TRUE(noteFor(dialog, "obj").isEmpty());
    EXPECT_EQ(dialog.options().skinning, SkinningMethod::DualQuaternion);
}

}  // namespace
}  // namespace rigmesh::test
