// Renders the application's SVG icon to the PNG sizes of the hicolor theme
// at build time, with Qt's own SVG renderer (the libqt6svg6 icon engine the
// studio already uses for its tool icons), so the PNGs never drift from
// the SVG.
//   rigmesh-render-icon ICON.svg OUTPUT_DIR SIZE...  -> OUTPUT_DIR/SIZE.png
#include <QDir>
#include <QGuiApplication>
#include <QIcon>
#include <QPixmap>
#include <cstdio>

int main(int argc, char** argv) {
    qputenv("QT_QPA_PLATFORM", "offscreen");
    QGuiApplication application(argc, argv);
    if (argc < 4) {
        std::fprintf(stderr, "usage: rigmesh-render-icon ICON.svg OUTPUT_DIR SIZE...\n");
        return 2;
    }
    const QIcon icon(QString::fromLocal8Bit(argv[1]));
    const QDir output(QString::fromLocal8Bit(argv[2]));
    if (!output.exists() && !QDir().mkpath(output.path())) {
        std::fprintf(stderr, "rigmesh-render-icon: cannot make %s\n", argv[2]);
        return 1;
    }
    for (int i = 3; i < argc; ++i) {
        const int size = QString::fromLocal8Bit(argv[i]).toInt();
        const QPixmap pixmap = icon.pixmap(size, size);
        if (size <= 0 || pixmap.isNull() || pixmap.width() != size ||
            !pixmap.save(output.filePath(QString::number(size) + QStringLiteral(".png")))) {
            std::fprintf(stderr, "rigmesh-render-icon: cannot render %s at %s px\n", argv[1],
                         argv[i]);
            return 1;
        }
    }
    return 0;
}
