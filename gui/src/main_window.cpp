// SPDX-License-Identifier: MIT
// ddfcam gui: MainWindow wiring: menus -> controller/scene/view, errors -> runUserAction.
#include <ddfcam/gui/main_window.h>

#include <ddfcam/error.h>
#include <ddfcam/gui/part_controller.h>
#include <ddfcam/gui/part_scene.h>
#include <ddfcam/gui/vtk_view.h>

#include <QAction>
#include <QApplication>
#include <QFileDialog>
#include <QFileInfo>
#include <QKeySequence>
#include <QLabel>
#include <QMenu>
#include <QMenuBar>
#include <QStatusBar>

#include <filesystem>

namespace ddfcam::gui {

namespace {

WorkbenchDialogs withDefaults(WorkbenchDialogs d, QWidget* parent) {
  if (!d.openPath)
    d.openPath = [parent] {
      return QFileDialog::getOpenFileName(
          parent, QObject::tr("Open part"), QString(),
          QObject::tr("Parts (*.ddf *.stl *.obj *.ply *.off);;DDF (*.ddf);;"
                      "Meshes (*.stl *.obj *.ply *.off);;All files (*)"));
    };
  if (!d.screenshotPath)
    d.screenshotPath = [parent] {
      return QFileDialog::getSaveFileName(parent, QObject::tr("Save screenshot"), "ddfcam.png",
                                          QObject::tr("PNG images (*.png)"));
    };
  if (!d.error) d.error = messageBoxReporter(parent);
  return d;
}

}  // namespace

MainWindow::MainWindow(WorkbenchDialogs dialogs, bool openDemoAtStart, QWidget* parent)
    : QMainWindow(parent) {
  setWindowTitle(tr("ddfcam workbench"));
  view_ = new VtkView(this);
  setCentralWidget(view_);
  scene_ = std::make_unique<PartScene>(view_->renderer());
  controller_ = std::make_unique<PartController>(*scene_);
  dialogs_ = withDefaults(std::move(dialogs), this);

  status_ = new QLabel(this);
  statusBar()->addPermanentWidget(status_, 1);
  createFileMenu();
  createViewMenu();
  resize(1200, 800);
  if (openDemoAtStart) openDemo();
}

MainWindow::~MainWindow() = default;

bool MainWindow::openPath(const QString& path) {
  const bool ok = runUserAction(dialogs_.error, tr("Open %1").arg(QFileInfo(path).fileName()), [&] {
    controller_->openFile(std::filesystem::path(path.toStdString()));
  });
  if (ok) afterPartChanged();
  return ok;
}

bool MainWindow::openDemo() {
  const bool ok =
      runUserAction(dialogs_.error, tr("Open demo part"), [&] { controller_->openDemo(); });
  if (ok) afterPartChanged();
  return ok;
}

bool MainWindow::saveScreenshot(const QString& path) {
  return runUserAction(dialogs_.error, tr("Save screenshot"), [&] {
    if (!view_->saveScreenshot(path))
      throw IoError("cannot write the screenshot to '" + path.toStdString() + "'");
  });
}

QString MainWindow::statusText() const {
  return status_->text();
}

void MainWindow::createFileMenu() {
  QMenu* file = menuBar()->addMenu(tr("&File"));
  QAction* open = file->addAction(tr("&Open..."), this, [this] {
    const QString path = dialogs_.openPath ? dialogs_.openPath() : QString();
    if (!path.isEmpty()) openPath(path);
  });
  open->setObjectName("actionOpen");
  open->setShortcut(QKeySequence::Open);
  QAction* demo = file->addAction(tr("Open &demo part"), this, [this] { openDemo(); });
  demo->setObjectName("actionOpenDemo");
  QAction* shot = file->addAction(tr("Save &screenshot..."), this, [this] {
    const QString path = dialogs_.screenshotPath ? dialogs_.screenshotPath() : QString();
    if (!path.isEmpty()) saveScreenshot(path);
  });
  shot->setObjectName("actionSaveScreenshot");
  file->addSeparator();
  QAction* quit = file->addAction(tr("&Quit"), this, &QWidget::close);
  quit->setObjectName("actionQuit");
  quit->setShortcut(QKeySequence::Quit);
}

void MainWindow::createViewMenu() {
  QMenu* menu = menuBar()->addMenu(tr("&View"));
  addLayerToggle(menu, tr("&Surface (shaded)"), "actionShowSurface",
                 static_cast<int>(Layer::Surface), true);
  addLayerToggle(menu, tr("Support &mesh (wireframe)"), "actionShowSupport",
                 static_cast<int>(Layer::Support), false);
  addLayerToggle(menu, tr("S&tubbles (lines)"), "actionShowStubbles",
                 static_cast<int>(Layer::Stubbles), false);
  menu->addSeparator();
  QAction* fit = menu->addAction(tr("&Fit view"), this, [this] { view_->fitCamera(); });
  fit->setObjectName("actionFitView");
  fit->setShortcut(Qt::Key_F);
}

QAction* MainWindow::addLayerToggle(QMenu* menu, const QString& text, const QString& name,
                                    int layer, bool checked) {
  QAction* action = menu->addAction(text);
  action->setObjectName(name);
  action->setCheckable(true);
  action->setChecked(checked);
  scene_->setVisible(static_cast<Layer>(layer), checked);
  connect(action, &QAction::toggled, this, [this, layer](bool on) {
    scene_->setVisible(static_cast<Layer>(layer), on);
    view_->requestRender();
  });
  return action;
}

void MainWindow::afterPartChanged() {
  status_->setText(QString::fromStdString(controller_->summary()));
  if (const PartDocument* doc = controller_->document())
    setWindowTitle(tr("%1 - ddfcam workbench").arg(QString::fromStdString(doc->name)));
  // An oblique view from the front-right, z up: parts are mostly z-maps or lie on the table.
  view_->fitCameraFrom(0.45, -1.0, 0.85, 0.0, 0.0, 1.0);
}

}  // namespace ddfcam::gui
