// MainWindow's exchange actions: File > Import, File > Export and File >
// Save History as Recipe (the rest of the window is in MainWindow.cpp).
#include <QAction>
#include <QActionGroup>
#include <QApplication>
#include <QCloseEvent>
#include <QDir>
#include <QDockWidget>
#include <QFile>
#include <QFileDialog>
#include <QFileInfo>
#include <QMenuBar>
#include <QMessageBox>
#include <QPointer>
#include <QSettings>
#include <QStandardPaths>
#include <QStatusBar>
#include <QStyle>
#include <QTabWidget>
#include <QToolBar>
#include <QUndoView>
#include <filesystem>
#include <system_error>

#include "DocumentView.h"
#include "MainWindow.h"
#include "base/Error.h"
#include "dialogs/ExportDialog.h"
#include "jobs/JobRunner.h"
#include "model/Autosave.h"
#include "model/DocumentExport.h"
#include "model/DocumentFile.h"
#include "model/ErrorText.h"
#include "model/ImportReader.h"
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
    importPath(path);
}

void MainWindow::importPath(const QString& path) {
    model::Document* current = currentDocument();
    if (!current)
        return;
    // Read by a child process (model/ImportReader), waited for off the GUI
    // thread; the parts arrive as one command when it is done.
    QPointer<model::Document> document(current);
    const QString file = QFileInfo(path).fileName();
    jobs_->run(
        tr("Importing %1").arg(file),
        [=, this]() -> JobRunner::Apply {
            std::vector<model::PartNode> nodes = model::readImportedParts(path);
            return [=, this]() mutable {
                if (!document)
                    return;
                try {
                    auto command = model::ImportPartsCommand::fromRead(*document, path, nodes);
                    finishImport(*document, file, std::move(command));
                } catch (const rigmesh::Error& error) {
                    QMessageBox::warning(this, tr("Cannot import"), model::errorText(error));
                }
            };
        },
        [this](const QString& reason) { QMessageBox::warning(this, tr("Cannot import"), reason); },
        [this, file] { showStatus(tr("Import of %1 cancelled").arg(file), 6000); });
}

void MainWindow::finishImport(model::Document& document, const QString& file,
                              std::unique_ptr<model::ImportPartsCommand> command) {
    const auto ids = command->partIds();
    const int unrigged = command->unrigged();
    document.undoStack()->push(command.release());
    if (!ids.empty())
        document.setSelection({ids.front(), kNoJoint});
    if (currentView() && currentView()->document() == &document)
        currentView()->viewport()->frameAll();
    QString message =
        tr("Imported %n part(s) from %1", nullptr, static_cast<int>(ids.size())).arg(file);
    if (unrigged > 0) {
        // Say so rather than fail silently: the mesh is here, its rig is not.
        message += tr(": %1 of them without a skeleton. Rigging imported meshes is not available "
                      "yet, so they cannot be posed; you can move, save and export them as OBJ.")
                       .arg(unrigged);
        QMessageBox::information(this, tr("Imported without a rig"), message);
    }
    showStatus(message, 8000);
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
    // The file's baked pose is the shape the view shows (View > Dual
    // Quaternion Skinning).
    ExportOptions options = dialog.options();
    options.skinning =
        dqsAction_->isChecked() ? SkinningMethod::DualQuaternion : SkinningMethod::LinearBlend;
    exportTo(dialog.path(), options);
}

void MainWindow::exportTo(const QString& path, const ExportOptions& options) {
    model::Document* document = currentDocument();
    if (!document || document->partCount() == 0)
        return;
    const bool animation = options.animation;
    // Written off the GUI thread from a copy of the parts (their engine
    // values are shared, never copied): the document is not touched.
    const std::vector<model::PartNode> parts = document->parts();
    const QString file = QFileInfo(path).fileName();
    // Written into a hidden folder beside the target (with its companion
    // .bin or .mtl, which keep their relative names) and moved over it when
    // done, so a cancelled export leaves the old file, or none, behind.
    const QFileInfo target(path);
    const QString staging = target.dir().filePath(QStringLiteral(".") + target.fileName() +
                                                  QStringLiteral(".exporting"));
    QDir(staging).removeRecursively();
    if (!QDir().mkpath(staging)) {
        QMessageBox::warning(this, tr("Cannot export"),
                             tr("Cannot write into %1").arg(target.dir().path()));
        return;
    }
    auto discard = [staging] { QDir(staging).removeRecursively(); };
    jobs_->run(
        tr("Exporting %1").arg(file),
        [=, this]() -> JobRunner::Apply {
            model::DocumentExportResult result = model::exportParts(
                parts, QDir(staging).filePath(target.fileName()).toStdString(), options, true);
            return [=, this]() mutable {
                QString failure;
                for (const QFileInfo& written : QDir(staging).entryInfoList(QDir::Files)) {
                    std::error_code error;
                    std::filesystem::rename(written.filePath().toStdString(),
                                            target.dir().filePath(written.fileName()).toStdString(),
                                            error);
                    if (error)
                        failure = QString::fromStdString(error.message());
                }
                discard();
                if (!failure.isEmpty()) {
                    QMessageBox::warning(this, tr("Cannot export"),
                                         tr("%1 could not be replaced: %2").arg(file, failure));
                    return;
                }
                // Animation ticked but nothing keyed: say why the file has
                // no animation.
                const bool rigged = target.suffix().toLower() != QLatin1String("obj");
                bool keyed = false;
                for (const model::PartNode& node : parts)
                    keyed = keyed || (node.visible && node.clip.keyCount() > 0);
                if (rigged && animation && !keyed)
                    result.warnings << tr("no animation: no visible part has keys");
                showStatus(tr("Exported %1%2")
                               .arg(file, result.warnings.isEmpty()
                                              ? QString()
                                              : QStringLiteral(" (") +
                                                    result.warnings.join(QStringLiteral("; ")) +
                                                    QLatin1Char(')')),
                           8000);
            };
        },
        [this, discard](const QString& reason) {
            discard();
            QMessageBox::warning(this, tr("Cannot export"), reason);
        },
        [this, file] { showStatus(tr("Export of %1 cancelled: nothing written").arg(file), 6000); },
        discard);
}

}  // namespace rigmesh::widgets
