// The File menu's documents: New, Open (and Open Recent), Save, Save As,
// asking before unsaved work goes, closing documents, an autosave per open
// document, and offering autosaved work back after a crash.
#pragma once

#include <QObject>
#include <QString>
#include <map>

class QMenu;

namespace rigmesh::model {
class Autosave;
struct RecoveryFile;
}  // namespace rigmesh::model

namespace rigmesh::widgets {

class DocumentView;
class StudioHost;

class FilesController : public QObject {
    Q_OBJECT
  public:
    // `recoveryDirectory`: where autosave writes.
    FilesController(StudioHost& host, QString recoveryDirectory, QObject* parent);

    // A new empty document, "Untitled 1", "Untitled 2", ...
    DocumentView* newDocument();
    // File > Open: a file dialog, then openFile.
    void open();
    // Opens `path` (or shows its tab if it is open already); false with a
    // message box when it cannot be read.
    bool openFile(const QString& path);
    bool save();
    bool saveAs();
    // Asks about unsaved changes, then closes the view; false if the user
    // kept it.
    bool close(DocumentView* view);
    // Closes every document (the window closing); false if one was kept.
    bool closeAll();
    // Offers to restore documents left in the recovery folder by a crash,
    // each named as it was.
    void offerRecovery();
    // The question offerRecovery() asks about `file`: its document's name
    // and when it was autosaved, in the studio's language.
    static QString recoveryQuestion(const model::RecoveryFile& file);

    // Autosaves `view`'s document from now on (MainWindow::addDocument).
    void watch(DocumentView* view);
    // Stops autosaving `view`'s document (its view goes).
    void unwatch(DocumentView* view);
    void setAutosaveDelay(int milliseconds);
    // File > Open Recent: filled from the settings, kept up to date.
    void setRecentMenu(QMenu* menu);

  private:
    bool saveDocument(DocumentView* view, const QString& path);
    bool maybeSave(DocumentView* view);
    void addRecentFile(const QString& path);
    void rebuildRecentMenu();

    StudioHost& host_;
    QString recoveryDirectory_;
    int untitledCount_ = 0;
    int autosaveDelay_ = 0;
    std::map<DocumentView*, model::Autosave*> autosaves_;
    QMenu* recentMenu_ = nullptr;
};

}  // namespace rigmesh::widgets
