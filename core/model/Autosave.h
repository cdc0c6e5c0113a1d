// Autosave and crash recovery. While a document has unsaved changes, its
// contents are written to a recovery file in `directory` a few seconds after
// the last change, with its name and file beside it (a ".name" file: one
// line each), so a recovered document is named as it was. The file is removed when the document
// becomes clean again (saved, or undone back to the saved state) and when the Autosave is destroyed
// (the document was closed cleanly). Files found in the directory at start-up were left by a crash:
// recoveryFiles() lists them, and DocumentFile::read() opens them.
#pragma once

#include <QDateTime>
#include <QObject>
#include <QString>
#include <QStringList>
#include <QTimer>

#include "model/Document.h"

namespace rigmesh::model {

struct RecoveryFile {
    QString path;
    QDateTime lastModified;
    // The document's name when it was autosaved ("Untitled 2", its file's
    // name) and its file (empty if never saved).
    QString name;
    QString documentPath;
};

class Autosave : public QObject {
    Q_OBJECT
  public:
    static constexpr int kDefaultDelayMs = 3000;
    static constexpr const char* kSuffix = "rigmesh-recovery";

    // `directory` is created when first needed (in the app:
    // QStandardPaths::AppLocalDataLocation + "/recovery").
    Autosave(Document* document, const QString& directory, QObject* parent = nullptr);
    ~Autosave() override;

    void setDelay(int milliseconds);
    int delay() const { return timer_.interval(); }
    // Where this document's recovery file goes (unique per Autosave).
    QString recoveryFilePath() const { return path_; }
    bool hasRecoveryFile() const;

    // Writes now if the document is modified (else removes the file); while
    // a preview is shown (preview/LivePreviews.h) it writes a delay later
    // instead. Returns false and emits failed() if writing failed.
    bool writeNow();
    // Removes the recovery file and stops the pending write.
    void discard();

    // Recovery files left in `directory`, newest first.
    static QList<RecoveryFile> recoveryFiles(const QString& directory);
    // The file beside a recovery file that names its document.
    static QString namePathOf(const QString& recoveryPath);

  signals:
    void written(const QString& path);
    void failed(const QString& message);

  private:
    void onIndexChanged();

    Document* document_;
    QString directory_;
    QString path_;
    QTimer timer_;
};

}  // namespace rigmesh::model
