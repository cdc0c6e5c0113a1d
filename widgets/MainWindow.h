// The studio's main window: documents in tabs, one undo stack each joined by
// a QUndoGroup for the Edit menu, docks for the outliner, properties, skin
// weights, undo history, tool options and the timeline,
// File/Edit/View/Tools/Animation/Help menus with standard shortcuts, a
// toolbar, a status bar for hints and errors, and the window's layout kept
// in QSettings. It assembles: the tools live in a registry
// (tools/ToolRegistry), each feature in its controller (controllers/: files,
// exchange, rig, weights, pose), the panels and tools wire themselves; the window
// routes the active document to them and is their StudioHost.
#pragma once

#include <QMainWindow>
#include <QUndoGroup>
#include <memory>
#include <vector>

#include "controllers/StudioHost.h"
#include "model/PartNode.h"
#include "preferences/StudioPreferences.h"
#include "tools/ToolRegistry.h"

class QStackedWidget;
class QTabWidget;
class QUndoView;
class QMenu;
class QToolBar;

namespace rigmesh::model {
class Document;
}  // namespace rigmesh::model

namespace rigmesh::widgets {

class MouseHint;
enum class WeightView;  // viewport/RenderScene.h
class WeightViewChooser;

class DocumentView;
class ExchangeController;
class FilesController;
class JobRunner;
class JobStatus;
class OutlinerPanel;
class PoseController;
class PropertiesPanel;
class RigController;
class TimelineDock;
class ViewportTool;
class WeightsController;
class WeightsPanel;

class MainWindow : public QMainWindow, public StudioHost {
    Q_OBJECT
  public:
    // `recoveryDirectory`: where autosave writes; empty = the standard location.
    explicit MainWindow(const QString& recoveryDirectory = {}, QWidget* parent = nullptr);
    ~MainWindow() override;

    // ---- StudioHost ----
    model::Document* currentDocument() const override;
    DocumentView* currentView() const override;
    // Long work off the GUI thread (widgets/jobs) and what the window shows
    // of it.
    JobRunner* jobs() const override { return jobs_; }
    QWidget* dialogParent() override { return this; }
    void showStatus(const QString& message, int timeoutMs = 0) override;
    std::vector<DocumentView*> views() const override;
    // A new "Untitled N" document as the current tab.
    DocumentView* newDocument() override;
    // Adds a document as a new tab and makes it current.
    DocumentView* addDocument(std::unique_ptr<model::Document> document) override;
    void setCurrentView(DocumentView* view) override;
    void removeView(DocumentView* view) override;

    QTabWidget* tabs() const { return tabs_; }
    OutlinerPanel* outliner() const { return outliner_; }
    WeightsPanel* weightsPanel() const { return weights_; }
    JobStatus* jobStatus() const { return jobStatus_; }
    PropertiesPanel* propertiesPanel() const { return properties_; }
    TimelineDock* timeline() const { return timeline_; }
    // The viewport tools, each with its action (tools/ToolRegistry.h).
    ToolRegistry* tools() const { return tools_; }
    // The feature controllers (controllers/).
    FilesController* files() const { return files_; }
    ExchangeController* exchange() const { return exchange_; }
    RigController* rig() const { return rig_; }
    WeightsController* weightsController() const { return weightsController_; }
    PoseController* pose() const { return pose_; }
    // Activates the registered tool of type T (SketchTool, PoseTool, ...).
    template <typename T>
    void activateTool() {
        activateTool(tools_->template find<T>());
    }
    // Makes `tool` (one of tools()) the active tool of every view: its
    // action checked, its options shown, its hint in the status bar.
    void activateTool(ViewportTool* tool);

    // Puts every preference into effect at once (the language at the next
    // start) and keeps them in QSettings (MainWindowPreferences.cpp).
    void applyPreferences(const StudioPreferences& preferences);
    const StudioPreferences& preferences() const { return preferences_; }
    // Closes the document in tab `index`, asking about unsaved changes first.
    bool closeDocument(int index);

  protected:
    void closeEvent(QCloseEvent* event) override;

  private:
    void createActions();
    void createDocks();
    void createTimelineActions();
    // The tools, their actions in the Tools menu and toolbar, their options.
    void createTools(QMenu* menu, QToolBar* toolbar);
    void currentTabChanged(int index);
    void updateTitle();
    void deleteSelection();
    // Edit > Preferences.
    void openPreferences();

    QTabWidget* tabs_;
    QUndoGroup undoGroup_;
    OutlinerPanel* outliner_;
    PropertiesPanel* properties_;
    WeightsPanel* weights_;
    QUndoView* history_;
    TimelineDock* timeline_;
    ToolRegistry* tools_;
    QMenu* viewMenu_ = nullptr;
    WeightViewChooser* weightViews_ = nullptr;
    QAction* wireframeAction_ = nullptr;
    QAction* dqsAction_ = nullptr;
    QAction* gridAction_ = nullptr;
    MouseHint* mouseHint_ = nullptr;
    QStackedWidget* toolOptions_ = nullptr;
    StudioPreferences preferences_;
    JobRunner* jobs_ = nullptr;
    JobStatus* jobStatus_ = nullptr;
    FilesController* files_ = nullptr;
    RigController* rig_ = nullptr;
    ExchangeController* exchange_ = nullptr;
    WeightsController* weightsController_ = nullptr;
    PoseController* pose_ = nullptr;
};

}  // namespace rigmesh::widgets
