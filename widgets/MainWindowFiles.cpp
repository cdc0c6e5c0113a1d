// MainWindow: the File menu's documents: New, Open (and Open Recent), Save,
// Save As, asking before unsaved work goes, closing tabs and the window, and
// offering autosaved work back after a crash.
#include <QAction>
#include <QCloseEvent>
#include <QFile>
#include <QFileDialog>
#include <QFileInfo>
#include <QMenu>
#include <QMessageBox>
#include <QSettings>
#include <QTabWidget>

#include "DocumentView.h"
#include "MainWindow.h"
#include "base/Error.h"
#include "jobs/JobRunner.h"
#include "model/Autosave.h"
#include "model/DocumentFile.h"
#include "model/ErrorText.h"

namespace rigmesh::widgets {
namespace {

constexpr int kMaxRecentFiles = 8;
const char* kRecentKey = "recentFiles";

QString fileFilter() {
    return QObject::tr("RigMesh documents (*.%1)")
        .arg(QString::fromLatin1(model::DocumentFile::kSuffix));
}

}  // namespace

void MainWindow::newDocument() {
    auto document = std::make_unique<model::Document>();
    document->setUntitledName(tr("Untitled %1").arg(++untitledCount_));
    addDocument(std::move(document));
}

void MainWindow::open() {
    const QString path =
        QFileDialog::getOpenFileName(this, tr("Open Document"), QString(), fileFilter());
    if (!path.isEmpty())
        openFile(path);
}

bool MainWindow::openFile(const QString& path) {
    for (int i = 0; i < tabs_->count(); ++i) {
        auto* view = qobject_cast<DocumentView*>(tabs_->widget(i));
        if (view && QFileInfo(view->document()->filePath()) == QFileInfo(path)) {
            tabs_->setCurrentIndex(i);
            return true;
        }
    }
    try {
        addDocument(model::DocumentFile::load(path));
        addRecentFile(path);
        showStatus(tr("Opened %1").arg(QFileInfo(path).fileName()), 4000);
        return true;
    } catch (const rigmesh::Error& error) {
        QMessageBox::warning(this, tr("Cannot open document"), model::errorText(error));
        return false;
    }
}

bool MainWindow::saveDocument(DocumentView* view, const QString& path) {
    try {
        model::DocumentFile::save(*view->document(), path);
        autosaves_[view]->discard();
        addRecentFile(path);
        showStatus(tr("Saved %1").arg(QFileInfo(path).fileName()), 4000);
        return true;
    } catch (const rigmesh::Error& error) {
        QMessageBox::warning(this, tr("Cannot save document"), model::errorText(error));
        return false;
    }
}

bool MainWindow::save() {
    DocumentView* view = currentView();
    if (!view)
        return false;
    if (view->document()->filePath().isEmpty())
        return saveAs();
    return saveDocument(view, view->document()->filePath());
}

bool MainWindow::saveAs() {
    DocumentView* view = currentView();
    if (!view)
        return false;
    QString path = QFileDialog::getSaveFileName(this, tr("Save Document"),
                                                view->document()->filePath(), fileFilter());
    if (path.isEmpty())
        return false;
    const QString suffix = QStringLiteral(".") + QString::fromLatin1(model::DocumentFile::kSuffix);
    if (!path.endsWith(suffix))
        path += suffix;
    return saveDocument(view, path);
}

bool MainWindow::maybeSave(DocumentView* view) {
    if (!view->document()->isModified())
        return true;
    tabs_->setCurrentWidget(view);
    const auto answer = QMessageBox::warning(
        this, tr("Unsaved changes"),
        tr("%1 has unsaved changes. Save them?").arg(view->document()->displayName()),
        QMessageBox::Save | QMessageBox::Discard | QMessageBox::Cancel);
    if (answer == QMessageBox::Cancel)
        return false;
    if (answer == QMessageBox::Save)
        return save();
    return true;
}

bool MainWindow::closeDocument(int index) {
    auto* view = qobject_cast<DocumentView*>(tabs_->widget(index));
    if (!view || !maybeSave(view))
        return false;
    undoGroup_.removeStack(view->document()->undoStack());
    autosaves_.erase(view);  // the Autosave is a child of the view: it goes with it
    tabs_->removeTab(index);
    delete view;
    return true;
}

void MainWindow::closeEvent(QCloseEvent* event) {
    jobs_->cancel();  // a running job's result would have no document to go to
    while (tabs_->count() > 0) {
        if (!closeDocument(tabs_->count() - 1)) {
            event->ignore();
            return;
        }
    }
    QSettings settings;
    settings.setValue(QStringLiteral("window/geometry"), saveGeometry());
    settings.setValue(QStringLiteral("window/state"), saveState());
    event->accept();
}

void MainWindow::addRecentFile(const QString& path) {
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

void MainWindow::rebuildRecentMenu() {
    recentMenu_->clear();
    const QStringList files = QSettings().value(QString::fromLatin1(kRecentKey)).toStringList();
    for (const QString& path : files)
        connect(recentMenu_->addAction(QFileInfo(path).fileName()), &QAction::triggered, this,
                [this, path] { openFile(path); });
    recentMenu_->setEnabled(!files.isEmpty());
}

void MainWindow::offerRecovery() {
    const auto files = model::Autosave::recoveryFiles(recoveryDirectory_);
    for (const auto& file : files) {
        const auto answer = QMessageBox::question(
            this, tr("Recover unsaved work?"),
            tr("RigMesh Studio did not close properly. Restore the document autosaved at %1?")
                .arg(file.lastModified.toString()),
            QMessageBox::Yes | QMessageBox::Discard);
        if (answer == QMessageBox::Yes) {
            try {
                auto document =
                    std::make_unique<model::Document>(model::DocumentFile::read(file.path));
                // Recovered work is unsaved work: mark it modified so closing asks.
                document->undoStack()->resetClean();
                addDocument(std::move(document));
            } catch (const rigmesh::Error& error) {
                showStatus(tr("Could not recover: %1").arg(model::errorText(error)), 8000);
                continue;
            }
        }
        QFile::remove(file.path);
    }
}

}  // namespace rigmesh::widgets
