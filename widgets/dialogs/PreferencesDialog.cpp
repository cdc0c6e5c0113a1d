#include "dialogs/PreferencesDialog.h"

#include <QComboBox>
#include <QDialogButtonBox>
#include <QDoubleSpinBox>
#include <QFormLayout>
#include <QLabel>
#include <QPushButton>
#include <QSpinBox>
#include <QVBoxLayout>

#include "preferences/Translations.h"

namespace rigmesh::widgets {
namespace {

QLabel* note(QWidget* parent) {
    auto* label = new QLabel(parent);
    label->setWordWrap(true);
    QFont font = label->font();
    font.setPointSizeF(font.pointSizeF() * 0.9);
    label->setFont(font);
    label->setForegroundRole(QPalette::PlaceholderText);
    return label;
}

}  // namespace

PreferencesDialog::PreferencesDialog(const StudioPreferences& current, QWidget* parent)
    : QDialog(parent) {
    setWindowTitle(tr("Preferences"));
    setObjectName(QStringLiteral("PreferencesDialog"));

    language_ = new QComboBox(this);
    const QString system = resolvedLanguage(QString());
    QString systemName;
    for (const StudioLanguage& language : studioLanguages())
        if (language.code == system)
            systemName = language.nativeName;
    language_->addItem(tr("System default (%1)").arg(systemName), QString());
    for (const StudioLanguage& language : studioLanguages())
        language_->addItem(language.nativeName, language.code);
    languageNote_ = note(this);

    edgeLength_ = new QDoubleSpinBox(this);
    edgeLength_->setRange(0.0, StudioPreferences::kMaxDefaultEdgeLength);
    edgeLength_->setDecimals(3);
    edgeLength_->setSingleStep(0.01);
    edgeLength_->setSpecialValueText(tr("Automatic"));
    edgeLength_->setToolTip(
        tr("The target edge length of each new sketch; Automatic takes the document's (its first "
           "sketched part's), or for the first part one from the sketch's size"));

    skinning_ = new QComboBox(this);
    skinning_->addItem(tr("Dual quaternion"), true);
    skinning_->addItem(tr("Linear blend"), false);
    skinning_->setToolTip(tr("How the view deforms posed parts (View > Dual Quaternion Skinning)"));

    autosave_ = new QSpinBox(this);
    autosave_->setRange(StudioPreferences::kMinAutosaveSeconds,
                        StudioPreferences::kMaxAutosaveSeconds);
    autosave_->setSuffix(tr(" s"));
    autosave_->setToolTip(
        tr("Seconds from the last change until unsaved work is written to the recovery file"));

    mouse_ = new QComboBox(this);
    mouse_->addItem(tr("Blender"), static_cast<int>(MouseBindings::Blender));
    mouse_->addItem(tr("Maya"), static_cast<int>(MouseBindings::Maya));
    mouseNote_ = note(this);

    theme_ = new QComboBox(this);
    theme_->addItem(tr("Light"), static_cast<int>(Theme::Light));
    theme_->addItem(tr("Dark"), static_cast<int>(Theme::Dark));

    auto* form = new QFormLayout;
    form->addRow(tr("&Language:"), language_);
    form->addRow(QString(), languageNote_);
    form->addRow(tr("Default &edge length:"), edgeLength_);
    form->addRow(tr("&Skinning:"), skinning_);
    form->addRow(tr("&Autosave after:"), autosave_);
    form->addRow(tr("&Mouse bindings:"), mouse_);
    form->addRow(QString(), mouseNote_);
    form->addRow(tr("&Theme:"), theme_);

    auto* buttons =
        new QDialogButtonBox(QDialogButtonBox::Ok | QDialogButtonBox::Cancel |
                                 QDialogButtonBox::Apply | QDialogButtonBox::RestoreDefaults,
                             this);
    connect(buttons, &QDialogButtonBox::accepted, this, [this] {
        emit applied(preferences());
        accept();
    });
    connect(buttons, &QDialogButtonBox::rejected, this, &QDialog::reject);
    connect(buttons->button(QDialogButtonBox::Apply), &QPushButton::clicked, this,
            [this] { emit applied(preferences()); });
    connect(buttons->button(QDialogButtonBox::RestoreDefaults), &QPushButton::clicked, this,
            [this] { setPreferences(StudioPreferences{}); });
    connect(mouse_, &QComboBox::currentIndexChanged, this, &PreferencesDialog::updateNotes);

    auto* layout = new QVBoxLayout(this);
    layout->addLayout(form);
    layout->addStretch();
    layout->addWidget(buttons);
    setPreferences(current);
    setMinimumWidth(460);
}

StudioPreferences PreferencesDialog::preferences() const {
    StudioPreferences p;
    p.language = language_->currentData().toString();
    p.defaultEdgeLength = edgeLength_->value();
    p.dualQuaternionSkinning = skinning_->currentData().toBool();
    p.autosaveSeconds = autosave_->value();
    p.mouseBindings = static_cast<MouseBindings>(mouse_->currentData().toInt());
    p.theme = static_cast<Theme>(theme_->currentData().toInt());
    return p;
}

void PreferencesDialog::setPreferences(const StudioPreferences& p) {
    const int language = language_->findData(p.language);
    language_->setCurrentIndex(language < 0 ? 0 : language);
    edgeLength_->setValue(p.defaultEdgeLength);
    skinning_->setCurrentIndex(p.dualQuaternionSkinning ? 0 : 1);
    autosave_->setValue(p.autosaveSeconds);
    mouse_->setCurrentIndex(mouse_->findData(static_cast<int>(p.mouseBindings)));
    theme_->setCurrentIndex(theme_->findData(static_cast<int>(p.theme)));
    updateNotes();
}

void PreferencesDialog::updateNotes() {
    languageNote_->setText(tr("A new language applies when RigMesh Studio starts again."));
    const auto bindings = static_cast<MouseBindings>(mouse_->currentData().toInt());
    QString text = navigationHint(bindings);
    if (!text.isEmpty())
        text[0] = text[0].toUpper();  // the status bar's fragment as a sentence of its own
    if (bindings == MouseBindings::Maya)
        text += QStringLiteral("; ") +
                tr("Alt + drag is the view's, so the Pose tool reaches through the whole body "
                   "with its Tool Options box");
    mouseNote_->setText(text);
}

}  // namespace rigmesh::widgets
