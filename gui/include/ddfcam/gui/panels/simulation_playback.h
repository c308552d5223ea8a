// SPDX-License-Identifier: MIT
// ddfcam gui: playback of a planning::LiveSimulation: live surface, tool, timeline, rates,
// collisions, V-convexity events and removed volume per pass.
#pragma once

#include <ddfcam/gui/workbench.h>
#include <ddfcam/gui/adapters/live_surface.h>
#include <ddfcam/planning/simulation/grinding_simulation.h>
#include <ddfcam/planning/simulation/live_simulation.h>
#include <ddfcam/planning/tools/tool.h>

#include <QElapsedTimer>
#include <QString>
#include <QWidget>

#include <array>
#include <cstdint>
#include <deque>
#include <memory>

class QComboBox;
class QLabel;
class QListWidget;
class QProgressBar;
class QPushButton;
class QSlider;
class QTimer;

namespace ddfcam::gui {

/// @brief Parameters of SimulationPlayback.
struct PlaybackParams {
  /// Interval at which the view looks for a newer frame of the simulation, ms (default 5):
  /// shorter than frameIntervalMs, so no published frame waits long.
  int tickMs = 5;
  /// Interval of the frames the simulation publishes while playing, ms
  /// (LiveSimulationParams::frameIntervalS): the display rate (default 25, 40 frames per
  /// second) whatever the simulation's rate, unless it cuts fewer poses per second.
  int frameIntervalMs = 25;
  /// Error bound of the live surface (ch. 7 adaptive triangulation) as a fraction of the
  /// part's bounding-box diagonal (dimensionless). Default 2e-4 (0.02 mm on a 100 mm part), as
  /// DisplayParams::adaptiveEpsFraction.
  double displayEpsFraction = 2e-4;
  /// Overcut against the project's "design" state up to this depth is within tolerance, mm.
  /// Default 0.01.
  double overcutToleranceMm = 0.01;
  /// Largest error of the live surface on the screen, pixels (a view-dependent level of
  /// detail, ddf::viewDependentBounds; never finer than displayEpsFraction). Default 0.5.
  double lodPixelError = 0.5;
  /// Interval at which the view's camera is checked for the level of detail, ms. Default 200.
  int lodCheckMs = 200;
};

/// @brief Controls and state of a playback in the Simulation panel. begin() copies the part
/// into a planning::LiveSimulation of one path (the document is untouched), which cuts on its
/// own thread at the set poses per second and keeps an incremental triangulation of the cut
/// surface; a timer takes its newest frame every tickMs and shows it (surface buffers swapped
/// in place, the tool at the last cut pose with its non-cutting part red on a collision,
/// colliding poses marked and listed, V-convexity poses listed, removed volume per pass, the
/// simulated and the displayed rate, elapsed and remaining time). pause() stops the worker
/// after its current pose, step() cuts exactly one pose, the timeline slider and a click on a
/// listed event seek to a pose (the recorded cut is undone or redone, so the state is that of
/// cutting poses 0..k). At the end, or on apply(), the simulated heights are committed as one
/// undoable SetHeightsCommand that also records a simulation state; cancel() drops the copy
/// and shows the document's surface again. A document edit during playback cancels it.
/// Child object names: "playButton", "pauseButton", "stepButton", "applyPlaybackButton",
/// "cancelPlaybackButton", "speedCombo", "timelineSlider", "playbackProgress",
/// "playbackStatus", "playbackRates", "overcutLabel", "showOvercutButton", "collisionLabel",
/// "collisionList", "vConvexityList", "removalList". With a "design" state in the project
/// every pose is inspected for overcut against it (planning::CutInspection): the largest so
/// far with its pose, which "Show" moves the timeline to.
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
  /// @brief Stops the simulation after its current pose; the playback stays active.
  void pause();
  /// @brief Cuts exactly one pose (begins a playback if none is active; pauses a running one).
  /// @return true if a pose was cut.
  bool step();
  /// @brief Pauses and moves to the state after poses 0..@p posesCut - 1 (clamped to the path).
  /// @return false without a playback.
  bool seek(int posesCut);
  /// @brief Commits the heights cut so far (one undoable edit with a simulation state) and
  /// ends the playback. @return true if committed.
  bool apply();
  /// @brief Ends the playback without touching the document.
  void cancel();
  /// @brief Poses per second while playing; <= 0: as fast as the machine can.
  void setPosesPerSecond(double posesPerSecond);
  /// @brief Mode and checks of the next begin() (a running playback keeps its own).
  void setSimulationParams(const planning::GrindingSimulationParams& params) {
    simulationParams_ = params;
  }

