// SPDX-License-Identifier: MIT
// ddfcam gui: the workbench main window (menus, status bar); delegates all work.
#pragma once

#include <ddfcam/gui/user_action.h>

#include <QMainWindow>
#include <QString>

#include <functional>
#include <memory>

class QAction;
class QLabel;
class QMenu;

namespace ddfcam::gui {

class PartController;
class PartScene;
class VtkView;

/// @brief The interactive parts of the window that tests replace: file dialogs and the
/// error message box.
struct WorkbenchDialogs {
  /// Asks for a part to open; an empty string means the user cancelled.
  std::function<QString()> openPath;
  /// Asks where to save a screenshot; an empty string means the user cancelled.
  std::function<QString()> screenshotPath;
  /// Shows an error of a user action.
  ErrorReporter error;
};

/// @brief Workbench window: a VtkView in the centre, File and View menus, a status line.
/// Starts on the built-in demo part. Every menu action runs through runUserAction(), so a
/// library error is shown once and leaves the previous state in place.
class MainWindow : public QMainWindow {
  Q_OBJECT

 public:
  /// @param dialogs file dialogs and error reporter; empty members get the defaults
  /// (QFileDialog, QMessageBox).
  /// @param openDemoAtStart show the demo part right away (else the window starts empty).
  explicit MainWindow(WorkbenchDialogs dialogs = {}, bool openDemoAtStart = true,
                      QWidget* parent = nullptr);
  ~MainWindow() override;

  /// @brief Opens @p path (.ddf or a mesh) as the File > Open action does after its dialog.
  /// @return false if loading failed (the error was reported, the previous part stays).
  bool openPath(const QString& path);
  /// @brief Shows the built-in demo part (File > Open demo part).
  bool openDemo();
  /// @brief Writes the rendered 3D view to @p path (File > Save screenshot after its dialog).
  bool saveScreenshot(const QString& path);

  VtkView* view() const { return view_; }
  const PartController& controller() const { return *controller_; }
  const PartScene& scene() const { return *scene_; }
  /// @brief Text of the permanent status-bar label.
  QString statusText() const;

 private:
  void createFileMenu();
  void createViewMenu();
  QAction* addLayerToggle(QMenu* menu, const QString& text, const QString& name, int layer,
                          bool checked);
  void afterPartChanged();

  VtkView* view_ = nullptr;
  QLabel* status_ = nullptr;
  std::unique_ptr<PartScene> scene_;
  std::unique_ptr<PartController> controller_;
  WorkbenchDialogs dialogs_;
};

}  // namespace ddfcam::gui
