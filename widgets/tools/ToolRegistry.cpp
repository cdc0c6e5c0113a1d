#include "tools/ToolRegistry.h"

#include <QAction>
#include <QIcon>

#include "preferences/Theme.h"

namespace rigmesh::widgets {

ToolRegistry::ToolRegistry(QObject* parent) : QObject(parent), group_(this) {}

QAction* ToolRegistry::add(ViewportTool* tool, const QString& text, const QKeySequence& shortcut,
                           const QString& iconPath) {
    tool->setParent(this);
    auto* action = new QAction(QIcon(iconPath), text, this);
    action->setShortcut(shortcut);
    action->setCheckable(true);
    action->setChecked(entries_.empty());
    group_.addAction(action);
    connect(action, &QAction::triggered, this, [this, tool] { activate(tool); });
    entries_.push_back({tool, action, iconPath});
    return action;
}

ViewportTool* ToolRegistry::active() const {
    for (const Entry& entry : entries_)
        if (entry.action->isChecked())
            return entry.tool;
    return entries_.empty() ? nullptr : entries_.front().tool;
}

QAction* ToolRegistry::actionOf(const ViewportTool* tool) const {
    for (const Entry& entry : entries_)
        if (entry.tool == tool)
            return entry.action;
    return nullptr;
}

void ToolRegistry::setTheme(Theme theme) {
    for (const Entry& entry : entries_)
        entry.action->setIcon(themedIcon(entry.iconPath, theme));
}

void ToolRegistry::activate(ViewportTool* tool) {
    for (const Entry& entry : entries_)
        if (entry.tool == tool) {
            entry.action->setChecked(true);
            emit activated(tool);
            return;
        }
}

}  // namespace rigmesh::widgets
