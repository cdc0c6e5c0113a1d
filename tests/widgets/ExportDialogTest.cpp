// File > Export says in one line when the file will bend otherwise than the
// view (View > Dual Quaternion Skinning), and the file gets the view's
// skinning where it can carry it. "Add leaf bones" is on unless the user
// unticked it at the last export (docs/EXCHANGE.md, "Leaf bones in Blender").
#include <gtest/gtest.h>

#include <QCheckBox>
#include <QComboBox>
#include <QLabel>
#include <QSettings>

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

QCheckBox* leafBonesBox(ExportDialog& dialog) {
    for (auto* box : dialog.findChildren<QCheckBox*>())
        if (box->text().contains(QStringLiteral("leaf bones")))
            return box;
    ADD_FAILURE() << "no leaf bones check box";
    return nullptr;
}

TEST(ExportDialogLeafBones, OnByDefaultAndTheAcceptedChoiceIsRemembered) {
    const QString key = QStringLiteral("export/leafBones");
    QSettings().remove(key);
    {
        ExportDialog dialog(QStringLiteral("/tmp/biped.glb"), SkinningMethod::LinearBlend);
        EXPECT_TRUE(leafBonesBox(dialog)->isChecked());
        EXPECT_TRUE(dialog.options().leafBones);
        leafBonesBox(dialog)->setChecked(false);
        EXPECT_FALSE(dialog.options().leafBones);
        dialog.accept();
    }
    {
        ExportDialog dialog(QStringLiteral("/tmp/biped.fbx"), SkinningMethod::LinearBlend);
        EXPECT_FALSE(dialog.options().leafBones);  // as last exported
        leafBonesBox(dialog)->setChecked(true);
        dialog.reject();  // a cancelled dialog changes nothing
    }
    {
        ExportDialog dialog(QStringLiteral("/tmp/biped.glb"), SkinningMethod::LinearBlend);
        EXPECT_FALSE(dialog.options().leafBones);
        leafBonesBox(dialog)->setChecked(true);
        dialog.accept();
    }
    ExportDialog dialog(QStringLiteral("/tmp/biped.glb"), SkinningMethod::LinearBlend);
    EXPECT_TRUE(dialog.options().leafBones);
    QSettings().remove(key);
}

}  // namespace
}  // namespace rigmesh::test
