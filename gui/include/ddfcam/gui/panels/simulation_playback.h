// SPDX-License-Identifier: MIT
// ddfcam gui: step-by-step playback of a planning::GrindingSimulation with live surface, tool,
// collisions and removed volume per pass.
#pragma once

#include <ddfcam/gui/workbench.h>
#include <ddfcam/planning/simulation/grinding_simulation.h>

#include <QElapsedTimer>
#include <QString>
#include <QWidget>

#include <memory>

class QComboBox;
class QLabel;
class QListWidget;
class QProgressBar;
class QPushButton;
class QTimer;

namespace ddfcam::gui {

/// @brief Parameters of SimulationPlayback.
struct PlaybackParams {
  int tickMs = 30;  ///< timer interval between playback frames, ms (default 30)
  /// Cutting time allowed per frame, s: the batch of poses per frame is chosen from the
  /// measured time per pose so the UI stays responsive. Default 0.02.
  double cutBudgetS = 0.02;
  /// The surface is re-uploaded to the view at most once per this many times its measured
  /// rebuild time, so a large part (slow to triangulate) does not stall playback. Default 2.
  double redrawCostFactor = 2.0;
};

/// @brief Controls and state of a playback in the Simulation panel. begin() copies the part
/// into a planning::GrindingSimulation of one path (the document is untouched); play() cuts a
/// batch of poses per timer tick (speed in poses per second, or as fast as the per-frame budget
/// allows), pause() stops, step() cuts exactly one pose. Every frame re-uploads the simulated
/// surface to the part view, draws the tool at the last cut pose (cutting and non-cutting
/// parts, the latter red on a collision), marks colliding poses, lists them and the removed
/// volume per pass. At the end, or on apply(), the simulated heights are committed as one
/// undoable SetHeightsCommand that also records a simulation state; cancel() drops the copy
/// and shows the document's surface again. A document edit during playback cancels it.
/// Child object names: "playButton", "pauseButton", "stepButton", "applyPlaybackButton",
/// "cancelPlaybackButton", "speedCombo", "playbackProgress", "playbackStatus",
/// "collisionLabel", "collisionList", "removalList".
class SimulationPlayback : public QWidget {
  Q_OBJECT

 public:
  explicit SimulationPlayback(Workbench& workbench, PlaybackParams params = {},
                              QWidget* parent = nullptr);
  ~SimulationPlayback() override;

  /// @brief The path the next begin() (or play/step without a playback) simulates.
  void setPathIndex(int index) { pathIndex_ = index; }
  /// @brief Starts a playback of path @p index on a copy of the part (cancels one running).
  /// @return false (error reported) if there is no part, no such path or its tool is unusable.
  bool begin(int index);
  /// @brief Plays (begins a playback of the set path if none is active). @return true if playing.
  bool play();
  /// @brief Stops the timer; the playback stays active.
  void pause();
  /// @brief Cuts exactly one pose (begins a playback if none is active; pauses a running one).
  /// @return true if a pose was cut.
  bool step();
  /// @brief Commits the heights cut so far (one undoable edit with a simulation state) and
  /// ends the playback. @return true if committed.
  bool apply();
  /// @brief Ends the playback without touching the document.
  void cancel();
  /// @brief Poses per second while playing; <= 0: as fast as the frame budget allows.
  void setPosesPerSecond(double posesPerSecond);
  /// @brief Mode and checks of the next begin() (a running playback keeps its own).
  void setSimulationParams(const planning::GrindingSimulationParams& params) {
    simulationParams_ = params;
  }

  bool isActive() const { return simulation_ != nullptr; }
  bool isPlaying() const;
  /// @brief The running simulation, or null.
  const planning::GrindingSimulation* simulation() const { return simulation_.get(); }
  /// @brief Index of the pose the tool is drawn at (last cut pose; 0 before the first cut),
  /// -1 without a playback.
  int shownPose() const;

 signals:
  /// @brief The playback ended: committed (true) or cancelled (false).
  void ended(bool committed);

 private:
  void tick();
  int batchSize(double seconds);
  void cut(int poses);
  void updateView(bool forceSurface);
  void updateControls();
  void restoreDocumentSurface();
  void finishIfDone();

  Workbench& workbench_;
  PlaybackParams params_;
  planning::GrindingSimulationParams simulationParams_;
  std::unique_ptr<planning::GrindingSimulation> simulation_;
  planning::Tool tool_;
  int pathIndex_ = -1;
  int simulatedPath_ = -1;
  double posesPerSecond_ = 30.0;
  double credit_ = 0.0;        ///< poses owed to the speed since the last tick
  double secondsPerPose_ = 0;  ///< measured cut time per pose (0: unknown)
  double redrawSeconds_ = 0;   ///< measured surface rebuild time
  bool committing_ = false;
  QElapsedTimer sinceTick_, sinceRedraw_;
  QTimer* timer_ = nullptr;
  QPushButton* play_ = nullptr;
  QPushButton* pause_ = nullptr;
  QPushButton* step_ = nullptr;
  QPushButton* apply_ = nullptr;
  QPushButton* cancel_ = nullptr;
  QComboBox* speed_ = nullptr;
  QProgressBar* progress_ = nullptr;
  QLabel* status_ = nullptr;
  QLabel* collisionLabel_ = nullptr;
  QListWidget* collisions_ = nullptr;
  QListWidget* removal_ = nullptr;
};

}  // namespace ddfcam::gui
