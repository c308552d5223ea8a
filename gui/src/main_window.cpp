// SPDX-License-Identifier: MIT
// ddfcam gui: MainWindow wiring: services, docks, menus -> actions, panels, jobs, drag and drop.
#include <ddfcam/gui/main_window.h>

#include <ddfcam/error.h>
#include <ddfcam/gui/camera_tool_bar.h>
#include <ddfcam/gui/console_dock.h>
#include <ddfcam/gui/default_dialogs.h>
#include <ddfcam/gui/document.h>
#include <ddfcam/gui/interaction_mode.h>
#include <ddfcam/gui/job_progress_widget.h>
#include <ddfcam/gui/job_runner.h>
#include <ddfcam/gui/mould_view.h>
#include <ddfcam/gui/panels/error_map_panel.h>
#include <ddfcam/gui/panels/fields_panel.h>
#include <ddfcam/gui/panels/mould_panel.h>
#include <ddfcam/gui/panels/mould_tools_panel.h>
#include <ddfcam/gui/panels/part_panel.h>
#include <ddfcam/gui/panels/pick_panel.h>
#include <ddfcam/gui/panels/segmentation_panel.h>
#include <ddfcam/gui/panels/simulation_panel.h>
#include <ddfcam/gui/panels/spacing_refinement_panel.h>
#include <ddfcam/gui/panels/streamlines_panel.h>
#include <ddfcam/gui/panels/tools_panel.h>
#include <ddfcam/gui/part_scene.h>
#include <ddfcam/gui/part_view.h>
#include <ddfcam/gui/path_export_dialog.h>
#include <ddfcam/gui/path_import.h>
#include <ddfcam/gui/plot_dock.h>
#include <ddfcam/gui/recent_files.h>
#include <ddfcam/gui/recovery_manager.h>
#include <ddfcam/gui/vtk_view.h>
#include <ddfcam/gui/wheel_guard.h>
#include <ddfcam/gui/workbench.h>

#include <QAction>
#include <QCloseEvent>
#include <QDockWidget>
#include <QFileInfo>
#include <QLabel>
#include <QMenu>
#include <QMenuBar>
#include <QMimeData>
#include <QScrollArea>
#include <QScrollBar>
#include <QSettings>
#include <QStatusBar>
#include <QTabWidget>
#include <QUndoStack>

