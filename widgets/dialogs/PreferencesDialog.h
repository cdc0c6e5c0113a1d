// Edit > Preferences: the studio's settings (StudioPreferences). Apply and
// OK hand the chosen values to the window, which puts each into effect at
// once; only a new language waits for the next start, as the dialog says.
#pragma once

#include <QDialog>

#include "preferences/StudioPreferences.h"

class QComboBox;
class QDoubleSpinBox;
class QLabel;
class QSpinBox;

namespace rigmesh::widgets {

class PreferencesDialog : public QDialog {
    Q_OBJECT
  public:
    explicit PreferencesDialog(const StudioPreferences& current, QWidget* parent = nullptr);

    // The values the dialog shows.
    StudioPreferences preferences() const;
    void setPreferences(const StudioPreferences& preferences);

    // The controls, for tests.
    QComboBox* languageBox() const { return language_; }
    QDoubleSpinBox* edgeLengthBox() const { return edgeLength_; }
    QComboBox* skinningBox() const { return skinning_; }
    QSpinBox* autosaveBox() const { return autosave_; }
    QComboBox* mouseBox() const { return mouse_; }
    QComboBox* themeBox() const { return theme_; }

  signals:
    // Apply or OK with these values.
    void applied(const StudioPreferences& preferences);

  private:
    void updateNotes();

    QComboBox* language_;
    QLabel* languageNote_;
    QDoubleSpinBox* edgeLength_;
    QComboBox* skinning_;
    QSpinBox* autosave_;
    QComboBox* mouse_;
    QLabel* mouseNote_;
    QComboBox* theme_;
};

}  // namespace rigmesh::widgets
