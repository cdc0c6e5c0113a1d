// rigmesh-studio: the desktop application. Starts with the example document
// (or the documents named on the command line) and offers to recover work
// autosaved before a crash.
#include <QApplication>
#include <QCommandLineParser>
#include <QElapsedTimer>
#include <QMessageBox>
#include <QSurfaceFormat>

#include <QTimer>
#include <cstdio>

#include "CommandLineFiles.h"
#include "ExampleDocument.h"
#include "MainWindow.h"
#include "UserAction.h"
#include "base/AllocatorTuning.h"
#include "controllers/FilesController.h"
#include "jobs/JobRunner.h"
#include "preferences/StudioPreferences.h"
#include "preferences/Translations.h"
#include "viewport/Viewport.h"

int main(int argc, char** argv) {
    rigmesh::tuneAllocatorForEditing();
    // Every GL widget gets a 3.3 core context (Mesa llvmpipe provides 4.5).
    QSurfaceFormat::setDefaultFormat(rigmesh::widgets::Viewport::requiredFormat());

    QApplication app(argc, argv);
    QApplication::setApplicationName(QStringLiteral("RigMesh Studio"));
    QApplication::setOrganizationName(QStringLiteral("RigMesh"));
    QApplication::setApplicationVersion(QStringLiteral(RIGMESH_VERSION));
    // The desktop entry (packaging/rigmesh-studio.desktop) names the window's
    // icon and groups its windows.
    QGuiApplication::setDesktopFileName(QStringLiteral("rigmesh-studio"));
    // The language of Preferences (the system's by default), from the start
    // on, so that even --help speaks it.
    using namespace rigmesh::widgets;
    installTranslations(resolvedLanguage(StudioPreferences::load().language));

    QCommandLineParser parser;
    parser.setApplicationDescription(
        QCoreApplication::translate("rigmesh::studio", "Sketch a silhouette, get a rigged part."));
    parser.addHelpOption();
    parser.addVersionOption();
    parser.addPositionalArgument(
        QCoreApplication::translate("rigmesh::studio", "files"),
        QCoreApplication::translate(
            "rigmesh::studio",
            "RigMesh documents to open, or 3D files (glTF, FBX, OBJ, ...) to import"));
    QCommandLineOption screenshot(
        QStringLiteral("screenshot"),
        QCoreApplication::translate(
            "rigmesh::studio", "Save a picture of the window to FILE after start-up and quit."),
        QCoreApplication::translate("rigmesh::studio", "FILE"));
    parser.addOption(screenshot);
    parser.process(app);

    // Without OpenGL (e.g. QT_QPA_PLATFORM=offscreen) the 3D view cannot
    // exist: say so and stop, rather than crash on the first paint.
    if (const QString reason = rigmesh::widgets::Viewport::unavailableReason(); !reason.isEmpty()) {
        std::fprintf(stderr, "rigmesh-studio: %s\n", qPrintable(reason));
        return 1;
    }

    rigmesh::widgets::MainWindow window;
    const QStringList files = parser.positionalArguments();
    for (const QString& file : files)
        rigmesh::widgets::openFromCommandLine(window, file);
    if (files.isEmpty()) {
        const bool opened = rigmesh::widgets::runUserAction(
            {},
            [&](const QString& failure) {
                QMessageBox::warning(
                    &window, QCoreApplication::translate("rigmesh::studio", "RigMesh Studio"),
                    failure);
            },
            // Built on the worker thread: the window shows at once.
            [&] { rigmesh::studio::openExample(window); });
        if (!opened)
            window.newDocument();
    }
    window.show();
    if (parser.isSet(screenshot)) {
        // After start-up and the example's build, whichever ends later.
        auto* poll = new QTimer(&window);
        QElapsedTimer started;
        started.start();
        QObject::connect(poll, &QTimer::timeout, &window, [&, poll, started] {
            if (started.elapsed() < 1500 || rigmesh::widgets::JobRunner::anyBusy())
                return;
            poll->stop();
            window.grab().save(parser.value(screenshot));
            app.quit();
        });
        poll->start(100);
    } else {
        QTimer::singleShot(0, &window, [&] { window.files()->offerRecovery(); });
    }
    return app.exec();
}
