// SPDX-License-Identifier: MIT
// ddfcam gui: the Simulation panel: tools, tool paths, grinding a path, simulation states.
#pragma once

#include <ddfcam/gui/job_runner.h>
#include <ddfcam/gui/workbench.h>
#include <ddfcam/planning/model/tool_path.h>
#include <ddfcam/planning/tools/tool.h>

class QDoubleSpinBox;
class QLabel;
class QListWidget;
class QPushButton;
class QSpinBox;

namespace ddfcam::gui {

class SimulationOptions;
class SimulationPlayback;

/// @brief Lists tools, paths and simulation states. Selecting a path shows its tool at the
/// first pose (cutting and non-cutting parts); the playback controls play the selected path
/// pose by pose (SimulationPlayback); "Simulate" grinds the selected path into a copy of the part
/// as a job with the SimulationOptions (planning::simulateGrinding, or planning::prestonStage
/// for the Preston model), prints the report to the console and the "simulationReport" label, and
/// commits the new heights as one undoable edit that also records a simulation state;
/// "Restore" sets the heights of a recorded state (undoable). Workpiece set-up ("allowanceSpin",
/// "raiseAllowanceButton", "stockMeshButton", "workpieceLabel") and penetration correction
/// ("correctionGridSpin", "correctionEverySpin", "correctPenetrationsButton",
/// "correctionLabel") run as jobs and commit one undoable edit each.
class SimulationPanel : public Panel {
  Q_OBJECT

 public:
  explicit SimulationPanel(Workbench& workbench, QWidget* parent = nullptr);
  QString title() const override { return tr("Simulation"); }
  QString id() const override { return "simulation"; }
  QString menuTitle() const override { return tr("&Simulate"); }
  QList<QAction*> menuActions() const override { return actions_; }

  /// @brief Starts grinding path @p index (the Simulate button). A path of more than
  /// longPathPoses() poses is first announced with its estimated time
  /// (planning::estimateSimulation, Workbench::confirmLongJob). @return true if started.
  bool simulatePath(int index);
  /// @brief Paths with more poses than this are announced before Simulate (default 5,000).
  int longPathPoses() const { return longPathPoses_; }
  void setLongPathPoses(int poses) { longPathPoses_ = poses; }
  /// @brief Sets the part's heights to those of state @p index (undoable).
  /// @return true if done.
  bool restoreState(int index);
  /// @brief Raises the part's heights by a stock allowance along the surface normal
  /// (planning::workpieceWithAllowance) as a job; the edit also records the result as a state
  /// "stock +<a> mm", preceded (same undo step) by a state "design" of the current heights if
  /// none exists. @return true if started.
  bool raiseByAllowance(double allowanceMm);
  /// @brief Replaces the part's heights by the stock mesh in file @p path converted onto the
  /// part's support (planning::workpieceFromStockMesh, points it misses keep their height and
  /// are counted in the console and "workpieceLabel") as a job. @return true if started.
  bool stockFromMesh(const QString& path);
  /// @brief Lifts the poses of path @p index off the part's current surface
  /// (planning::correctPathPenetrations with @p gridSize and @p every) as a job, committed as one
  /// ReplacePathCommand; "correctionLabel" shows the lifts. @return true if started.
  bool correctPenetrations(int index, int gridSize = 50, int every = 1);
  /// @brief Sets the feed of path @p index (ToolPath::feedMmPerMin, mm/min), as an edit of the
  /// options' feed does for the selected path: one ReplacePathCommand. The Preston model and
  /// exported programs both use this feed. @return true if the feed changed.
  bool setPathFeed(int index, double feedMmPerMin);
  /// @brief Mode, checks and removal model used by Simulate and the playback.
  SimulationOptions& options() const { return *options_; }
  /// @brief The playback controls (play, pause, step, speed, apply, cancel) of the selected
  /// path.
  SimulationPlayback& playback() const { return *playback_; }

 private:
  void refresh();
  void showToolOfSelectedPath();
  /// Shows the selected path's feed in the options (the Preston feed is the path's).
  void showFeedOfSelectedPath();
  void applyOptions();
  QWidget* makeWorkpieceGroup();
  QWidget* makeCorrectionGroup();
  bool startJob(const QString& title, JobWork work);
  bool confirmLongPath(const planning::ToolPath& path, const planning::Tool& tool);
  void report(const QString& text, QLabel* label);

  int longPathPoses_ = 5'000;
  QList<QAction*> actions_;
  QListWidget* tools_ = nullptr;
  QListWidget* paths_ = nullptr;
  QListWidget* states_ = nullptr;
  QPushButton* simulate_ = nullptr;
  QPushButton* restore_ = nullptr;
  SimulationPlayback* playback_ = nullptr;
  SimulationOptions* options_ = nullptr;
  QLabel* report_ = nullptr;
  QDoubleSpinBox* allowance_ = nullptr;
  QPushButton* raise_ = nullptr;
  QPushButton* stockMesh_ = nullptr;
  QLabel* workpieceLabel_ = nullptr;
  QSpinBox* correctionGrid_ = nullptr;
  QSpinBox* correctionEvery_ = nullptr;
  QPushButton* correct_ = nullptr;
  QLabel* correctionLabel_ = nullptr;
};

}  // namespace ddfcam::gui
