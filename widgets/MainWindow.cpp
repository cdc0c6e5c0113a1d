#include "MainWindow.h"

#include <QAction>
#include <QApplication>
#include <QCloseEvent>
#include <QDockWidget>
#include <QIcon>
#include <QLabel>
#include <QMenuBar>
#include <QMessageBox>
#include <QSettings>
#include <QStackedWidget>
#include <QStandardPaths>
#include <QStatusBar>
#include <QStyle>
#include <QTabWidget>
#include <QToolBar>
#include <QUndoView>
#include <tuple>

#include "DocumentView.h"
#include "GuardedUndoActions.h"
#include "HistoryView.h"
#include "MouseHint.h"
#include "ShortcutToolTips.h"
#include "UndoStatus.h"
#include "UserAction.h"
#include "WeightViewChooser.h"
#include "base/Error.h"
#include "controllers/ExchangeController.h"
#include "controllers/FilesController.h"
#include "controllers/PoseController.h"
#include "controllers/RigController.h"
#include "controllers/WeightsController.h"
#include "jobs/JobRunner.h"
#include "jobs/JobStatus.h"
#include "model/ErrorText.h"
#include "model/GuardedUndo.h"
#include "model/commands/DeletePartCommand.h"
#include "panels/OutlinerPanel.h"
#include "panels/PropertiesPanel.h"
#include "panels/WeightsPanel.h"
#include "timeline/TimelineDock.h"
#include "tools/CutTool.h"
#include "tools/MergeTool.h"
#include "tools/PaintTool.h"
#include "tools/PoseTool.h"
#include "tools/SelectTool.h"
#include "tools/SketchTool.h"
#include "viewport/ViewpointActions.h"
#include "viewport/Viewport.h"

// The tool icons are compiled into this static library: register them
// explicitly (Q_INIT_RESOURCE must be called outside any namespace).
static void registerIconResources() {
    Q_INIT_RESOURCE(icons);
}

