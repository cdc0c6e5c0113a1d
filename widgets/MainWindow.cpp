#include "MainWindow.h"

#include <QAction>
#include <QActionGroup>
#include <QApplication>
#include <QCloseEvent>
#include <QDockWidget>
#include <QFileDialog>
#include <QFileInfo>
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

#include "DocumentView.h"
#include "MouseHint.h"
#include "base/Error.h"
#include "dialogs/ExportDialog.h"
#include "jobs/JobRunner.h"
#include "jobs/JobStatus.h"
#include "model/Autosave.h"
#include "model/DocumentExport.h"
#include "model/DocumentFile.h"
#include "model/ErrorText.h"
#include "model/PoseChange.h"
#include "model/commands/DeletePartCommand.h"
#include "model/commands/ImportPartsCommand.h"
#include "model/commands/ResetPoseCommand.h"
#include "model/recipe/RecipeFromHistory.h"
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
#include "viewport/Viewport.h"

// The tool icons are compiled into this static library: register them
// explicitly (Q_INIT_RESOURCE must be called outside any namespace).
static void registerIconResources() {
    Q_INIT_RESOURCE(icons);
}

namespace rigmesh::widgets {

MainWindow::MainWindow(const QString& recoveryDirectory, QWidget* parent)
    : QMainWindow(parent),
      tabs_(new QTabWidget(this)),
      outliner_(new OutlinerPanel(this)),
      properties_(new PropertiesPanel(this)),
      weights_(new WeightsPanel(this)),
      history_(new QUndoView(&undoGroup_, this)),
      timeline_(new TimelineDock(this)),
      selectTool_(new SelectTool(this)),
      sketchTool_(new SketchTool(this)),
      poseTool_(new PoseTool(this)),
      mergeTool_(new MergeTool(this)),
      cutTool_(new CutTool(this)),
      paintTool_(new PaintTool(this)),
      recoveryDirectory_(recoveryDirectory.isEmpty() ? QStandardPaths::writableLocation(
                                                           QStandardPaths::AppLocalDataLocation) +
                                                           QStringLiteral("/recovery")
                                                     : recoveryDirectory) {
    registerIconResources();
    setObjectName(QStringLiteral("RigMeshStudioMainWindow"));
    setWindowIcon(QIcon(QStringLiteral(":/icons/rigmesh-studio.svg")));
    confirmDiscardWeights = [this](const QString& question) {
        return QMessageBox::question(this, tr("Recompute Weights"), question,
                                     QMessageBox::Yes | QMessageBox::Cancel,
                                     QMessageBox::Cancel) == QMessageBox::Yes;
    };
    tabs_->setTabsClosable(true);
    tabs_->setDocumentMode(true);
    setCentralWidget(tabs_);
    connect(tabs_, &QTabWidget::currentChanged, this, &MainWindow::currentTabChanged);
    connect(tabs_, &QTabWidget::tabCloseRequested, this, &MainWindow::closeDocument);
    connect(sketchTool_, &SketchTool::hintMessage, this,
            [this](const QString& m) { showStatus(m, 5000); });
    connect(properties_, &PropertiesPanel::statusMessage, this, &MainWindow::showStatus);
    connect(weights_, &WeightsPanel::statusMessage, this, &MainWindow::showStatus);
    connect(timeline_, &TimelineDock::statusMessage, this, &MainWindow::showStatus);
    connect(timeline_, &TimelineDock::onionSkinToggled, this, [this](bool on) {
        if (auto* v = currentView())
            v->viewport()->setOnionSkin(on);
    });
    // Long work runs off the GUI thread, one job at a time (issue 16 item 3).
    jobs_ = new JobRunner(this);
    jobStatus_ = new JobStatus(this, jobs_);
    properties_->setJobRunner(jobs_);
    mouseHint_ = new MouseHint(tabs_);
    createActions();
    createDocks();
    createTimelineActions();
    applyPreferences(StudioPreferences::load());

    QSettings settings;
    restoreGeometry(settings.value(QStringLiteral("window/geometry")).toByteArray());
    restoreState(settings.value(QStringLiteral("window/state")).toByteArray());
    if (!settings.contains(QStringLiteral("window/geometry")))
        resize(1280, 800);
    rebuildRecentMenu();
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
        autosaves_.erase(view);
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
    toolbar->addAction(add(file, tr("&Open..."), QKeySequence::Open, &MainWindow::open,
                           QStyle::SP_DialogOpenButton));
    recentMenu_ = file->addMenu(tr("Open &Recent"));
    toolbar->addAction(
        add(file, tr("&Save"), QKeySequence::Save, &MainWindow::save, QStyle::SP_DialogSaveButton));
    // Explicit: QKeySequence::SaveAs is empty on platforms without a desktop theme.
    add(file, tr("Save &As..."), QKeySequence(Qt::CTRL | Qt::SHIFT | Qt::Key_S),
        &MainWindow::saveAs);
    file->addSeparator();
    add(file, tr("&Import..."), QKeySequence(Qt::CTRL | Qt::Key_I), &MainWindow::importFile);
    add(file, tr("&Export..."), QKeySequence(Qt::CTRL | Qt::Key_E), &MainWindow::exportDocument);
    add(file, tr("Save History as &Recipe..."), QKeySequence(), &MainWindow::saveHistoryAsRecipe);
    file->addSeparator();
    add(file, tr("&Close"), QKeySequence::Close, [this] { closeDocument(tabs_->currentIndex()); });
    add(file, tr("&Quit"), QKeySequence::Quit, &QWidget::close);

    auto* edit = menuBar()->addMenu(tr("&Edit"));
    QAction* undo = undoGroup_.createUndoAction(this, tr("&Undo"));
    undo->setShortcut(QKeySequence::Undo);
    undo->setIcon(s->standardIcon(QStyle::SP_ArrowBack));
    QAction* redo = undoGroup_.createRedoAction(this, tr("&Redo"));
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
    add(edit, tr("Co&nnect Bone"), QKeySequence(), &MainWindow::connectSelectedBone)
        ->setToolTip(tr("Move the selected bone's head onto its parent's tail, as Blender's "
                        "Connected does (cut and merge need connected bones)"));
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
    dqsAction_->setChecked(true);
    dqsAction_->setToolTip(tr("Off: linear blend skinning"));
    connect(dqsAction_, &QAction::toggled, this, [this](bool on) {
        if (auto* v = currentView())
            v->viewport()->setDualQuaternionSkinning(on);
    });
    // Skin weight views (issue 14 item 1), like Blender's weight paint display.
    auto* weights = viewMenu_->addMenu(tr("&Weights"));
    weightViewGroup_ = new QActionGroup(this);
    const std::pair<QString, WeightView> views[] = {
        {tr("&Off"), WeightView::Off},
        {tr("&Selected Bone (select its joint)"), WeightView::SelectedBone},
        {tr("&Dominant Bone"), WeightView::DominantBone},
        {tr("&Influence Count"), WeightView::Influences},
        {tr("Difference from &Global Weights"), WeightView::GlobalDifference}};
    for (const auto& [text, view] : views) {
        QAction* action = weights->addAction(text);
        action->setCheckable(true);
        action->setChecked(view == WeightView::Off);
        action->setData(static_cast<int>(view));
        weightViewGroup_->addAction(action);
        connect(action, &QAction::triggered, this, [this, view = view] {
            if (auto* v = currentView())
                v->viewport()->setWeightView(view);
            if (view == WeightView::SelectedBone)
                showStatus(tr("Weights of the selected joint's bone: blue 0, green 0.5, red 1, "
                              "dark blue none"),
                           6000);
        });
    }
    gridAction_ = viewMenu_->addAction(tr("&Grid"));
    gridAction_->setCheckable(true);
    gridAction_->setChecked(true);
    connect(gridAction_, &QAction::toggled, this, [this](bool on) {
        if (auto* v = currentView())
            v->viewport()->setGridVisible(on);
    });
    viewMenu_->addSeparator();

    auto* tools = menuBar()->addMenu(tr("&Tools"));
    toolGroup_ = new QActionGroup(this);
    // Our own icons (resources/icons, drawn by Qt's SVG icon engine,
    // libqt6svg6) say what each tool does.
    selectToolAction_ =
        add(tools, tr("&Select / Move"), QKeySequence(Qt::Key_Q), &MainWindow::activateSelectTool);
    selectToolAction_->setIcon(QIcon(QStringLiteral(":/icons/select.svg")));
    sketchToolAction_ =
        add(tools, tr("S&ketch Part"), QKeySequence(Qt::Key_S), &MainWindow::activateSketchTool);
    sketchToolAction_->setIcon(QIcon(QStringLiteral(":/icons/sketch.svg")));
    poseToolAction_ =
        add(tools, tr("&Pose"), QKeySequence(Qt::Key_P), &MainWindow::activatePoseTool);
    poseToolAction_->setIcon(QIcon(QStringLiteral(":/icons/pose.svg")));
    mergeToolAction_ =
        add(tools, tr("&Merge Parts"), QKeySequence(Qt::Key_M), &MainWindow::activateMergeTool);
    mergeToolAction_->setIcon(QIcon(QStringLiteral(":/icons/merge.svg")));
    cutToolAction_ =
        add(tools, tr("&Cut Part"), QKeySequence(Qt::Key_C), &MainWindow::activateCutTool);
    cutToolAction_->setIcon(QIcon(QStringLiteral(":/icons/cut.svg")));
    paintToolAction_ =
        add(tools, tr("Paint &Weights"), QKeySequence(Qt::Key_W), &MainWindow::activatePaintTool);
    paintToolAction_->setIcon(QIcon(QStringLiteral(":/icons/paint.svg")));
    tools->addSeparator();
    add(tools, tr("&Reset Pose"), QKeySequence(Qt::ALT | Qt::Key_R), &MainWindow::resetPose);
    QAction* rig = add(tools, tr("&Auto-Rig Part"), QKeySequence(), &MainWindow::rigSelectedPart);
    rig->setObjectName(QStringLiteral("autoRigPart"));
    rig->setToolTip(
        tr("Give the selected part without a skeleton (an imported mesh) a skeleton "
           "from its shape and skin weights"));
    createWeightMenu(tools);
    for (const auto& [action, tool] : toolPairs()) {
        action->setCheckable(true);
        toolGroup_->addAction(action);
    }
    toolbar->addSeparator();
    toolbar->addAction(selectToolAction_);
    toolbar->addAction(sketchToolAction_);
    toolbar->addAction(poseToolAction_);
    toolbar->addAction(mergeToolAction_);
    toolbar->addAction(cutToolAction_);
    toolbar->addAction(paintToolAction_);
    sketchToolAction_->setChecked(true);

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
    for (const auto& [action, tool] : toolPairs())
        if (QWidget* options = tool->optionsWidget())
            toolOptions_->addWidget(options);
    dock(tr("Tool Options"), "toolOptionsDock", toolOptions_, Qt::LeftDockWidgetArea);
    // The timeline along the bottom, under the view, as in Blender.
    dock(tr("Timeline"), "timelineDock", timeline_, Qt::BottomDockWidgetArea);
}

// Transport and keying (issue 15), window-wide as in Blender: a text field
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
            showWeightView(shown);
    });
    connect(sketchTool_, &SketchTool::strokeFinished, view,
            [this, view](const auto& stroke, const auto& plane) {
                if (currentView() == view)
                    view->createPartFromStroke(stroke, plane);
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
    autosaves_[view] = new model::Autosave(doc, recoveryDirectory_, view);
    autosaves_[view]->setDelay(preferences_.autosaveSeconds * 1000);
    const int index = tabs_->addTab(view, doc->displayName());
    tabs_->setCurrentIndex(index);
    refreshTab();
    return view;
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
        view->viewport()->setTool(activeTool());  // the checked tool, whichever it is
        view->viewport()->setWireframe(wireframeAction_->isChecked());
        view->viewport()->setDualQuaternionSkinning(dqsAction_->isChecked());
        view->viewport()->setGridVisible(gridAction_->isChecked());
        view->viewport()->setOnionSkin(timeline_->onionSkin());
        view->viewport()->setMouseBindings(preferences_.mouseBindings);
        view->setDefaultEdgeLength(preferences_.defaultEdgeLength);
        showWeightView(view->viewport()->weightView());  // each document keeps its own
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

// One activation path for every tool: its action checked, the current
// view's viewport given the tool, its hint in the status bar.
void MainWindow::activateTool(QAction* action, ViewportTool* tool) {
    action->setChecked(true);
    QWidget* options = tool->optionsWidget();
    toolOptions_->setCurrentIndex(options ? toolOptions_->indexOf(options) : 0);
    if (auto* v = currentView())
        v->viewport()->setTool(tool);
    showStatus(tool->hint());
}

void MainWindow::activateSelectTool() {
    activateTool(selectToolAction_, selectTool_);
}

void MainWindow::activateSketchTool() {
    activateTool(sketchToolAction_, sketchTool_);
}

void MainWindow::activatePoseTool() {
    activateTool(poseToolAction_, poseTool_);
}

void MainWindow::activateMergeTool() {
    activateTool(mergeToolAction_, mergeTool_);
}

void MainWindow::activateCutTool() {
    activateTool(cutToolAction_, cutTool_);
}

void MainWindow::activatePaintTool() {
    activateTool(paintToolAction_, paintTool_);
    // Painting shows what it paints: the selected bone's weights.
    for (QAction* action : weightViewGroup_->actions())
        if (static_cast<WeightView>(action->data().toInt()) == WeightView::SelectedBone)
            action->trigger();
}

ViewportTool* MainWindow::activeTool() const {
    for (const auto& [action, tool] : toolPairs())
        if (action->isChecked())
            return tool;
    return selectTool_;
}

std::vector<std::pair<QAction*, ViewportTool*>> MainWindow::toolPairs() const {
    return {{selectToolAction_, selectTool_}, {sketchToolAction_, sketchTool_},
            {poseToolAction_, poseTool_},     {mergeToolAction_, mergeTool_},
            {cutToolAction_, cutTool_},       {paintToolAction_, paintTool_}};
}

void MainWindow::resetPose() {
    model::Document* document = currentDocument();
    if (!document || !document->contains(document->selection().part)) {
        showStatus(tr("Select a part to reset its pose"), 4000);
        return;
    }
    const model::PartId id = document->selection().part;
    model::pushPoseChange(*document, id, new model::ResetPoseCommand(*document, id));
}

void MainWindow::deleteSelection() {
    model::Document* document = currentDocument();
    if (!document || !document->contains(document->selection().part)) {
        showStatus(tr("Select a part to delete"), 4000);
        return;
    }
    const model::PartId id = document->selection().part;
    document->clearSelection();
    document->undoStack()->push(new model::DeletePartCommand(*document, id));
}

}  // namespace rigmesh::widgets
