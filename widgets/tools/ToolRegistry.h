// The studio's viewport tools in one place, after Krita's tool registry: each
// tool with its action (text, shortcut, icon, checkable in one exclusive
// group), in toolbar order. The window builds its Tools menu, toolbar and
// options dock from it and activates every tool through activate(); tools
// report through their one status signal (viewport/ViewportTool.h).
#pragma once

#include <QActionGroup>
#include <QKeySequence>
#include <QObject>
#include <QString>
#include <vector>

#include "preferences/StudioPreferences.h"
#include "viewport/ViewportTool.h"

class QAction;

namespace rigmesh::widgets {

class ToolRegistry : public QObject {
    Q_OBJECT
  public:
    explicit ToolRegistry(QObject* parent = nullptr);

    struct Entry {
        ViewportTool* tool = nullptr;
        QAction* action = nullptr;
        QString iconPath;
    };

    // Takes `tool` (parented to the registry) and makes its action; the
    // first tool added is active until another is.
    QAction* add(ViewportTool* tool, const QString& text, const QKeySequence& shortcut,
                 const QString& iconPath);
    const std::vector<Entry>& entries() const { return entries_; }
    ViewportTool* active() const;
    QAction* actionOf(const ViewportTool* tool) const;
    // Checks the tool's action and emits activated (also when it already is).
    void activate(ViewportTool* tool);
    // The actions' icons drawn for the light or dark theme.
    void setTheme(Theme theme);
    // The registered tool of type T, or nullptr.
    template <typename T>
    T* find() const {
        for (const Entry& entry : entries_)
            if (auto* tool = qobject_cast<T*>(entry.tool))
                return tool;
        return nullptr;
    }

  signals:
    void activated(rigmesh::widgets::ViewportTool* tool);

  private:
    QActionGroup group_;
    std::vector<Entry> entries_;
};

}  // namespace rigmesh::widgets
