// Edit > Preferences and putting each preference into effect.
#include <QAction>

#include "DocumentView.h"
#include "MainWindow.h"
#include "MouseHint.h"
#include "controllers/FilesController.h"
#include "dialogs/PreferencesDialog.h"
#include "preferences/Theme.h"
#include "viewport/Viewport.h"

namespace rigmesh::widgets {

void MainWindow::openPreferences() {
    PreferencesDialog dialog(preferences_, this);
    connect(&dialog, &PreferencesDialog::applied, this, &MainWindow::applyPreferences);
    dialog.exec();
}

void MainWindow::applyPreferences(const StudioPreferences& preferences) {
    const bool newLanguage = preferences.language != preferences_.language;
    preferences_ = preferences;
    preferences_.save();
    applyTheme(preferences_.theme);
    setStyleSheet(themeStyleSheet(preferences_.theme));
    tools_->setTheme(preferences_.theme);
    // The View menu's skinning follows at once; it applies to the current
    // view, and currentTabChanged() gives each other view the same.
    dqsAction_->setChecked(preferences_.dualQuaternionSkinning);
    files_->setAutosaveDelay(preferences_.autosaveSeconds * 1000);
    if (DocumentView* view = currentView()) {
        view->viewport()->setMouseBindings(preferences_.mouseBindings);
        view->setDefaultEdgeLength(preferences_.defaultEdgeLength);
    }
    mouseHint_->setMouseBindings(preferences_.mouseBindings);
    if (newLanguage && isVisible())
        showStatus(tr("The new language applies when RigMesh Studio starts again."), 8000);
}

}  // namespace rigmesh::widgets
