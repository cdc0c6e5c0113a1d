// MainWindow's exchange actions: File > Import, File > Export and File >
// Save History as Recipe (the rest of the window is in MainWindow.cpp).
#include <QAction>
#include <QActionGroup>
#include <QApplication>
#include <QCloseEvent>
#include <QDockWidget>
#include <QFileDialog>
#include <QFileInfo>
#include <QMenuBar>
#include <QMessageBox>
#include <QSettings>
#include <QStandardPaths>
#include <QStatusBar>
#include <QStyle>
#include <QTabWidget>
#include <QToolBar>
#include <QUndoView>
#include "DocumentView.h"
#include "MainWindow.h"
#include "base/Error.h"
#include "dialogs/ExportDialog.h"
#include "model/Autosave.h"
#include "model/DocumentExport.h"
#include "model/DocumentFile.h"
#include "model/ErrorText.h"
#include "model/commands/DeletePartCommand.h"
#include "model/commands/ImportPartsCommand.h"
#include "model/commands/ResetPoseCommand.h"
#include "model/recipe/RecipeFromHistory.h"
#include "panels/OutlinerPanel.h"
#include "panels/PropertiesPanel.h"
#include "tools/PoseTool.h"
#include "tools/SelectTool.h"
#include "tools/SketchTool.h"
#include "viewport/Viewport.h"

namespace rigmesh::widgets {

void MainWindow::importFile() {
    model::Document* document = currentDocument();
    if (!document) {
        newDocument();
        document = currentDocument();
    }
    const QString path = QFileDialog::getOpenFileName(
        this, tr("Import"), QString(),
        tr("3D scenes (*.glb *.gltf *.fbx *.dae *.obj *.ply *.off *.stl);;All files (*)"));
    if (path.isEmpty())
        return;
    try {
        // The file is read by a child process; the studio waits for it.
        QApplication::setOverrideCursor(Qt::WaitCursor);
        std::unique_ptr<model::ImportPartsCommand> command;
        try {
            command = model::ImportPartsCommand::create(*document, path);
        } catch (...) {
            QApplication::restoreOverrideCursor();
            throw;
        }
        QApplication::restoreOverrideCursor();
        const auto ids = command->partIds();
        const int unrigged = command->unrigged();
        document->undoStack()->push(command.release());
        if (!ids.empty())
            document->setSelection({ids.front(), kNoJoint});
        currentView()->viewport()->frameAll();
        QString message = tr("Imported %n part(s) from %1", nullptr, static_cast<int>(ids.size()))
                              .arg(QFileInfo(path).fileName());
        if (unrigged > 0) {
            // Say so rather than fail silently: the mesh is here, its rig is not.
            message +=
                tr(": %1 of them without a skeleton. Rigging imported meshes is not available "
                   "yet, so they cannot be posed; you can move, save and export them as OBJ.")
                    .arg(unrigged);
            QMessageBox::information(this, tr("Imported without a rig"), message);
        }
        showStatus(message, 8000);
    } catch (const rigmesh::Error& error) {
        QMessageBox::warning(this, tr("Cannot import"), model::errorText(error));
    }
}

void MainWindow::saveHistoryAsRecipe() {
    model::Document* document = currentDocument();
    if (!document)
        return;
    const QString path = QFileDialog::getSaveFileName(this, tr("Save History as Recipe"),
                                                      QStringLiteral("history.json"),
                                                      tr("RigMesh recipes (*.json)"));
    if (path.isEmpty())
        return;
    try {
        model::saveHistoryAsRecipe(*document, path.toStdString());
        showStatus(tr("Saved the history as %1: replay it with rigmesh run")
                       .arg(QFileInfo(path).fileName()),
                   6000);
    } catch (const rigmesh::Error& error) {
        QMessageBox::warning(this, tr("Cannot save the recipe"), model::errorText(error));
    }
}

void MainWindow::exportDocument() {
    model::Document* document = currentDocument();
    if (!document || document->partCount() == 0) {
        showStatus(tr("Nothing to export: sketch a part first"), 4000);
        return;
    }
    QString suggested = document->filePath();
    suggested = suggested.isEmpty()
                    ? QStringLiteral("untitled.glb")
                    : QFileInfo(suggested).path() + QLatin1Char('/') +
                          QFileInfo(suggested).completeBaseName() + QStringLiteral(".glb");
    ExportDialog dialog(suggested, this);
    if (dialog.exec() != QDialog::Accepted)
        return;
    try {
        // The file's baked pose is the shape the view shows (View > Dual
        // Quaternion Skinning).
        ExportOptions options = dialog.options();
        options.skinning =
            dqsAction_->isChecked() ? SkinningMethod::DualQuaternion : SkinningMethod::LinearBlend;
        auto result = model::exportDocument(*document, dialog.path().toStdString(), options, true);
        // Animation ticked but nothing keyed: say why the file has no animation.
        const bool rigged = QFileInfo(dialog.path()).suffix().toLower() != QLatin1String("obj");
        bool keyed = false;
        for (const model::PartNode& node : document->parts())
            keyed = keyed || (node.visible && node.clip.keyCount() > 0);
        if (rigged && dialog.options().animation && !keyed)
            result.warnings << tr("no animation: no visible part has keys");
        showStatus(
            tr("Exported %1%2")
                .arg(QFileInfo(dialog.path()).fileName(),
                     result.warnings.isEmpty()
                         ? QString()
                         : QStringLiteral(" (") + result.warnings.join(QStringLiteral("; ")) +
                               QLatin1Char(')')),
            8000);
    } catch (const rigmesh::Error& error) {
        QMessageBox::warning(this, tr("Cannot export"), model::errorText(error));
    }
}

}  // namespace rigmesh::widgets