  bool isActive() const { return live_ != nullptr; }
  bool isPlaying() const;
  /// @brief The paused simulation, or null (no playback, or playing).
  const planning::GrindingSimulation* simulation() const;
  /// @brief Poses cut in the frame shown, -1 without a playback.
  int posesCut() const;
  /// @brief The newest frame of the active playback, or null.
  std::shared_ptr<const planning::LiveFrame> latestFrame() const {
    return live_ ? live_->latestFrame() : nullptr;
  }
  /// @brief The surface shown while a playback is active (with its tolerance texture), or null.
  const LiveSurfacePolyData* liveSurface() const { return live_ ? surface_.get() : nullptr; }
  /// @brief Index of the pose the tool is drawn at (last cut pose; 0 before the first cut),
  /// -1 without a playback.
  int shownPose() const;
  /// @brief Frames shown in the last second of playing (0 before one passed).
  double framesPerSecond() const;
  /// @brief Where the tool is drawn along the path, in poses: shownPose() while paused; while
  /// playing slower than the display rate it moves on from there towards the next pose at the
  /// set rate (pose + fraction), so the view shows motion between two cuts. -1 without a
  /// playback.
  double toolPosition() const { return live_ ? toolPosition_ : -1.0; }

 signals:
  /// @brief The playback ended: committed (true) or cancelled (false).
  void ended(bool committed);

 private:
  void buildControls();
  void tick();
  void showLatest();
  void showFrame(const planning::LiveFrame& frame);
  void showReport(const planning::GrindingReport& report);
  void showStatus(const planning::LiveFrame& frame);
  void showOvercut(const planning::LiveFrame& frame);
  void updateControls();
  void restoreDocumentSurface();
  bool checkWorker();
  void finishIfDone();
  /// Hands the camera to the live simulation when it moved (or @p force): the level of detail.
  void updateLevelOfDetail(bool force);
  /// Draws the tool at @p position (poses; a fraction interpolates between two poses).
  void showToolAt(double position);
  /// While playing slower than the display rate: the tool moves on at the set rate.
  void moveToolBetweenPoses();
  /// Back to the last cut pose (after a pause).
  void settleTool();

  Workbench& workbench_;
  PlaybackParams params_;
  planning::GrindingSimulationParams simulationParams_;
  std::unique_ptr<planning::LiveSimulation> live_;
  std::unique_ptr<LiveSurfacePolyData> surface_;
  planning::Tool tool_;
  planning::ToolPath path_;  ///< the path being played (a copy: the selection may change)
  int pathIndex_ = -1;
  double posesPerSecond_ = 30.0;
  std::uint64_t shownSerial_ = 0;
  int shownPosesCut_ = -1;
  std::size_t shownCollisions_ = static_cast<std::size_t>(-1);  ///< markers drawn for these
  std::deque<std::int64_t> frameTimesMs_;  ///< when frames were shown, last second
  std::int64_t shownAtMs_ = 0;             ///< when the frame shown arrived (clock_)
  std::int64_t renderedAtMs_ = 0;          ///< last render requested while playing (clock_)
  double toolPosition_ = 0.0;              ///< see toolPosition()
  bool shownColliding_ = false;            ///< the last cut pose collides
  QElapsedTimer clock_;
  bool committing_ = false;
  QTimer* timer_ = nullptr;
  QTimer* lodTimer_ = nullptr;
  std::array<double, 9> lodView_{};  ///< camera and viewport of the last level of detail
  QPushButton* play_ = nullptr;
  QPushButton* pause_ = nullptr;
  QPushButton* step_ = nullptr;
  QPushButton* apply_ = nullptr;
  QPushButton* cancel_ = nullptr;
  QComboBox* speed_ = nullptr;
  QSlider* timeline_ = nullptr;
  QProgressBar* progress_ = nullptr;
  QLabel* status_ = nullptr;
  QLabel* rates_ = nullptr;
  QLabel* overcut_ = nullptr;
  QPushButton* showOvercut_ = nullptr;
  QLabel* collisionLabel_ = nullptr;
  QListWidget* collisions_ = nullptr;
  QListWidget* vConvexity_ = nullptr;
  QListWidget* removal_ = nullptr;
};

}  // namespace ddfcam::gui
