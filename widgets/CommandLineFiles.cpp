#include "CommandLineFiles.h"

#include <QCoreApplication>
#include <QFileInfo>
#include <QMessageBox>

#include "MainWindow.h"
#include "controllers/ExchangeController.h"
#include "controllers/FilesController.h"
#include "model/DocumentFile.h"

namespace rigmesh::widgets {

void openFromCommandLine(MainWindow& window, const QString& path) {
    const QFileInfo file(path);
    if (!file.isFile() || !file.isReadable()) {
        // QCoreApplication::translate with its context written out: lupdate
        // files a tr() of a free function under the namespace, a context no
        // run-time lookup uses.
        const QString title =
            QCoreApplication::translate("rigmesh::widgets::CommandLineFiles", "Cannot open %1");
        const QString reason =
            file.exists() ? QCoreApplication::translate("rigmesh::widgets::CommandLineFiles",
                                                        "%1 is not a file this user may read.")
                          : QCoreApplication::translate("rigmesh::widgets::CommandLineFiles",
                                                        "%1 does not exist.");
        QMessageBox::warning(&window, title.arg(file.fileName()), reason.arg(path));
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
