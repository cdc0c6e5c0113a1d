#include "CommandLineFiles.h"

#include <QCoreApplication>
#include <QFileInfo>
#include <QMessageBox>

#include "MainWindow.h"
#include "controllers/ExchangeController.h"
#include "controllers/FilesController.h"
#include "model/DocumentFile.h"

namespace rigmesh::widgets {
namespace {

QString tr(const char* text) {
    return QCoreApplication::translate("rigmesh::widgets::CommandLineFiles", text);
}

}  // namespace

void openFromCommandLine(MainWindow& window, const QString& path) {
    const QFileInfo file(path);
    if (!file.isFile() || !file.isReadable()) {
        QMessageBox::warning(&window, tr("Cannot open %1").arg(file.fileName()),
                             file.exists() ? tr("%1 is not a file this user may read.").arg(path)
                                           : tr("%1 does not exist.").arg(path));
        return;
    }
    if (file.suffix().compare(QLatin1String(model::DocumentFile::kSuffix), Qt::CaseInsensitive) ==
        0) {
        window.files()->openFile(path);
        return;
    }
    window.newDocument();
    window.exchange()->importPath(path);
}

}  // namespace rigmesh::widgets
