// A QApplication for the widget tests; settings and recovery files go to a
// scratch place so tests never touch a user's.
#include <gtest/gtest.h>

#include <QApplication>
#include <QStandardPaths>
#include <QSurfaceFormat>

#include "model/ImportReader.h"
#include "preferences/Translations.h"
#include "viewport/Viewport.h"

int main(int argc, char** argv) {
    QStandardPaths::setTestModeEnabled(true);
    QSurfaceFormat::setDefaultFormat(rigmesh::widgets::Viewport::requiredFormat());
    QApplication app(argc, argv);
    QApplication::setOrganizationName(QStringLiteral("RigMeshTests"));
    QApplication::setApplicationName(QStringLiteral("RigMesh Studio Tests"));
    // Imports are read by the built rigmesh in a child process.
    rigmesh::model::setImportWorkerProgram(QStringLiteral(RIGMESH_CLI));
    // The compiled translations of the build tree.
    rigmesh::widgets::setTranslationsDirectory(QStringLiteral(RIGMESH_QM_DIR));
    testing::InitGoogleTest(&argc, argv);
    return RUN_ALL_TESTS();
}
