#include "ShortcutToolTips.h"

#include <QAction>
#include <QCoreApplication>
#include <QWidget>

namespace rigmesh::widgets {

void showShortcutsInToolTips(QWidget* window) {
    for (QAction* action : window->findChildren<QAction*>()) {
        const QKeySequence key = action->shortcut();
        if (key.isEmpty())
            continue;
        const QString keyText = key.toString(QKeySequence::NativeText);
        const QString tip = action->toolTip();
        // A tooltip that already ends naming its key keeps its words ("Sketch
        // Part" holds the letter S, but does not name the key).
        if (tip.endsWith(QStringLiteral("(%1)").arg(keyText)))
            continue;
        action->setToolTip(
            QCoreApplication::translate("rigmesh::widgets::ShortcutToolTips", "%1 (%2)")
                .arg(tip, keyText));
    }
}

}  // namespace rigmesh::widgets