namespace rigmesh::widgets {

namespace {

// A failure of a user action, shown in the window's status bar for 8 s.
ReportFailure statusReport(MainWindow& window) {
    return [&window](const QString& failure) { window.showStatus(failure, 8000); };
}

}  // namespace

MainWindow::MainWindow(const QString& recoveryDirectory, QWidget* parent)
    : QMainWindow(parent),
      tabs_(new QTabWidget(this)),
      outliner_(new OutlinerPanel(this)),
      properties_(new PropertiesPanel(this)),
      weights_(new WeightsPanel(this)),
      history_(new HistoryView(
          &undoGroup_, [this] { return currentDocument(); }, statusReport(*this), this)),
      timeline_(new TimelineDock(this)),
      tools_(new ToolRegistry(this)) {
    registerIconResources();
    setObjectName(QStringLiteral("RigMeshStudioMainWindow"));
    setWindowIcon(QIcon(QStringLiteral(":/icons/rigmesh-studio.svg")));
    tabs_->setTabsClosable(true);
    tabs_->setDocumentMode(true);
    setCentralWidget(tabs_);
    connect(tabs_, &QTabWidget::currentChanged, this, &MainWindow::currentTabChanged);
    connect(tabs_, &QTabWidget::tabCloseRequested, this, &MainWindow::closeDocument);
    connect(outliner_, &OutlinerPanel::statusMessage, this, &MainWindow::showStatus);
    connect(properties_, &PropertiesPanel::statusMessage, this, &MainWindow::showStatus);
    connect(weights_, &WeightsPanel::statusMessage, this, &MainWindow::showStatus);
    connect(timeline_, &TimelineDock::statusMessage, this, &MainWindow::showStatus);
    connect(timeline_, &TimelineDock::onionSkinToggled, this, [this](bool on) {
        if (auto* v = currentView())
            v->viewport()->setOnionSkin(on);
    });
    // Long work runs off the GUI thread, one job at a time.
    jobs_ = new JobRunner(this);
    jobStatus_ = new JobStatus(this, jobs_);
    // The features, each its own controller over this window (StudioHost).
    files_ = new FilesController(
        *this,
        recoveryDirectory.isEmpty()
            ? QStandardPaths::writableLocation(QStandardPaths::AppLocalDataLocation) +
                  QStringLiteral("/recovery")
            : recoveryDirectory,
        this);
    rig_ = new RigController(*this, this);
    exchange_ = new ExchangeController(
        *this, *rig_,
        [this] {
            return dqsAction_->isChecked() ? SkinningMethod::DualQuaternion
                                           : SkinningMethod::LinearBlend;
        },
        this);
    weightsController_ = new WeightsController(*this, weights_, this);
    pose_ = new PoseController(*this, this);
    properties_->setJobRunner(jobs_);
    mouseHint_ = new MouseHint(tabs_);
    createActions();
    createDocks();
    createTimelineActions();
    showShortcutsInToolTips(this);
    // An undo or redo says so in the status bar, in place of what the step
    // itself reported.
    new UndoStatus(
        undoGroup_, findChild<QAction*>(QStringLiteral("redoAction")), history_,
        [this](const QString& m) { showStatus(m, 4000); }, this);
    // Below this the docks crowd the view and each other.
    setMinimumSize(900, 600);
    applyPreferences(StudioPreferences::load());

    QSettings settings;
    restoreGeometry(settings.value(QStringLiteral("window/geometry")).toByteArray());
    restoreState(settings.value(QStringLiteral("window/state")).toByteArray());
    if (!settings.contains(QStringLiteral("window/geometry")))
        resize(1280, 800);
    updateTitle();
    mouseHint_->showOnFirstRun();
    showStatus(tr("Ready: S sketches a part, Q selects, P poses; %1")
                   .arg(navigationHint(preferences_.mouseBindings)));
}

MainWindow::~MainWindow() {
    // Close the views while the tab widget still exists: a document's
    // destruction emits signals this window listens to.
    while (tabs_->count() > 0) {
        auto* view = qobject_cast<DocumentView*>(tabs_->widget(0));
        tabs_->removeTab(0);
        if (!view)
            continue;
        disconnect(view->document(), nullptr, this, nullptr);
        undoGroup_.removeStack(view->document()->undoStack());
        files_->unwatch(view);
        delete view;
    }
}

void MainWindow::createActions() {
    QStyle* s = style();
    auto* file = menuBar()->addMenu(tr("&File"));
    auto* toolbar = addToolBar(tr("Main"));
    toolbar->setObjectName(QStringLiteral("mainToolBar"));

    auto add = [&](QMenu* menu, const QString& text, QKeySequence shortcut, auto slot,
                   QStyle::StandardPixmap icon = QStyle::SP_CustomBase) {
        QAction* action = menu->addAction(text);
        action->setShortcut(shortcut);
        if (icon != QStyle::SP_CustomBase)
            action->setIcon(s->standardIcon(icon));
        connect(action, &QAction::triggered, this, slot);
        return action;
    };
    toolbar->addAction(
        add(file, tr("&New"), QKeySequence::New, &MainWindow::newDocument, QStyle::SP_FileIcon));
    toolbar->addAction(add(
        file, tr("&Open..."), QKeySequence::Open, [this] { files_->open(); },
        QStyle::SP_DialogOpenButton));
    files_->setRecentMenu(file->addMenu(tr("Open &Recent")));
    toolbar->addAction(add(
        file, tr("&Save"), QKeySequence::Save, [this] { files_->save(); },
        QStyle::SP_DialogSaveButton));
    // Explicit: QKeySequence::SaveAs is empty on platforms without a desktop theme.
    add(file, tr("Save &As..."), QKeySequence(Qt::CTRL | Qt::SHIFT | Qt::Key_S),
        [this] { files_->saveAs(); });
    file->addSeparator();
    add(file, tr("&Import..."), QKeySequence(Qt::CTRL | Qt::Key_I),
        [this] { exchange_->importFile(); });
    add(file, tr("&Export..."), QKeySequence(Qt::CTRL | Qt::Key_E),
        [this] { exchange_->exportDocument(); });
    add(file, tr("Save History as &Recipe..."), QKeySequence(),
        [this] { exchange_->saveHistoryAsRecipe(); });
    file->addSeparator();
    add(file, tr("&Close"), QKeySequence::Close, [this] { closeDocument(tabs_->currentIndex()); });
    add(file, tr("&Quit"), QKeySequence::Quit, &QWidget::close);

    auto* edit = menuBar()->addMenu(tr("&Edit"));
    QAction* undo = undoGroup_.createUndoAction(this, tr("&Undo"));
    undo->setObjectName(QStringLiteral("undoAction"));
    undo->setShortcut(QKeySequence::Undo);
    undo->setIcon(s->standardIcon(QStyle::SP_ArrowBack));
    QAction* redo = undoGroup_.createRedoAction(this, tr("&Redo"));
    redo->setObjectName(QStringLiteral("redoAction"));
    guardUndoActions(
        undoGroup_, undo, tr("&Undo"), redo, tr("&Redo"), [this] { return currentDocument(); },
        statusReport(*this));
    // Ctrl+Shift+Z everywhere, plus the platform's own redo key (Ctrl+Y on
    // some); a key listed twice would make the shortcut ambiguous.
    QList<QKeySequence> redoKeys{QKeySequence(Qt::CTRL | Qt::SHIFT | Qt::Key_Z)};
    for (const QKeySequence& key : QKeySequence::keyBindings(QKeySequence::Redo))
        if (!redoKeys.contains(key))
            redoKeys.append(key);
    redo->setShortcuts(redoKeys);
    redo->setIcon(s->standardIcon(QStyle::SP_ArrowForward));
    edit->addAction(undo);
    edit->addAction(redo);
    toolbar->addSeparator();
    toolbar->addAction(undo);
    toolbar->addAction(redo);
    edit->addSeparator();
    add(edit, tr("&Delete Part"), QKeySequence::Delete, &MainWindow::deleteSelection,
        QStyle::SP_TrashIcon);
    add(edit, tr("Co&nnect Bone"), QKeySequence(), [this] { rig_->connectSelectedBone(); })
        ->setToolTip(tr("Move the selected bone's head onto its parent's tail, as Blender's "
                        "Connected does (cut and merge need connected bones)"));
    pose_->addMirrorAction(edit);
    edit->addSeparator();
    add(edit, tr("&Preferences..."), QKeySequence::Preferences, &MainWindow::openPreferences)
        ->setMenuRole(QAction::PreferencesRole);

    viewMenu_ = menuBar()->addMenu(tr("&View"));
    add(viewMenu_, tr("Frame &All"), QKeySequence(Qt::Key_Home), [this] {
        if (auto* v = currentView())
            v->viewport()->frameAll();
    });
    add(viewMenu_, tr("Frame &Selected"), QKeySequence(Qt::KeypadModifier | Qt::Key_Period),
        [this] {
            if (auto* v = currentView())
                v->viewport()->frameSelected();
        });
    addViewpointMenu(viewMenu_, [this]() -> Viewport* {
        auto* v = currentView();
        return v ? v->viewport() : nullptr;
    });
    viewMenu_->addSeparator();
    wireframeAction_ = viewMenu_->addAction(tr("&Wireframe"));
    wireframeAction_->setCheckable(true);
    wireframeAction_->setShortcut(QKeySequence(Qt::SHIFT | Qt::Key_W));
    connect(wireframeAction_, &QAction::toggled, this, [this](bool on) {
        if (auto* v = currentView())
            v->viewport()->setWireframe(on);
    });
    dqsAction_ = viewMenu_->addAction(tr("&Dual Quaternion Skinning"));
    dqsAction_->setCheckable(true);
    dqsAction_->setChecked(false);  // linear blend until the preferences say (applyPreferences)
    dqsAction_->setToolTip(tr("Off: linear blend skinning"));
    connect(dqsAction_, &QAction::toggled, this, [this](bool on) {
        if (auto* v = currentView())
            v->viewport()->setDualQuaternionSkinning(on);
    });
    weightViews_ = new WeightViewChooser(viewMenu_, this);
    connect(weightViews_, &WeightViewChooser::chosen, this, [this](WeightView view) {
        if (auto* v = currentView())
            v->viewport()->setWeightView(view);
        if (view == WeightView::SelectedBone)
            showStatus(tr("Weights of the selected joint's bone: blue 0, green 0.5, red 1, "
                          "dark blue none"),
                       6000);
    });
    gridAction_ = viewMenu_->addAction(tr("&Grid"));
    gridAction_->setCheckable(true);
    gridAction_->setChecked(true);
    connect(gridAction_, &QAction::toggled, this, [this](bool on) {
        if (auto* v = currentView())
            v->viewport()->setGridVisible(on);
    });
    viewMenu_->addSeparator();

    auto* tools = menuBar()->addMenu(tr("&Tools"));
    toolbar->addSeparator();
    createTools(tools, toolbar);
    tools->addSeparator();
    pose_->addResetAction(tools);
    QAction* rig =
        add(tools, tr("&Auto-Rig Part"), QKeySequence(), [this] { rig_->rigSelectedPart(); });
    rig->setObjectName(QStringLiteral("autoRigPart"));
    rig->setToolTip(
        tr("Give the selected part without a skeleton (an imported mesh) a skeleton "
           "from its shape and skin weights"));
    weightsController_->addMenu(tools);

    auto* help = menuBar()->addMenu(tr("&Help"));
    add(help, tr("&Mouse Gestures"), QKeySequence(), [this] {
        mouseHint_->show();
        mouseHint_->raise();
    });
    add(help, tr("&About RigMesh Studio"), QKeySequence(), [this] {
        QMessageBox::about(this, tr("About RigMesh Studio"),
                           tr("<b>RigMesh Studio</b><p>Sketch a silhouette, get a rigged part: "
                              "surface, skeleton and skin weights, after Borosán et al., "
                              "<i>RigMesh</i>, SIGGRAPH Asia 2012.</p><p>GPL-3.0-or-later.</p>"));
    });
}

void MainWindow::createDocks() {
    auto dock = [&](const QString& title, const char* name, QWidget* content,
                    Qt::DockWidgetArea area) {
        auto* widget = new QDockWidget(title, this);
        widget->setObjectName(QString::fromLatin1(name));
        widget->setWidget(content);
        addDockWidget(area, widget);
        viewMenu_->addAction(widget->toggleViewAction());
        return widget;
    };
    dock(tr("Outliner"), "outlinerDock", outliner_, Qt::RightDockWidgetArea);
    QDockWidget* propertiesDock =
        dock(tr("Properties"), "propertiesDock", properties_, Qt::RightDockWidgetArea);
    // A tab beside Properties (Blender's Properties editor has a tab per
    // data kind), so the view keeps its width.
    tabifyDockWidget(propertiesDock,
                     dock(tr("Skin Weights"), "weightsDock", weights_, Qt::RightDockWidgetArea));
    propertiesDock->raise();
    dock(tr("History"), "historyDock", history_, Qt::LeftDockWidgetArea);
    history_->setEmptyLabel(tr("<original>"));
    // The active tool's options (ViewportTool::optionsWidget), one page each.
    toolOptions_ = new QStackedWidget(this);
    auto* none = new QLabel(tr("This tool has no options."), toolOptions_);
    none->setAlignment(Qt::AlignTop | Qt::AlignLeft);
    none->setMargin(6);
    toolOptions_->addWidget(none);
    for (const ToolRegistry::Entry& entry : tools_->entries())
        if (QWidget* options = entry.tool->optionsWidget())
            toolOptions_->addWidget(options);
    dock(tr("Tool Options"), "toolOptionsDock", toolOptions_, Qt::LeftDockWidgetArea);
    // The timeline along the bottom, under the view, as in Blender.
    dock(tr("Timeline"), "timelineDock", timeline_, Qt::BottomDockWidgetArea);
}

// Transport and keying, window-wide as in Blender: a text field
// or spin box with the focus keeps its own keys (Qt's shortcut override).
void MainWindow::createTimelineActions() {
    auto* menu = new QMenu(tr("&Animation"), this);
    menuBar()->insertMenu(menuBar()->actions().last(), menu);  // before Help
    auto add = [&](const QString& text, const QKeySequence& key, auto slot) {
        QAction* action = menu->addAction(text);
        action->setShortcut(key);
        connect(action, &QAction::triggered, timeline_, slot);
        return action;
    };
    add(tr("&Play / Pause"), QKeySequence(Qt::Key_Space), &TimelineDock::togglePlayback);
    add(tr("Pre&vious Frame"), QKeySequence(Qt::Key_Left), [this] { timeline_->stepFrames(-1); });
    add(tr("&Next Frame"), QKeySequence(Qt::Key_Right), [this] { timeline_->stepFrames(1); });
    add(tr("Jump to &Start"), QKeySequence(Qt::SHIFT | Qt::Key_Left), &TimelineDock::jumpToStart);
    add(tr("Jump to &End"), QKeySequence(Qt::SHIFT | Qt::Key_Right), &TimelineDock::jumpToEnd);
    menu->addSeparator();
    add(tr("&Insert Key"), QKeySequence(Qt::Key_I), &TimelineDock::insertKey);
}

DocumentView* MainWindow::addDocument(std::unique_ptr<model::Document> document) {
    auto* view = new DocumentView(std::move(document), tabs_);
    model::Document* doc = view->document();
    undoGroup_.addStack(doc->undoStack());
    view->viewport()->setJobRunner(jobs_);
    connect(view, &DocumentView::statusMessage, this, &MainWindow::showStatus);
    connect(view->viewport(), &Viewport::statusMessage, this,
            [this](const QString& m) { showStatus(m); });
    connect(view->viewport(), &Viewport::weightViewChanged, this, [this, view](WeightView shown) {
        if (currentView() == view)
            weightViews_->show(shown);
    });
    auto refreshTab = [this, view] {
        const int index = tabs_->indexOf(view);
        if (index < 0)
            return;
        const model::Document* d = view->document();
        tabs_->setTabText(index,
                          d->displayName() + (d->isModified() ? QStringLiteral(" *") : QString()));
        tabs_->setTabToolTip(index, d->filePath());
        if (view == currentView())
            updateTitle();
    };
    // The first part a user makes shows they have the gestures.
    connect(doc, &model::Document::partInserted, mouseHint_, [this] {
        if (mouseHint_->isVisible())
            mouseHint_->dismiss();
    });
    connect(doc, &model::Document::modifiedChanged, this, refreshTab);
    connect(doc, &model::Document::filePathChanged, this, refreshTab);
    files_->watch(view);
    const int index = tabs_->addTab(view, doc->displayName());
    tabs_->setCurrentIndex(index);
    refreshTab();
    return view;
}

std::vector<DocumentView*> MainWindow::views() const {
    std::vector<DocumentView*> views;
    for (int i = 0; i < tabs_->count(); ++i)
        if (auto* view = qobject_cast<DocumentView*>(tabs_->widget(i)))
            views.push_back(view);
    return views;
}

DocumentView* MainWindow::newDocument() {
    return files_->newDocument();
}

void MainWindow::setCurrentView(DocumentView* view) {
    tabs_->setCurrentWidget(view);
}

void MainWindow::removeView(DocumentView* view) {
    const int index = tabs_->indexOf(view);
    if (index < 0)
        return;
    undoGroup_.removeStack(view->document()->undoStack());
    files_->unwatch(view);
    tabs_->removeTab(index);
    delete view;
}

bool MainWindow::closeDocument(int index) {
    return files_->close(qobject_cast<DocumentView*>(tabs_->widget(index)));
}

void MainWindow::closeEvent(QCloseEvent* event) {
    jobs_->cancel();  // a running job's result would have no document to go to
    if (!files_->closeAll()) {
        event->ignore();
        return;
    }
    QSettings settings;
    settings.setValue(QStringLiteral("window/geometry"), saveGeometry());
    settings.setValue(QStringLiteral("window/state"), saveState());
    event->accept();
}

DocumentView* MainWindow::currentView() const {
    return qobject_cast<DocumentView*>(tabs_->currentWidget());
}

model::Document* MainWindow::currentDocument() const {
    auto* view = currentView();
    return view ? view->document() : nullptr;
}

void MainWindow::currentTabChanged(int) {
    DocumentView* view = currentView();
    model::Document* document = view ? view->document() : nullptr;
    undoGroup_.setActiveStack(document ? document->undoStack() : nullptr);
    outliner_->setDocument(document);
    properties_->setDocument(document);
    weights_->setDocument(document, view ? view->viewport() : nullptr);
    timeline_->setDocument(document);
    if (view) {
        view->viewport()->setTool(tools_->active());  // the checked tool, whichever it is
        view->viewport()->setWireframe(wireframeAction_->isChecked());
        view->viewport()->setDualQuaternionSkinning(dqsAction_->isChecked());
        view->viewport()->setGridVisible(gridAction_->isChecked());
        view->viewport()->setOnionSkin(timeline_->onionSkin());
        view->viewport()->setMouseBindings(preferences_.mouseBindings);
        view->setDefaultEdgeLength(preferences_.defaultEdgeLength);
        weightViews_->show(view->viewport()->weightView());  // each document keeps its own
    }
    updateTitle();
}

void MainWindow::updateTitle() {
    model::Document* document = currentDocument();
    setWindowTitle(document ? tr("%1[*] - RigMesh Studio").arg(document->displayName())
                            : tr("RigMesh Studio"));
    setWindowModified(document && document->isModified());
}

void MainWindow::showStatus(const QString& message, int timeoutMs) {
    statusBar()->showMessage(message, timeoutMs);
}

// Select first (Blender's default), the Sketch tool active: a new user
// draws at once. Every tool reports through its status signal; a stroke
// being drawn is previewed in, and a finished one becomes a part of, the
// current document only.
void MainWindow::createTools(QMenu* menu, QToolBar* toolbar) {
    // Our own icons (resources/icons, drawn by Qt's SVG icon engine,
    // libqt6svg6) say what each tool does.
    auto* sketch = new SketchTool;
    const std::tuple<ViewportTool*, QString, QKeySequence, QString> tools[] = {
        {new SelectTool, tr("&Select / Move"), QKeySequence(Qt::Key_Q), "select"},
        {sketch, tr("S&ketch Part"), QKeySequence(Qt::Key_S), "sketch"},
        {new PoseTool, tr("&Pose"), QKeySequence(Qt::Key_P), "pose"},
        {new MergeTool, tr("&Merge Parts"), QKeySequence(Qt::Key_M), "merge"},
        {new CutTool, tr("&Cut Part"), QKeySequence(Qt::Key_C), "cut"},
        {new PaintTool, tr("Paint &Weights"), QKeySequence(Qt::Key_W), "paint"}};
    for (const auto& [tool, text, key, icon] : tools) {
        QAction* action = tools_->add(tool, text, key, QStringLiteral(":/icons/%1.svg").arg(icon));
        menu->addAction(action);
        toolbar->addAction(action);
        connect(tool, &ViewportTool::status, this, &MainWindow::showStatus);
    }
    tools_->actionOf(sketch)->setChecked(true);
    connect(tools_, &ToolRegistry::activated, this,
            qOverload<ViewportTool*>(&MainWindow::activateTool));
    connect(sketch, &SketchTool::strokeFinished, this,
            [this](const auto& stroke, const auto& plane) {
                if (DocumentView* view = currentView())
                    view->createPartFromStroke(stroke, plane);
            });
    connect(sketch, &SketchTool::strokeChanged, this,
            [this](const auto& stroke, const auto& plane) {
                if (DocumentView* view = currentView())
                    view->previewStroke(stroke, plane);
            });
    connect(sketch, &SketchTool::strokeAbandoned, this, [this] {
        if (DocumentView* view = currentView())
            view->dropStrokePreview();
    });
}

// One activation path for every tool: its action checked, the current
// view's viewport given the tool, its options and weight view shown, its
// hint in the status bar.
void MainWindow::activateTool(ViewportTool* tool) {
    if (!tool)
        return;
    if (QAction* action = tools_->actionOf(tool); action && !action->isChecked()) {
        tools_->activate(tool);  // checks the action, then comes back here
        return;
    }
    QWidget* options = tool->optionsWidget();
    toolOptions_->setCurrentIndex(options ? toolOptions_->indexOf(options) : 0);
    if (auto* v = currentView())
        v->viewport()->setTool(tool);
    showStatus(tool->hint());
    // Painting shows what it paints: the selected bone's weights.
    if (const std::optional<WeightView> shown = tool->weightView())
        weightViews_->choose(*shown);
}

void MainWindow::deleteSelection() {
    model::Document* document = currentDocument();
    if (!document || !document->contains(document->selection().part)) {
        showStatus(tr("Select a part to delete"), 4000);
        return;
    }
    const model::PartId id = document->selection().part;
    runUserAction(tr("&Delete Part"), statusReport(*this), [&] {
        model::changeOrRestore(*document, [&] {
            document->clearSelection();
            model::pushCommand(*document,
                               std::make_unique<model::DeletePartCommand>(*document, id));
        });
    });
}

}  // namespace rigmesh::widgets
