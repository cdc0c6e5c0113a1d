#include "controllers/FilesController.h"

#include <QAction>
#include <QFile>
#include <QFileDialog>
#include <QFileInfo>
#include <QMenu>
#include <QMessageBox>
#include <QSettings>
#include <memory>

#include "DocumentView.h"
#include "UserAction.h"
#include "base/Error.h"
#include "controllers/StudioHost.h"
#include "model/Autosave.h"
#include "model/Document.h"
#include "model/DocumentFile.h"
#include "model/ErrorText.h"
#include "preferences/Translations.h"

namespace rigmesh::widgets {
namespace {

constexpr int kMaxRecentFiles = 8;
const char* kRecentKey = "recentFiles";

QString fileFilter() {
    return QObject::tr("RigMesh documents (*.%1)")
        .arg(QString::fromLatin1(model::DocumentFile::kSuffix));
}

}  // namespace

FilesController::FilesController(StudioHost& host, QString recoveryDirectory, QObject* parent)
    : QObject(parent), host_(host), recoveryDirectory_(std::move(recoveryDirectory)) {}

DocumentView* FilesController::newDocument() {
    auto document = std::make_unique<model::Document>();
    document->setUntitledName(tr("Untitled %1").arg(++untitledCount_));
    return host_.addDocument(std::move(document));
}

void FilesController::open() {
    const QString path = QFileDialog::getOpenFileName(host_.dialogParent(), tr("Open Document"),
                                                      QString(), fileFilter());
    if (!path.isEmpty())
        openFile(path);
}

bool FilesController::openFile(const QString& path) {
    for (DocumentView* view : host_.views())
        if (QFileInfo(view->document()->filePath()) == QFileInfo(path)) {
            host_.setCurrentView(view);
            return true;
        }
    return runUserAction(
        tr("Open Document"),
        [this](const QString& failure) {
            QMessageBox::warning(host_.dialogParent(), tr("Cannot open document"), failure);
        },
        [&] {
            host_.addDocument(model::DocumentFile::load(path));
            addRecentFile(path);
            host_.showStatus(tr("Opened %1").arg(QFileInfo(path).fileName()), 4000);
        });
}

bool FilesController::saveDocument(DocumentView* view, const QString& path) {
    return runUserAction(
        tr("Save Document"),
        [this](const QString& failure) {
            QMessageBox::warning(host_.dialogParent(), tr("Cannot save document"), failure);
        },
        [&] {
            model::DocumentFile::save(*view->document(), path);
            if (const auto it = autosaves_.find(view); it != autosaves_.end())
                it->second->discard();
            addRecentFile(path);
            host_.showStatus(tr("Saved %1").arg(QFileInfo(path).fileName()), 4000);
        });
}

bool FilesController::save() {
    DocumentView* view = host_.currentView();
    if (!view)
        return false;
    if (view->document()->filePath().isEmpty())
        return saveAs();
    return saveDocument(view, view->document()->filePath());
}

bool FilesController::saveAs() {
    DocumentView* view = host_.currentView();
    if (!view)
        return false;
    QString path = QFileDialog::getSaveFileName(host_.dialogParent(), tr("Save Document"),
                                                view->document()->filePath(), fileFilter());
    if (path.isEmpty())
        return false;
    const QString suffix = QStringLiteral(".") + QString::fromLatin1(model::DocumentFile::kSuffix);
    if (!path.endsWith(suffix))
        path += suffix;
    return saveDocument(view, path);
}

bool FilesController::maybeSave(DocumentView* view) {
    if (!view->document()->isModified())
        return true;
    host_.setCurrentView(view);
    const auto answer = QMessageBox::warning(
        host_.dialogParent(), tr("Unsaved changes"),
        tr("%1 has unsaved changes. Save them?").arg(view->document()->displayName()),
        QMessageBox::Save | QMessageBox::Discard | QMessageBox::Cancel);
    if (answer == QMessageBox::Cancel)
        return false;
    if (answer == QMessageBox::Save)
        return save();
    return true;
}

bool FilesController::close(DocumentView* view) {
    if (!view || !maybeSave(view))
        return false;
    unwatch(view);
    host_.removeView(view);
    return true;
}

bool FilesController::closeAll() {
    for (std::vector<DocumentView*> views = host_.views(); !views.empty(); views.pop_back())
        if (!close(views.back()))
            return false;
    return true;
}

void FilesController::watch(DocumentView* view) {
    // A child of the view: it goes with it.
    auto* autosave = new model::Autosave(view->document(), recoveryDirectory_, view);
    autosave->setDelay(autosaveDelay_);
    autosaves_[view] = autosave;
}

void FilesController::unwatch(DocumentView* view) {
    autosaves_.erase(view);
}

void FilesController::setAutosaveDelay(int milliseconds) {
    autosaveDelay_ = milliseconds;
    for (const auto& [view, autosave] : autosaves_)
        autosave->setDelay(milliseconds);
}

void FilesController::setRecentMenu(QMenu* menu) {
    recentMenu_ = menu;
    rebuildRecentMenu();
}

void FilesController::addRecentFile(const QString& path) {
    QSettings settings;
    QStringList files = settings.value(QString::fromLatin1(kRecentKey)).toStringList();
    const QString absolute = QFileInfo(path).absoluteFilePath();
    files.removeAll(absolute);
    files.prepend(absolute);
    while (files.size() > kMaxRecentFiles)
        files.removeLast();
    settings.setValue(QString::fromLatin1(kRecentKey), files);
    rebuildRecentMenu();
}

void FilesController::rebuildRecentMenu() {
    if (!recentMenu_)
        return;
    recentMenu_->clear();
    const QStringList files = QSettings().value(QString::fromLatin1(kRecentKey)).toStringList();
    for (const QString& path : files)
        connect(recentMenu_->addAction(QFileInfo(path).fileName()), &QAction::triggered, this,
                [this, path] { openFile(path); });
    recentMenu_->setEnabled(!files.isEmpty());
}

QString FilesController::recoveryQuestion(const model::RecoveryFile& file) {
    return tr("RigMesh Studio did not close properly. Restore \"%1\", autosaved %2?")
        .arg(file.name, studioLocale().toString(file.lastModified, QLocale::LongFormat));
}

void FilesController::offerRecovery() {
    const auto files = model::Autosave::recoveryFiles(recoveryDirectory_);
    for (const auto& file : files) {
        const auto answer =
            QMessageBox::question(host_.dialogParent(), tr("Recover unsaved work?"),
                                  recoveryQuestion(file), QMessageBox::Yes | QMessageBox::Discard);
        if (answer == QMessageBox::Yes) {
            const bool recovered = runUserAction(
                {},
                [this](const QString& failure) {
                    host_.showStatus(tr("Could not recover: %1").arg(failure), 8000);
                },
                [&] {
                    auto document =
                        std::make_unique<model::Document>(model::DocumentFile::read(file.path));
                    // Named as it was: its own file (Save writes there), or its
                    // title, marked recovered.
                    document->setFilePath(file.documentPath);
                    document->setUntitledName(tr("%1 (recovered)").arg(file.name));
                    // Recovered work is unsaved work: mark it modified so closing asks.
                    document->undoStack()->resetClean();
                    host_.addDocument(std::move(document));
                });
            if (!recovered)
                continue;
        }
        // Restored (it lives on in the open document) or discarded: the
        // recovery file and the name beside it go.
        QFile::remove(file.path);
        QFile::remove(model::Autosave::namePathOf(file.path));
    }
}

}  // namespace rigmesh::widgets