namespace ddfcam::gui {

MainWindow::MainWindow(WorkbenchDialogs dialogs, WorkbenchOptions options, QWidget* parent)
    : QMainWindow(parent), dialogs_(withDefaultDialogs(std::move(dialogs), this)) {
  setWindowTitle(tr("ddfcam workbench"));
  setAcceptDrops(true);
  // The part and the mould study each get a tab of the central area.
  centralTabs_ = new QTabWidget(this);
  centralTabs_->setObjectName("centralTabs");
  view_ = new VtkView(centralTabs_);
  centralTabs_->addTab(view_, tr("Part"));
  mouldView_ = new MouldView(centralTabs_);
  mouldView_->setObjectName("mouldView");
  centralTabs_->addTab(mouldView_, tr("Mould"));
  setCentralWidget(centralTabs_);
  createServices(options);
  createDocks();
  createFileMenu();
  createEditMenu();
  createViewMenu();
  registerDefaultPanels();
  resize(1280, 820);
  // The 3D view is the workbench; the plots get a strip below it.
  resizeDocks({plots_}, {190}, Qt::Vertical);
  // The engineer's own arrangement of docks and window, as left last time.
  restoreGeometry(settings_->value("window/geometry").toByteArray());
  restoreState(settings_->value("window/state").toByteArray());
  updateTitle();
  updateStatus();
  if (!projectActions_->offerRecovery(*recovery_) && options.openDemoAtStart) openDemo();
}

MainWindow::~MainWindow() {
  jobs_->cancel();
  jobs_->waitForFinished(10'000);
}

void MainWindow::createServices(const WorkbenchOptions& options) {
  document_ = std::make_unique<Document>();
  ErrorReporter report = [this](const QString& title, const QString& message) {
    if (dialogs_.error) dialogs_.error(title, message);
  };
  jobs_ = std::make_unique<JobRunner>(report);
  partView_ = std::make_unique<PartView>(*document_, *view_);
  settings_ = options.settings ? options.settings : new QSettings(this);
  recent_ = std::make_unique<RecentFiles>(settings_);
  RecoveryParams recovery;
  if (!options.recoveryDirectory.isEmpty()) recovery.directory = options.recoveryDirectory;
  recovery.intervalMs = options.autosaveIntervalMs;
  recovery_ = std::make_unique<RecoveryManager>(*document_, recovery);
  projectActions_ = std::make_unique<ProjectActions>(*document_, *jobs_, *recent_, dialogs_);

  cameraBar_ = new CameraToolBar(view_, this);
  addToolBar(Qt::TopToolBarArea, cameraBar_);
  status_ = new QLabel(this);
  // The part facts give way (clipped, whole in the tooltip) to the mode and the job progress.
  status_->setSizePolicy(QSizePolicy::Ignored, QSizePolicy::Preferred);
  statusBar()->addPermanentWidget(status_, 1);
  jobProgress_ = new JobProgressWidget(*jobs_, this);
  // Keep its room while idle: a status bar that grows during a job would resize the 3D view.
  QSizePolicy policy = jobProgress_->sizePolicy();
  policy.setRetainSizeWhenHidden(true);
  jobProgress_->setSizePolicy(policy);
  statusBar()->addPermanentWidget(jobProgress_);
  connect(jobProgress_, &JobProgressWidget::statusMessage, this,
          [this](const QString& message) { statusBar()->showMessage(message, 8000); });

  connect(document_.get(), &Document::modifiedChanged, this, &MainWindow::updateTitle);
  connect(document_.get(), &Document::filePathChanged, this, &MainWindow::updateTitle);
  connect(document_.get(), &Document::changed, this, &MainWindow::updateTitle);
  connect(partView_.get(), &PartView::geometryChanged, this, [this](bool partReplaced) {
    updateStatus();
    // An oblique view from the front-right, z up: parts are mostly z-maps or lie on the table.
    if (!partReplaced) return;
    view_->viewFrom(ViewDirection::Isometric);
    plots_->clear();  // histograms and sections of the previous part
  });
}

void MainWindow::createDocks() {
  plots_ = new PlotDock(this);
  addDockWidget(Qt::BottomDockWidgetArea, plots_);
  console_ = new ConsoleDock(this);
  console_->installLogSink();
  addDockWidget(Qt::BottomDockWidgetArea, console_);
  tabifyDockWidget(console_, plots_);
  plots_->raise();
  workbench_ = std::make_unique<Workbench>(
      Workbench{*document_, *jobs_, *partView_, *plots_, *console_, dialogs_.error});
  workbench_->confirmLongJob = dialogs_.confirmLongJob;
  // A converted mesh that is no valid DDF stays flagged in the status until the next open;
  // the details are in the console, which comes to the front.
  connect(projectActions_.get(), &ProjectActions::opened, this, [this] {
    conversionWarning_.clear();
    updateStatus();
  });
  connect(projectActions_.get(), &ProjectActions::conversionReported, this,
          [this](const QString& verdict, bool valid) {
            conversionWarning_ = valid ? QString() : verdict;
            updateStatus();
            statusBar()->showMessage(verdict, valid ? 8000 : 0);
            if (!valid) console_->raise();
          });
  workbench_->mouldView = mouldView_;
  workbench_->projectActions = projectActions_.get();
  workbench_->mode = new InteractionMode(this);
  workbench_->mode->attachTo(*this);
  new WheelGuard(this);  // the wheel scrolls panels, it does not change their boxes
}

void MainWindow::registerPanel(Panel* panel) {
  auto* dock = new QDockWidget(panel->title(), this);
  dock->setObjectName("panel_" + panel->id());
  // Panels taller than the window scroll instead of forcing the window (and the view) to grow.
  auto* scroll = new QScrollArea(dock);
  scroll->setObjectName("panelScroll_" + panel->id());
  scroll->setWidgetResizable(true);
  scroll->setFrameShape(QFrame::NoFrame);
  scroll->setWidget(panel);
  // Full width (no horizontal scrolling), scrolled vertically only.
  scroll->setHorizontalScrollBarPolicy(Qt::ScrollBarAlwaysOff);
  scroll->setMinimumWidth(panel->minimumSizeHint().width() +
                          scroll->verticalScrollBar()->sizeHint().width());
  dock->setWidget(scroll);
  addDockWidget(panel->area(), dock);
  for (Panel* other : panels_) {
    if (other->area() == panel->area()) {
      tabifyDockWidget(findChild<QDockWidget*>("panel_" + other->id()), dock);
      break;
    }
  }
  panelsMenu_->addAction(dock->toggleViewAction());
  if (!panel->menuTitle().isEmpty())
    menuNamed(panel->menuTitle())->addActions(panel->menuActions());
  panels_.push_back(panel);
}

void MainWindow::registerDefaultPanels() {
  registerPanel(new PartPanel(*workbench_));
  registerPanel(new FieldsPanel(*workbench_));
  registerPanel(new ToolsPanel(*workbench_));
  registerPanel(new SimulationPanel(*workbench_));
  registerPanel(new PickPanel(*workbench_));
  registerPanel(new StreamlinesPanel(*workbench_));
  registerPanel(new SegmentationPanel(*workbench_));
  registerPanel(new ErrorMapPanel(*workbench_));
  registerPanel(new SpacingRefinementPanel(*workbench_));
  registerPanel(new MouldPanel(*workbench_));
  registerPanel(new MouldToolsPanel(*workbench_));
  if (auto* first = findChild<QDockWidget*>("panel_fields")) first->raise();
}

QMenu* MainWindow::menuNamed(const QString& title) {
  for (QAction* action : menuBar()->actions())
    if (action->menu() && action->text() == title) return action->menu();
  return menuBar()->addMenu(title);
}

bool MainWindow::openPath(const QString& path) {
  return projectActions_->openPath(path);
}

bool MainWindow::importPathFile(const QString& path) {
  return gui::importPathFile(path, *document_, dialogs_, console_);
}

bool MainWindow::exportToolPaths() {
  const QStringList written =
      exportPathsInteractively(document_->project(), dialogs_, *settings_, console_);
  if (written.isEmpty()) return false;
  // Success is said where the user looks, not only in the console.
  QStringList names;
  for (const QString& file : written) names << QFileInfo(file).fileName();
  statusBar()->showMessage(tr("Exported tool paths to %1").arg(names.join(", ")), 8000);
  return true;
}

bool MainWindow::openDemo() {
  return projectActions_->openDemo();
}

bool MainWindow::saveScreenshot(const QString& path, QSize size) {
  return runUserAction(dialogs_.error, tr("Save screenshot"), [&] {
    const bool saved =
        size.isValid() ? view_->saveScreenshot(path, size) : view_->saveScreenshot(path);
    if (!saved) throw IoError("cannot write the screenshot to '" + path.toStdString() + "'");
  });
}

bool MainWindow::waitForJobs(int timeoutMs) {
  return jobs_->waitForFinished(timeoutMs);
}

QString MainWindow::statusText() const {
  return status_->text();
}

void MainWindow::createFileMenu() {
  QMenu* file = menuBar()->addMenu(tr("&File"));
  auto add = [&](const QString& text, const char* name, auto slot, QKeySequence key = {}) {
    QAction* action = file->addAction(text, this, slot);
    action->setObjectName(name);
    action->setShortcut(key);
    return action;
  };
  add(
      tr("&New project"), "actionNew", [this] { projectActions_->newProject(); },
      QKeySequence::New);
  add(
      tr("&Open..."), "actionOpen",
      [this] {
        const QString path = dialogs_.openPath ? dialogs_.openPath() : QString();
        if (!path.isEmpty()) openPath(path);
      },
      QKeySequence::Open);
  add(tr("Open &demo part"), "actionOpenDemo", [this] { openDemo(); });
  recentMenu_ = file->addMenu(tr("Open &recent"));
  recentMenu_->setObjectName("menuRecent");
  connect(recentMenu_, &QMenu::aboutToShow, this, [this] {
    recent_->populate(recentMenu_, [this](const QString& path) { openPath(path); });
  });
  file->addSeparator();
  add(
      tr("&Save project"), "actionSave", [this] { projectActions_->save(); }, QKeySequence::Save);
  add(
      tr("Save project &as..."), "actionSaveAs",
      [this] {
        const QString path = dialogs_.saveProjectPath ? dialogs_.saveProjectPath() : QString();
        if (!path.isEmpty()) projectActions_->saveAs(path);
      },
      QKeySequence::SaveAs);
  add(tr("Save s&creenshot..."), "actionSaveScreenshot", [this] {
    if (const auto request = dialogs_.screenshot ? dialogs_.screenshot() : std::nullopt)
      saveScreenshot(request->path, request->size);
  });
  file->addSeparator();
  addPathFileActions(file);
  file->addSeparator();
  add(
      tr("&Quit"), "actionQuit", [this] { close(); }, QKeySequence::Quit);
}

void MainWindow::addPathFileActions(QMenu* file) {
  QAction* import = file->addAction(tr("&Import tool path..."), this, [this] {
    const QString path = dialogs_.importPathFile ? dialogs_.importPathFile() : QString();
    if (!path.isEmpty()) importPathFile(path);
  });
  import->setObjectName("actionImportPath");
  QAction* exportPaths =
      file->addAction(tr("&Export tool paths..."), this, [this] { exportToolPaths(); });
  exportPaths->setObjectName("actionExportPaths");
  auto enableExport = [this, exportPaths] {
    exportPaths->setEnabled(!document_->project().paths.empty());
  };
  connect(document_.get(), &Document::changed, exportPaths, enableExport);
  enableExport();
}

void MainWindow::createEditMenu() {
  QMenu* edit = menuBar()->addMenu(tr("&Edit"));
  QAction* undo = document_->undoStack()->createUndoAction(this, tr("&Undo"));
  undo->setObjectName("actionUndo");
  undo->setShortcut(QKeySequence::Undo);
  QAction* redo = document_->undoStack()->createRedoAction(this, tr("&Redo"));
  redo->setObjectName("actionRedo");
  redo->setShortcut(QKeySequence::Redo);
  edit->addAction(undo);
  edit->addAction(redo);
  edit->addSeparator();
  // Esc stops what is going on: the running job, else an editing mode of the views.
  QAction* cancel = edit->addAction(tr("&Cancel running job or editing mode"), this, [this] {
    if (jobs_->isRunning())
      jobs_->cancel();
    else
      workbench_->mode->end();
  });
  cancel->setObjectName("actionCancelJob");
  cancel->setShortcut(Qt::Key_Escape);
}

void MainWindow::createViewMenu() {
  QMenu* menu = menuBar()->addMenu(tr("&View"));
  auto toggle = [&](const QString& text, const char* name, bool on, auto apply) {
    QAction* action = menu->addAction(text);
    action->setObjectName(name);
    action->setCheckable(true);
    action->setChecked(on);
    connect(action, &QAction::toggled, this, apply);
    apply(on);
  };
  PartScene& scene = partView_->scene();
  auto layer = [this, &scene](Layer l) {
    return [this, &scene, l](bool on) {
      scene.setVisible(l, on);
      view_->requestRender();
    };
  };
  toggle(tr("&Surface (shaded)"), "actionShowSurface", true, layer(Layer::Surface));
  toggle(tr("Support &mesh (wireframe)"), "actionShowSupport", false, layer(Layer::Support));
  toggle(tr("S&tubbles (lines)"), "actionShowStubbles", false, layer(Layer::Stubbles));
  toggle(tr("Tool &paths"), "actionShowPaths", true,
         [this](bool on) { partView_->setPathsVisible(on); });
  toggle(tr("Displacement &vectors (arrows)"), "actionShowVectors", false,
         [this](bool on) { partView_->setVectorGlyphsVisible(on); });
  toggle(tr("C&rust h = +1 (translucent)"), "actionShowCrustAbove", false,
         [this](bool on) { partView_->setCrustVisible(+1, on); });
  toggle(tr("Crust h = -&1 (translucent)"), "actionShowCrustBelow", false,
         [this](bool on) { partView_->setCrustVisible(-1, on); });
  menu->addSeparator();
  menu->addActions(cameraBar_->actions());
  menu->addSeparator();
  panelsMenu_ = menu->addMenu(tr("&Panels"));
  panelsMenu_->setObjectName("menuPanels");
  panelsMenu_->addAction(plots_->toggleViewAction());
  panelsMenu_->addAction(console_->toggleViewAction());
}

void MainWindow::updateTitle() {
  const auto& project = document_->project();
  QString name = document_->filePath().isEmpty()
                     ? QString::fromStdString(project.part ? project.partName : "no part")
                     : QFileInfo(document_->filePath()).fileName();
  setWindowTitle(tr("%1%2 - ddfcam workbench").arg(name, document_->isModified() ? "*" : ""));
}

void MainWindow::updateStatus() {
  const QString summary = QString::fromStdString(partView_->summary());
  status_->setText(conversionWarning_.isEmpty() ? summary : summary + "  |  " + conversionWarning_);
  status_->setToolTip(status_->text());
}

void MainWindow::closeEvent(QCloseEvent* event) {
  if (!projectActions_->maybeSave()) {
    event->ignore();
    return;
  }
  jobs_->cancel();
  jobs_->waitForFinished(10'000);
  recovery_->discardRecovery();
  settings_->setValue("window/geometry", saveGeometry());
  settings_->setValue("window/state", saveState());
  event->accept();
}

void MainWindow::dragEnterEvent(QDragEnterEvent* event) {
  const auto urls = event->mimeData()->urls();
  if (urls.size() != 1 || !urls.front().isLocalFile()) return;
  const QString path = urls.front().toLocalFile();
  if (ProjectActions::canOpen(path) || isPathFile(path)) event->acceptProposedAction();
}

void MainWindow::dropEvent(QDropEvent* event) {
  const auto urls = event->mimeData()->urls();
  if (urls.size() != 1 || !urls.front().isLocalFile()) return;
  event->acceptProposedAction();
  const QString path = urls.front().toLocalFile();
  // Tool-path files are placed on the open part; everything else opens as before.
  if (!ProjectActions::canOpen(path) && isPathFile(path))
    // After the drop returns: the import dialog is modal and the drag source waits for us.
    QMetaObject::invokeMethod(
        this, [this, path] { importPathFile(path); }, Qt::QueuedConnection);
  else
    openPath(path);
}

}  // namespace ddfcam::gui
