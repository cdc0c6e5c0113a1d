// The studio's main window: documents in tabs, one undo stack each joined by
// a QUndoGroup for the Edit menu, docks for the outliner, properties and undo
// history, File/Edit/View/Tools/Help menus with standard shortcuts, a
// toolbar, a status bar for hints and errors, settings and recent files kept
// in QSettings, and autosave with recovery. Panels and tools own their own
// wiring; the window only routes the active document to them.
#pragma once

#include <functional>

#include <QMainWindow>
#include <QUndoGroup>
#include <map>
#include <memory>
#include <utility>
#include <vector>
#include "io/SceneExport.h"
#include "model/PartNode.h"

#include "preferences/StudioPreferences.h"

class QStackedWidget;
class QTabWidget;
class QUndoView;
class QMenu;
class QActionGroup;
class QComboBox;

namespace rigmesh::model {
class Autosave;
class Document;
class ImportPartsCommand;
}  // namespace rigmesh::model

namespace rigmesh::widgets {

class MouseHint;
enum class WeightView;  // viewport/RenderScene.h

class DocumentView;
class OutlinerPanel;
class PropertiesPanel;
class JobRunner;
class JobStatus;
class WeightsPanel;
class CutTool;
class PaintTool;
class MergeTool;
class PoseTool;
class SelectTool;
class SketchTool;
class TimelineDock;

class MainWindow : public QMainWindow {
    Q_OBJECT
  public:
    // `recoveryDirectory`: where autosave writes; empty = the standard location.
    explicit MainWindow(const QString& recoveryDirectory = {}, QWidget* parent = nullptr);
    ~MainWindow() override;

    // Adds a document as a new tab and makes it current.
    DocumentView* addDocument(std::unique_ptr<model::Document> document);
    DocumentView* currentView() const;
    model::Document* currentDocument() const;
    QTabWidget* tabs() const { return tabs_; }
    OutlinerPanel* outliner() const { return outliner_; }
    WeightsPanel* weightsPanel() const { return weights_; }
    // Long work off the GUI thread (widgets/jobs) and what the window shows
    // of it.
    JobRunner* jobs() const { return jobs_; }
    // Asked before Recompute Weights replaces hand-painted weights (the
    // question in its argument); true goes on. A message box by default;
    // tests answer it.
    std::function<bool(const QString&)> confirmDiscardWeights;
    JobStatus* jobStatus() const { return jobStatus_; }
    PropertiesPanel* propertiesPanel() const { return properties_; }
    TimelineDock* timeline() const { return timeline_; }

    bool openFile(const QString& path);
    // Puts every preference into effect at once (the language at the next
    // start) and keeps them in QSettings (MainWindowPreferences.cpp).
    void applyPreferences(const StudioPreferences& preferences);
    const StudioPreferences& preferences() const { return preferences_; }
    // Offers to restore documents left in the recovery folder by a crash.
    void offerRecovery();

  public slots:
    void newDocument();
    void open();
    bool save();
    bool saveAs();
    void exportDocument();
    void importFile();
    // Imports `path` into the current document (File > Import without the
    // file dialog), as a background job.
    void importPath(const QString& path);
    // Exports the current document's visible parts to `path` (File > Export
    // without the dialog), as a background job.
    void exportTo(const QString& path, const ExportOptions& options);
    void saveHistoryAsRecipe();
    bool closeDocument(int index);
    void activateSelectTool();
    void activateSketchTool();
    void activatePoseTool();
    void activateMergeTool();
    void activateCutTool();
    void activatePaintTool();
    void resetPose();
    // Tools > Auto-Rig Part on the selected part (issue 17).
    void rigSelectedPart();
    void connectSelectedBone();
    void deleteSelection();
    // Edit > Preferences.
    void openPreferences();

  protected:
    void closeEvent(QCloseEvent* event) override;

  private:
    void createActions();
    void createDocks();
    void finishImport(model::Document& document, const QString& file,
                      std::unique_ptr<model::ImportPartsCommand> command);
    // Tools > Weights: the clean-ups, Smooth All, Recompute Weights and Check
    // Rig (MainWindowWeights.cpp).
    void createWeightMenu(QMenu* tools);
    // Bone heat over the selected part again, as a background job; asks
    // first if its weights were painted.
    void recomputeWeights();
    // Rigs the parts one after another, each a background job and one undo step.
    void rigParts(model::Document* document, std::vector<model::PartId> ids);
    // After an import: offers to rig the parts without a skeleton now.
    bool offerToRig(model::Document& document, const std::vector<model::PartId>& ids,
                    const QString& message);
    // The View > Weights choice and the Weight View toolbar follow the
    // current document's viewport (each document keeps its own view).
    void showWeightView(WeightView view);
    void createTimelineActions();
    void currentTabChanged(int index);
    class ViewportTool* activeTool() const;
    void activateTool(QAction* action, class ViewportTool* tool);
    // Every tool with its action, in toolbar order.
    std::vector<std::pair<QAction*, class ViewportTool*>> toolPairs() const;
    void updateTitle();
    bool saveDocument(DocumentView* view, const QString& path);
    bool maybeSave(DocumentView* view);
    void addRecentFile(const QString& path);
    void rebuildRecentMenu();
    void showStatus(const QString& message, int timeoutMs = 0);

    QTabWidget* tabs_;
    QUndoGroup undoGroup_;
    OutlinerPanel* outliner_;
    PropertiesPanel* properties_;
    WeightsPanel* weights_;
    QUndoView* history_;
    TimelineDock* timeline_;
    QMenu* recentMenu_ = nullptr;
    QMenu* viewMenu_ = nullptr;
    QActionGroup* toolGroup_ = nullptr;
    QAction* selectToolAction_ = nullptr;
    QAction* sketchToolAction_ = nullptr;
    QAction* poseToolAction_ = nullptr;
    QAction* mergeToolAction_ = nullptr;
    QActionGroup* weightViewGroup_ = nullptr;
    QComboBox* weightViewBox_ = nullptr;
    QAction* cutToolAction_ = nullptr;
    QAction* paintToolAction_ = nullptr;
    QAction* wireframeAction_ = nullptr;
    QAction* dqsAction_ = nullptr;
    QAction* gridAction_ = nullptr;
    SelectTool* selectTool_;
    SketchTool* sketchTool_;
    PoseTool* poseTool_;
    MergeTool* mergeTool_;
    CutTool* cutTool_;
    PaintTool* paintTool_;
    QString recoveryDirectory_;
    int untitledCount_ = 0;  // new documents are "Untitled 1", "Untitled 2", ...
    std::map<DocumentView*, model::Autosave*> autosaves_;
    MouseHint* mouseHint_ = nullptr;
    QStackedWidget* toolOptions_ = nullptr;
    StudioPreferences preferences_;
    JobRunner* jobs_ = nullptr;
    JobStatus* jobStatus_ = nullptr;
};

}  // namespace rigmesh::widgets
