// SPDX-License-Identifier: MIT
// ddfcam gui: the workbench main window: 3D view, docks, menus; delegates all work.
#pragma once

#include <ddfcam/gui/project_actions.h>

#include <QMainWindow>
#include <QString>

#include <memory>
#include <vector>

class QAction;
class QLabel;
class QMenu;
class QSettings;
class QTabWidget;

namespace ddfcam::gui {

class CameraToolBar;
class ConsoleDock;
class Document;
class JobProgressWidget;
class JobRunner;
class MouldView;
class Panel;
class PartView;
class PlotDock;
class RecentFiles;
class RecoveryManager;
class VtkView;
struct Workbench;

/// @brief Start-up options of the workbench window.
struct WorkbenchOptions {
  /// Start with the built-in demo part (a load job started by the constructor). Default true.
  bool openDemoAtStart = true;
  /// Directory of autosave/recovery files; empty: the per-user application data folder.
  QString recoveryDirectory;
  /// Autosave interval, ms. Default 120,000 (2 minutes).
  int autosaveIntervalMs = 120'000;
  /// Settings store (recent files); null: the application's default QSettings.
  QSettings* settings = nullptr;
};

/// @brief Workbench window: a VtkView in the centre with camera buttons, workflow panels in
/// docks (registerPanel), a plot dock and a console, File/Edit/View menus and a status bar
/// with job progress and cancel. Every menu action runs through runUserAction or a job, so a
/// library error is shown once and leaves the document as it was.
class MainWindow : public QMainWindow {
  Q_OBJECT

 public:
  explicit MainWindow(WorkbenchDialogs dialogs = {}, WorkbenchOptions options = {},
                      QWidget* parent = nullptr);
  ~MainWindow() override;

  /// @brief Puts @p panel in a dock (its area), adds its toggle to View > Panels and its
  /// actions to its menu. Takes ownership.
  void registerPanel(Panel* panel);

  /// @brief Opens @p path (project, .ddf or mesh) as File > Open does after its dialog.
  /// @return true if the load job started (it reports its own errors).
  bool openPath(const QString& path);
  /// @brief Imports the tool-path file @p path onto the open part as File > Import tool path
  /// does after its file dialog (import dialog, one undoable path). @return true if added.
  bool importPathFile(const QString& path);
  /// @brief File > Export tool paths: the export dialog, then the files. @return true if
  /// written.
  bool exportToolPaths();
  /// @brief Starts loading the demo part (File > Open demo part).
  bool openDemo();
  /// @brief Writes the 3D view to @p path at @p size (device pixels; invalid: view size).
  bool saveScreenshot(const QString& path, QSize size = {});
  /// @brief Processes events until no job runs (tests, batch mode). @return false on timeout.
  bool waitForJobs(int timeoutMs = 60'000);

  VtkView* view() const { return view_; }
  /// @brief The "Mould" tab: mould and formed surfaces (MouldView).
  MouldView* mouldView() const { return mouldView_; }
  /// @brief The central tabs ("Part": view(), "Mould": mouldView()).
  QTabWidget* centralTabs() const { return centralTabs_; }
  Document& document() const { return *document_; }
  PartView& partView() const { return *partView_; }
  JobRunner& jobs() const { return *jobs_; }
  PlotDock& plots() const { return *plots_; }
  ConsoleDock& console() const { return *console_; }
  ProjectActions& projectActions() const { return *projectActions_; }
  RecoveryManager& recovery() const { return *recovery_; }
  Workbench& workbench() const { return *workbench_; }
  /// @brief Text of the permanent status-bar label.
  QString statusText() const;

 protected:
  void closeEvent(QCloseEvent* event) override;
  void dragEnterEvent(QDragEnterEvent* event) override;
  void dropEvent(QDropEvent* event) override;

 private:
  void createServices(const WorkbenchOptions& options);
  void createDocks();
  void createFileMenu();
  /// Import and export of tool-path files, enabled as the document allows.
  void addPathFileActions(QMenu* file);
  void createEditMenu();
  void createViewMenu();
  void registerDefaultPanels();
  void updateTitle();
  void updateStatus();
  QMenu* menuNamed(const QString& title);

  WorkbenchDialogs dialogs_;
  VtkView* view_ = nullptr;
  QTabWidget* centralTabs_ = nullptr;
  MouldView* mouldView_ = nullptr;
  CameraToolBar* cameraBar_ = nullptr;
  QLabel* status_ = nullptr;
  JobProgressWidget* jobProgress_ = nullptr;
  PlotDock* plots_ = nullptr;
  ConsoleDock* console_ = nullptr;
  QMenu* panelsMenu_ = nullptr;
  QMenu* recentMenu_ = nullptr;
  /// Verdict on the part converted last when it is not a valid DDF; shown in the status.
  QString conversionWarning_;
  std::unique_ptr<Document> document_;
  std::unique_ptr<JobRunner> jobs_;
  std::unique_ptr<PartView> partView_;
  std::unique_ptr<RecentFiles> recent_;
  std::unique_ptr<RecoveryManager> recovery_;
  std::unique_ptr<ProjectActions> projectActions_;
  std::unique_ptr<Workbench> workbench_;
  std::vector<Panel*> panels_;
  QSettings* settings_ = nullptr;
};

}  // namespace ddfcam::gui
