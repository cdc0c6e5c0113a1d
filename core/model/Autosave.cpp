#include "model/Autosave.h"

#include <QDir>
#include <QFile>
#include <QFileInfo>
#include <QSaveFile>
#include <QUuid>
#include <algorithm>

#include "model/DocumentFile.h"
#include "model/preview/LivePreviews.h"

namespace rigmesh::model {

Autosave::Autosave(Document* document, const QString& directory, QObject* parent)
    : QObject(parent), document_(document), directory_(directory) {
    const QString base = document->filePath().isEmpty()
                             ? QStringLiteral("untitled")
                             : QFileInfo(document->filePath()).completeBaseName();
    path_ =
        QDir(directory).filePath(QStringLiteral("%1-%2.%3")
                                     .arg(base, QUuid::createUuid().toString(QUuid::WithoutBraces),
                                          QString::fromLatin1(kSuffix)));
    timer_.setSingleShot(true);
    timer_.setInterval(kDefaultDelayMs);
    connect(&timer_, &QTimer::timeout, this, &Autosave::writeNow);
    connect(document->undoStack(), &QUndoStack::indexChanged, this, &Autosave::onIndexChanged);
    connect(document->undoStack(), &QUndoStack::cleanChanged, this, [this](bool clean) {
        if (clean)
            discard();
    });
    connect(document, &QObject::destroyed, this, [this] {
        document_ = nullptr;
        discard();
    });
}

Autosave::~Autosave() {
    discard();
}

void Autosave::setDelay(int milliseconds) {
    timer_.setInterval(std::max(0, milliseconds));
}

bool Autosave::hasRecoveryFile() const {
    return QFileInfo::exists(path_);
}

void Autosave::onIndexChanged() {
    if (document_ && document_->isModified())
        timer_.start();  // restarts: writes a delay after the last change
    else
        discard();
}

bool Autosave::writeNow() {
    timer_.stop();
    if (!document_ || !document_->isModified()) {
        discard();
        return true;
    }
    // A gesture is under way (preview/LivePreviews.h): the document holds
    // a state that is no undo step yet. Try again a delay later; its commit
    // restarts the delay anyway (onIndexChanged).
    if (hasLivePreview(*document_)) {
        timer_.start();
        return true;
    }
    if (!QDir().mkpath(directory_)) {
        emit failed(tr("Cannot create the recovery folder \"%1\".").arg(directory_));
        return false;
    }
    try {
        DocumentFile::write(*document_, path_);
    } catch (const DocumentFileError& e) {
        emit failed(QString::fromStdString(e.what()));
        return false;
    }
    // Its name and file, for the offer to recover it. The document itself
    // is recovered without them.
    QSaveFile name(namePathOf(path_));
    if (name.open(QIODevice::WriteOnly | QIODevice::Text)) {
        name.write((document_->displayName() + QLatin1Char('\n') + document_->filePath() +
                    QLatin1Char('\n'))
                       .toUtf8());
        name.commit();
    }
    emit written(path_);
    return true;
}

void Autosave::discard() {
    timer_.stop();
    if (QFileInfo::exists(path_))
        QFile::remove(path_);
    if (QFileInfo::exists(namePathOf(path_)))
        QFile::remove(namePathOf(path_));
}

QString Autosave::namePathOf(const QString& recoveryPath) {
    return recoveryPath + QStringLiteral(".name");
}

QList<RecoveryFile> Autosave::recoveryFiles(const QString& directory) {
    QList<RecoveryFile> files;
    const QFileInfoList entries = QDir(directory).entryInfoList(
        {QStringLiteral("*.") + QString::fromLatin1(kSuffix)}, QDir::Files, QDir::Time);
    for (const QFileInfo& entry : entries) {
        RecoveryFile file{entry.absoluteFilePath(), entry.lastModified(), {}, {}};
        QFile name(namePathOf(file.path));
        if (name.open(QIODevice::ReadOnly | QIODevice::Text)) {
            const QStringList lines = QString::fromUtf8(name.readAll()).split(QLatin1Char('\n'));
            file.name = lines.value(0);
            file.documentPath = lines.value(1);
        }
        if (file.name.isEmpty())
            file.name = entry.completeBaseName().section(QLatin1Char('-'), 0, 0);
        files.push_back(std::move(file));
    }
    return files;
}

}  // namespace rigmesh::model
