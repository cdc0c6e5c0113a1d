#include "dialogs/ExportDialog.h"

#include <QCheckBox>
#include <QComboBox>
#include <QDialogButtonBox>
#include <QFileDialog>
#include <QFileInfo>
#include <QFormLayout>
#include <QHBoxLayout>
#include <QLabel>
#include <QLineEdit>
#include <QPushButton>
#include <QSettings>
#include <QSpinBox>
#include <QStandardItemModel>

namespace rigmesh::widgets {
namespace {

struct Format {
    const char* suffix;
    const char* label;
};
// Labels translated in ExportDialog's context.
constexpr Format kFormats[] = {
    {"glb", QT_TRANSLATE_NOOP("rigmesh::widgets::ExportDialog", "glTF 2.0 binary (.glb)")},
    {"gltf", QT_TRANSLATE_NOOP("rigmesh::widgets::ExportDialog", "glTF 2.0 (.gltf + .bin)")},
    {"fbx", QT_TRANSLATE_NOOP("rigmesh::widgets::ExportDialog", "FBX binary (.fbx)")},
    {"dae", QT_TRANSLATE_NOOP("rigmesh::widgets::ExportDialog", "COLLADA (.dae)")},
    {"obj",
     QT_TRANSLATE_NOOP("rigmesh::widgets::ExportDialog", "Wavefront OBJ, static mesh (.obj)")}};

// The last choice of "Add leaf bones", kept in QSettings; on unless unticked
// (docs/EXCHANGE.md, "Leaf bones in Blender").
const QString kLeafBonesKey = QStringLiteral("export/leafBones");

}  // namespace

ExportDialog::ExportDialog(const QString& suggestedPath, SkinningMethod viewSkinning,
                           QWidget* parent)
    : QDialog(parent), viewSkinning_(viewSkinning) {
    setWindowTitle(tr("Export"));
    path_ = new QLineEdit(suggestedPath, this);
    auto* browse = new QPushButton(tr("Browse..."), this);
    auto* pathRow = new QHBoxLayout;
    pathRow->addWidget(path_);
    pathRow->addWidget(browse);
    format_ = new QComboBox(this);
    for (const Format& f : kFormats)
        format_->addItem(tr(f.label), QString::fromLatin1(f.suffix));
    influences_ = new QSpinBox(this);
    influences_->setRange(0, 16);
    influences_->setValue(4);
    influences_->setSpecialValueText(tr("all the format allows"));
    influences_->setToolTip(
        tr("Bones per vertex; extra influences are cut and the rest renormalised"));
    pose_ = new QComboBox(this);
    pose_->addItem(tr("Rest pose"));
    pose_->addItem(tr("Current pose as the rest shape"));
    pose_->addItem(tr("Current pose as one key"));
    pose_->setToolTip(
        tr("As one key, the file keeps the rest shape and the skeleton opens "
           "in the current pose (an animation of a single key at 0 s)"));
    animation_ = new QCheckBox(tr("Animation (each part's keyed clip)"), this);
    animation_->setChecked(true);
    leafBones_ = new QCheckBox(tr("Add leaf bones (an end bone at each leaf's tail)"), this);
    leafBones_->setToolTip(
        tr("Like Blender's FBX option: importers then also know how long "
           "each leaf bone is (without, Blender gives a leaf its parent's length)"));
    leafBones_->setChecked(QSettings().value(kLeafBonesKey, true).toBool());
    subdivide_ = new QSpinBox(this);
    subdivide_->setRange(0, 4);
    subdivide_->setSpecialValueText(tr("none"));
    subdivide_->setToolTip(
        tr("Rounds of Loop subdivision: each makes four triangles of one; "
           "skin weights are carried"));
    decimate_ = new QSpinBox(this);
    decimate_->setRange(0, 10'000'000);
    decimate_->setSingleStep(500);
    decimate_->setSpecialValueText(tr("keep all"));
    decimate_->setSuffix(tr(" faces"));
    decimate_->setToolTip(
        tr("At most this many triangles per part (quadric error); every kept "
           "vertex keeps its weights"));
    skinningNote_ = new QLabel(this);
    skinningNote_->setWordWrap(true);
    auto* form = new QFormLayout(this);
    form->addRow(tr("File"), pathRow);
    form->addRow(tr("Format"), format_);
    form->addRow(tr("Influences"), influences_);
    form->addRow(tr("Subdivide"), subdivide_);
    form->addRow(tr("Decimate to"), decimate_);
    form->addRow(tr("Pose"), pose_);
    form->addRow(QString(), animation_);
    form->addRow(QString(), leafBones_);
    form->addRow(skinningNote_);
    auto* buttons = new QDialogButtonBox(QDialogButtonBox::Ok | QDialogButtonBox::Cancel, this);
    buttons->button(QDialogButtonBox::Ok)->setText(tr("Export"));
    form->addRow(buttons);
    connect(buttons, &QDialogButtonBox::accepted, this, &QDialog::accept);
    connect(this, &QDialog::accepted, this,
            [this] { QSettings().setValue(kLeafBonesKey, leafBones_->isChecked()); });
    connect(buttons, &QDialogButtonBox::rejected, this, &QDialog::reject);
    connect(browse, &QPushButton::clicked, this, &ExportDialog::browse);
    connect(format_, &QComboBox::currentIndexChanged, this, &ExportDialog::formatChanged);
    const int index = format_->findData(QFileInfo(suggestedPath).suffix().toLower());
    format_->setCurrentIndex(index >= 0 ? index : 0);
    formatChanged();
}

void ExportDialog::browse() {
    const QString path = QFileDialog::getSaveFileName(
        this, tr("Export to"), path_->text(),
        tr("%1 (*.%2)").arg(format_->currentText(), format_->currentData().toString()));
    if (!path.isEmpty())
        path_->setText(path);
}

void ExportDialog::formatChanged() {
    const QString suffix = format_->currentData().toString();
    // Keep the file's suffix in step with the chosen format.
    QFileInfo info(path_->text());
    if (!path_->text().isEmpty() && info.suffix().toLower() != suffix)
        path_->setText(info.path() + QLatin1Char('/') + info.completeBaseName() + QLatin1Char('.') +
                       suffix);
    const bool obj = suffix == QLatin1String("obj");
    // Every format can carry the current pose; as a key only the rigged ones.
    if (obj && pose_->currentIndex() == 2)
        pose_->setCurrentIndex(1);
    qobject_cast<QStandardItemModel*>(pose_->model())->item(2)->setEnabled(!obj);
    animation_->setEnabled(!obj);
    influences_->setEnabled(!obj);
    leafBones_->setEnabled(!obj);
    // An OBJ is the pose baked as the view skins it: nothing differs.
    QString note;
    if (viewSkinning_ == SkinningMethod::DualQuaternion && suffix == QLatin1String("fbx"))
        note =
            tr("The file records dual quaternion skinning (Maya uses it); Blender skins it "
               "linearly unless Preserve Volume is on.");
    else if (viewSkinning_ == SkinningMethod::DualQuaternion && !obj)
        note =
            tr("The view bends with dual quaternions; this format is skinned linearly, so "
               "bent joints look different elsewhere.");
    skinningNote_->setText(note);
    skinningNote_->setVisible(!note.isEmpty());
}

QString ExportDialog::path() const {
    return path_->text();
}

ExportOptions ExportDialog::options() const {
    ExportOptions options;
    options.maxInfluences = influences_->value();
    options.restPose = pose_->currentIndex() == 0;
    options.poseAsKey = pose_->currentIndex() == 2;
    options.animation = animation_->isChecked();
    options.leafBones = leafBones_->isChecked();
    options.subdivisionLevels = subdivide_->value();
    options.decimateToFaces = decimate_->value();
    options.skinning = viewSkinning_;
    return options;
}

}  // namespace rigmesh::widgets
