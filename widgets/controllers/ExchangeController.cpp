#include "controllers/ExchangeController.h"

#include <QFileDialog>
#include <QFileInfo>
#include <QMessageBox>
#include <QPointer>
#include <memory>

#include "DocumentView.h"
#include "UserAction.h"
#include "base/Error.h"
#include "controllers/RigController.h"
#include "controllers/StudioHost.h"
#include "dialogs/ExportDialog.h"
#include "jobs/JobRunner.h"
#include "model/Document.h"
#include "model/DocumentExport.h"
#include "model/ErrorText.h"
#include "model/GuardedUndo.h"
#include "model/ImportReader.h"
#include "model/commands/ImportPartsCommand.h"
#include "model/recipe/RecipeFromHistory.h"
#include "viewport/Viewport.h"

namespace rigmesh::widgets {

ExchangeController::ExchangeController(StudioHost& host, RigController& rig,
                                       std::function<SkinningMethod()> skinning, QObject* parent)
    : QObject(parent), host_(host), rig_(rig), skinning_(std::move(skinning)) {}

void ExchangeController::importFile() {
    model::Document* document = host_.currentDocument();
    if (!document) {
        host_.newDocument();
        document = host_.currentDocument();
    }
    const QString path = QFileDialog::getOpenFileName(
        host_.dialogParent(), tr("Import"), QString(),
        tr("3D scenes (*.glb *.gltf *.fbx *.dae *.obj *.ply *.off *.stl);;All files (*)"));
    if (path.isEmpty())
        return;
    importPath(path);
}

void ExchangeController::importPath(const QString& path) {
    model::Document* current = host_.currentDocument();
    if (!current)
        return;
    // Read by a child process (model/ImportReader), waited for off the GUI
    // thread; the parts arrive as one command when it is done.
    QPointer<model::Document> document(current);
    const QString file = QFileInfo(path).fileName();
    host_.jobs()->run(
        tr("Importing %1").arg(file),
        [=, this]() -> JobRunner::Apply {
            std::vector<model::PartNode> nodes = model::readImportedParts(path);
            return [=, this]() mutable {
                if (!document)
                    return;
                runUserAction(
                    tr("Importing %1").arg(file),
                    [this](const QString& failure) {
                        QMessageBox::warning(host_.dialogParent(), tr("Cannot import"), failure);
                    },
                    [&] {
                        auto command = model::ImportPartsCommand::fromRead(*document, path, nodes);
                        finishImport(*document, file, std::move(command));
                    });
            };
        },
        [this](const QString& reason) {
            QMessageBox::warning(host_.dialogParent(), tr("Cannot import"), reason);
        },
        [this, file] { host_.showStatus(tr("Import of %1 cancelled").arg(file), 6000); });
}

void ExchangeController::finishImport(model::Document& document, const QString& file,
                                      std::unique_ptr<model::ImportPartsCommand> command) {
    const auto ids = command->partIds();
    model::pushCommand(document, std::move(command));
    if (!ids.empty())
        document.setSelection({ids.front(), kNoJoint});
    if (host_.currentView() && host_.currentView()->document() == &document)
        host_.currentView()->viewport()->frameAll();
    std::vector<model::PartId> unrigged;
    for (const model::PartId id : ids)
        if (document.part(id).part->skeleton.jointCount() == 0)
            unrigged.push_back(id);
    QString message =
        tr("Imported %n part(s) from %1", nullptr, static_cast<int>(ids.size())).arg(file);
    host_.showStatus(message, 8000);
    if (!unrigged.empty()) {
        // Say so rather than fail silently: the mesh is here, its rig is not yet.
        message += tr(": %n of them without a skeleton, so they cannot be posed yet.", nullptr,
                      static_cast<int>(unrigged.size()));
        rig_.offerToRig(document, unrigged, message);
    }
}

void ExchangeController::saveHistoryAsRecipe() {
    model::Document* document = host_.currentDocument();
    if (!document)
        return;
    const QString path = QFileDialog::getSaveFileName(
        host_.dialogParent(), tr("Save History as Recipe"), QStringLiteral("history.json"),
        tr("RigMesh recipes (*.json)"));
    if (path.isEmpty())
        return;
    runUserAction(
        tr("Save History as Recipe"),
        [this](const QString& failure) {
            QMessageBox::warning(host_.dialogParent(), tr("Cannot save the recipe"), failure);
        },
        [&] {
            model::saveHistoryAsRecipe(*document, path.toStdString());
            host_.showStatus(tr("Saved the history as %1: replay it with rigmesh run")
                                 .arg(QFileInfo(path).fileName()),
                             6000);
        });
}

void ExchangeController::exportDocument() {
    model::Document* document = host_.currentDocument();
    if (!document || document->partCount() == 0) {
        host_.showStatus(tr("Nothing to export: sketch a part first"), 4000);
        return;
    }
    QString suggested = document->filePath();
    suggested = suggested.isEmpty()
                    ? QStringLiteral("untitled.glb")
                    : QFileInfo(suggested).path() + QLatin1Char('/') +
                          QFileInfo(suggested).completeBaseName() + QStringLiteral(".glb");
    // The file's baked pose is the shape the view shows (View > Dual
    // Quaternion Skinning), and an FBX records that skinning.
    ExportDialog dialog(suggested, skinning_(), host_.dialogParent());
    if (dialog.exec() != QDialog::Accepted)
        return;
    exportTo(dialog.path(), dialog.options());
}

void ExchangeController::exportTo(const QString& path, const ExportOptions& options) {
    model::Document* document = host_.currentDocument();
    if (!document || document->partCount() == 0)
        return;
    const bool animation = options.animation;
    // Written off the GUI thread from a copy of the parts (their engine
    // values are shared, never copied): the document is not touched.
    const std::vector<model::PartNode> parts = document->parts();
    const QString file = QFileInfo(path).fileName();
    // Written beside the target off the GUI thread and renamed into place
    // when the job is applied (model::stageParts), so a cancelled export
    // leaves the old file, or none, behind.
    const QFileInfo target(path);
    host_.jobs()->run(
        tr("Exporting %1").arg(file),
        [=, this]() -> JobRunner::Apply {
            auto staged = std::make_shared<model::StagedDocumentExport>(
                model::stageParts(parts, path.toStdString(), options, true));
            return [=, this]() {
                const bool committed = runUserAction(
                    tr("Exporting %1").arg(file),
                    [&](const QString& failure) {
                        QMessageBox::warning(host_.dialogParent(), tr("Cannot export"),
                                             tr("%1 could not be replaced: %2").arg(file, failure));
                    },
                    [&] { staged->files.commit(); });
                if (!committed)
                    return;
                // Animation ticked but nothing keyed: say why the file has
                // no animation.
                QStringList warnings = staged->warnings;
                const bool rigged = target.suffix().toLower() != QLatin1String("obj");
                bool keyed = false;
                for (const model::PartNode& node : parts)
                    keyed = keyed || (node.visible && node.clip.keyCount() > 0);
                if (rigged && animation && !keyed)
                    warnings << tr("no animation: no visible part has keys");
                host_.showStatus(
                    tr("Exported %1%2")
                        .arg(file, warnings.isEmpty() ? QString()
                                                      : QStringLiteral(" (") +
                                                            warnings.join(QStringLiteral("; ")) +
                                                            QLatin1Char(')')),
                    8000);
            };
        },
        [this](const QString& reason) {
            QMessageBox::warning(host_.dialogParent(), tr("Cannot export"), reason);
        },
        [this, file] {
            host_.showStatus(tr("Export of %1 cancelled: nothing written").arg(file), 6000);
        });
}

}  // namespace rigmesh::widgets
