#include "preferences/Theme.h"

#include <QApplication>
#include <QImage>
#include <QPainter>
#include <QPixmap>
#include <QStyle>
#include <QStyleFactory>
#include <QWidget>

namespace rigmesh::widgets {

QPalette themePalette(Theme theme) {
    QStyle* fusion = QStyleFactory::create(QStringLiteral("Fusion"));
    QPalette palette = fusion->standardPalette();
    delete fusion;
    if (theme == Theme::Light)
        return palette;
    const QColor window(48, 48, 48), base(36, 36, 36), text(222, 222, 222);
    const QColor disabledText(128, 128, 128), highlight(71, 114, 179);
    palette.setColor(QPalette::Window, window);
    palette.setColor(QPalette::WindowText, text);
    palette.setColor(QPalette::Base, base);
    palette.setColor(QPalette::AlternateBase, QColor(42, 42, 42));
    palette.setColor(QPalette::ToolTipBase, QColor(24, 24, 24));
    palette.setColor(QPalette::ToolTipText, text);
    palette.setColor(QPalette::PlaceholderText, disabledText);
    palette.setColor(QPalette::Text, text);
    palette.setColor(QPalette::Button, QColor(60, 60, 60));
    palette.setColor(QPalette::ButtonText, text);
    palette.setColor(QPalette::BrightText, QColor(255, 80, 80));
    palette.setColor(QPalette::Light, QColor(80, 80, 80));
    palette.setColor(QPalette::Midlight, QColor(66, 66, 66));
    palette.setColor(QPalette::Mid, QColor(40, 40, 40));
    palette.setColor(QPalette::Dark, QColor(30, 30, 30));
    palette.setColor(QPalette::Shadow, QColor(16, 16, 16));
    palette.setColor(QPalette::Highlight, highlight);
    palette.setColor(QPalette::HighlightedText, Qt::white);
    palette.setColor(QPalette::Link, QColor(110, 160, 230));
    palette.setColor(QPalette::LinkVisited, QColor(160, 130, 220));
    for (QPalette::ColorRole role :
         {QPalette::WindowText, QPalette::Text, QPalette::ButtonText, QPalette::HighlightedText})
        palette.setColor(QPalette::Disabled, role, disabledText);
    palette.setColor(QPalette::Disabled, QPalette::Button, QColor(52, 52, 52));
    palette.setColor(QPalette::Disabled, QPalette::Highlight, QColor(80, 80, 80));
    return palette;
}

void applyTheme(Theme theme) {
    if (QApplication::style()->name().compare(QLatin1String("fusion"), Qt::CaseInsensitive) != 0)
        QApplication::setStyle(QStyleFactory::create(QStringLiteral("Fusion")));
    QApplication::setPalette(themePalette(theme));
    // Qt hands a new application palette to existing widgets only once the
    // event loop has run (QApplication::exec); before that (start-up,
    // tests) each window takes it here, and its children from it.
    for (QWidget* window : QApplication::topLevelWidgets())
        window->setPalette(QPalette());
    // A widget with a style sheet keeps the palette it was polished with.
    for (QWidget* widget : QApplication::allWidgets())
        if (!widget->styleSheet().isEmpty())
            widget->setStyleSheet(widget->styleSheet());
}

QIcon tintedIcon(const QIcon& icon, const QColor& colour) {
    QIcon tinted;
    for (int size : {16, 24, 32}) {
        QPixmap pixmap = icon.pixmap(size, size);
        if (pixmap.isNull())
            continue;
        QPainter painter(&pixmap);
        painter.setCompositionMode(QPainter::CompositionMode_SourceIn);
        painter.fillRect(pixmap.rect(), colour);
        painter.end();
        tinted.addPixmap(pixmap);
    }
    return tinted;
}

QString themeStyleSheet(Theme theme) {
    // Fusion draws a check box in a list or table with an outline a shade
    // darker than the window and fills it with the base colour: on the dark
    // palette both are near black and the box vanishes (the Skin Weights
    // panel's Lock column). Light outlines, and a light check mark
    // (resources/icons/check.svg) when checked: a box filled with the
    // highlight colour, as before, vanished on a selected row, whose
    // background is that colour (the Outliner's visibility box of the
    // selected part).
    return theme == Theme::Dark ? QStringLiteral(
                                      "QAbstractItemView::indicator { width: 12px; height: 12px; "
                                      "border: 1px solid #9a9a9a; border-radius: 2px; "
                                      "background: #2a2a2a; } "
                                      "QAbstractItemView::indicator:checked { "
                                      "image: url(:/icons/check.svg); border-color: #e0e0e0; }")
                                : QString();
}

QIcon themedIcon(const QString& path, Theme theme) {
    const QIcon icon(path);
    if (theme == Theme::Light)
        return icon;
    QIcon themed;
    for (int size : {16, 20, 24, 32, 48}) {
        QImage image = icon.pixmap(size, size).toImage().convertToFormat(QImage::Format_ARGB32);
        for (int y = 0; y < image.height(); ++y) {
            auto* line = reinterpret_cast<QRgb*>(image.scanLine(y));
            for (int x = 0; x < image.width(); ++x) {
                const QColor c = QColor::fromRgba(line[x]);
                // The icons' line colour is a dark grey (#3c3c3c): dark and
                // without colour becomes as light; colours stay.
                if (c.alpha() == 0 || c.hslSaturation() > 40 || c.lightness() > 110)
                    continue;
                const int light = 255 - c.lightness() / 2;
                line[x] = qRgba(light, light, light, c.alpha());
            }
        }
        themed.addPixmap(QPixmap::fromImage(image));
    }
    return themed;
}

}  // namespace rigmesh::widgets
