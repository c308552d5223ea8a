// SPDX-License-Identifier: MIT
// ddfcam gui: SimulationPlayback.
#include <ddfcam/gui/panels/simulation_playback.h>

#include <ddfcam/error.h>
#include <ddfcam/gui/document.h>
#include <ddfcam/gui/document_command.h>
#include <ddfcam/gui/part_geometry.h>
#include <ddfcam/gui/part_view.h>
#include <ddfcam/gui/tool_overlay.h>
#include <ddfcam/gui/vtk_view.h>
#include <ddfcam/planning/model/simulation_states.h>

#include <QComboBox>
#include <QGridLayout>
#include <QLabel>
#include <QListWidget>
#include <QProgressBar>
#include <QPushButton>
#include <QSignalBlocker>
#include <QTimer>
#include <QVBoxLayout>

#include <algorithm>
#include <cmath>

namespace ddfcam::gui {

namespace {

QPushButton* makeButton(const QString& text, const char* name, QWidget* parent) {
  auto* button = new QPushButton(text, parent);
  button->setObjectName(name);
  return button;
}

bool isColliding(const planning::GrindingReport& report, int pose) {
  return std::ranges::binary_search(report.collisions, pose, {}, &planning::CollisionHit::pose);
}

}  // namespace

SimulationPlayback::SimulationPlayback(Workbench& workbench, PlaybackParams params, QWidget* parent)
    : QWidget(parent), workbench_(workbench), params_(params) {
  auto* layout = new QVBoxLayout(this);
  layout->setContentsMargins(0, 0, 0, 0);
  auto* buttons = new QGridLayout;
  play_ = makeButton(tr("Play"), "playButton", this);
  pause_ = makeButton(tr("Pause"), "pauseButton", this);
  step_ = makeButton(tr("Step"), "stepButton", this);
  apply_ = makeButton(tr("Apply"), "applyPlaybackButton", this);
  cancel_ = makeButton(tr("Cancel"), "cancelPlaybackButton", this);
  speed_ = new QComboBox(this);
  speed_->setObjectName("speedCombo");
  for (const int pps : {3, 10, 30, 100, 300}) speed_->addItem(tr("%1 poses/s").arg(pps), pps);
  speed_->addItem(tr("as fast as possible"), 0);
  speed_->setCurrentIndex(2);
  buttons->addWidget(play_, 0, 0);
  buttons->addWidget(pause_, 0, 1);
  buttons->addWidget(step_, 0, 2);
  buttons->addWidget(speed_, 1, 0, 1, 3);
  buttons->addWidget(apply_, 2, 0);
  buttons->addWidget(cancel_, 2, 2);
  layout->addLayout(buttons);
  progress_ = new QProgressBar(this);
  progress_->setObjectName("playbackProgress");
  progress_->setRange(0, 1000);
  layout->addWidget(progress_);
  status_ = new QLabel(this);
  status_->setObjectName("playbackStatus");
  layout->addWidget(status_);
  collisionLabel_ = new QLabel(this);
  collisionLabel_->setObjectName("collisionLabel");
  layout->addWidget(collisionLabel_);
  collisions_ = new QListWidget(this);
  collisions_->setObjectName("collisionList");
  collisions_->setMaximumHeight(70);
  layout->addWidget(collisions_);
  layout->addWidget(new QLabel(tr("Removed volume per pass"), this));
  removal_ = new QListWidget(this);
  removal_->setObjectName("removalList");
  removal_->setMaximumHeight(90);
  layout->addWidget(removal_);

  timer_ = new QTimer(this);
  timer_->setInterval(params_.tickMs);
  connect(timer_, &QTimer::timeout, this, &SimulationPlayback::tick);
  connect(play_, &QPushButton::clicked, this, [this] { play(); });
  connect(pause_, &QPushButton::clicked, this, &SimulationPlayback::pause);
  connect(step_, &QPushButton::clicked, this, [this] { step(); });
  connect(apply_, &QPushButton::clicked, this, [this] { apply(); });
  connect(cancel_, &QPushButton::clicked, this, &SimulationPlayback::cancel);
  connect(speed_, &QComboBox::currentIndexChanged, this,
          [this] { setPosesPerSecond(speed_->currentData().toDouble()); });
  connect(&workbench.document, &Document::changed, this, [this](Changes what) {
    // The playback cuts a copy of what the document held at begin(): an edit makes it stale.
    if (isActive() && !committing_ &&
        (what & (Change::Part | Change::Heights | Change::Tools | Change::Paths)))
      cancel();
  });
  updateControls();
}

SimulationPlayback::~SimulationPlayback() = default;

bool SimulationPlayback::isPlaying() const {
  return timer_->isActive();
}

void SimulationPlayback::setPosesPerSecond(double posesPerSecond) {
  posesPerSecond_ = posesPerSecond;
  const int index = speed_->findData(static_cast<int>(std::lround(std::max(0.0, posesPerSecond))));
  if (index >= 0 && index != speed_->currentIndex()) {
    const QSignalBlocker block(speed_);
    speed_->setCurrentIndex(index);
  }
}

int SimulationPlayback::shownPose() const {
  if (!simulation_) return -1;
  return std::max(0, simulation_->nextPose() - 1);
}

bool SimulationPlayback::begin(int index) {
  if (isActive()) cancel();
  return runUserAction(workbench_.reportError, tr("Play simulation"), [&] {
    const planning::Project& p = workbench_.document.project();
    if (!p.part) throw InvalidInput("there is no part to grind");
    if (index < 0 || index >= static_cast<int>(p.paths.size()))
      throw InvalidInput("select a tool path to play");
    const planning::ToolPath& path = p.paths[static_cast<std::size_t>(index)];
    if (path.tool < 0 || path.tool >= static_cast<int>(p.tools.size()))
      throw InvalidInput("path '" + path.name + "' refers to a missing tool");
    if (path.poses.empty()) throw InvalidInput("path '" + path.name + "' has no poses");
    tool_ = p.tools[static_cast<std::size_t>(path.tool)];
    simulation_ =
        std::make_unique<planning::GrindingSimulation>(*p.part, planning::toolMeshes(tool_), path,
                                                      simulationParams_);
    simulatedPath_ = index;
    credit_ = 0.0;
    secondsPerPose_ = redrawSeconds_ = 0.0;
    sinceRedraw_.invalidate();
    updateView(true);
  });
}

bool SimulationPlayback::play() {
  if (!isActive() && !begin(pathIndex_)) return false;
  if (simulation_->finished()) return false;
  credit_ = 0.0;
  sinceTick_.start();
  timer_->start();
  updateControls();
  return true;
}

void SimulationPlayback::pause() {
  timer_->stop();
  if (isActive()) updateView(true);
}

bool SimulationPlayback::step() {
  if (!isActive() && !begin(pathIndex_)) return false;
  timer_->stop();
  if (simulation_->finished()) return false;
  if (!runUserAction(workbench_.reportError, tr("Step simulation"), [&] { cut(1); })) {
    cancel();
    return false;
  }
  updateView(true);
  finishIfDone();
  return true;
}

int SimulationPlayback::batchSize(double seconds) {
  const int remaining =
      static_cast<int>(simulation_->path().poses.size()) - simulation_->nextPose();
  // The budget caps a frame's cutting time; before the first measurement, one pose.
  const int budget = secondsPerPose_ > 0.0
                         ? std::max(1, static_cast<int>(params_.cutBudgetS / secondsPerPose_))
                         : 1;
  int wanted = budget;
  if (posesPerSecond_ > 0.0) {
    credit_ += posesPerSecond_ * seconds;
    wanted = static_cast<int>(credit_);
  }
  const int n = std::min({wanted, budget, remaining});
  // Poses the budget could not cut are dropped, not owed: a slow part plays slower.
  if (posesPerSecond_ > 0.0) credit_ = std::min(credit_ - n, 1.0);
  return std::max(n, 0);
}

void SimulationPlayback::cut(int poses) {
  const double before = simulation_->report().seconds;
  const int done = simulation_->advance(poses);
  if (done > 0) {
    const double perPose = (simulation_->report().seconds - before) / done;
    secondsPerPose_ = secondsPerPose_ > 0.0 ? 0.5 * (secondsPerPose_ + perPose) : perPose;
  }
}

void SimulationPlayback::tick() {
  if (!isActive()) {
    timer_->stop();
    return;
  }
  const double seconds = sinceTick_.restart() / 1000.0;
  const int n = batchSize(seconds);
  if (n == 0) return;
  // A failed cut is reported once and ends the playback (the next tick would fail again).
  if (!runUserAction(workbench_.reportError, tr("Play simulation"), [&] { cut(n); })) {
    cancel();
    return;
  }
  updateView(false);
  finishIfDone();
}

void SimulationPlayback::finishIfDone() {
  if (simulation_ && simulation_->finished()) {
    timer_->stop();
    apply();
  }
}

void SimulationPlayback::updateView(bool forceSurface) {
  const planning::GrindingReport& report = simulation_->report();
  const planning::ToolPath& path = simulation_->path();
  PartScene& scene = workbench_.partView.scene();
  const bool redraw = forceSurface || !sinceRedraw_.isValid() ||
                      sinceRedraw_.elapsed() / 1000.0 >= params_.redrawCostFactor * redrawSeconds_;
  if (redraw) {
    QElapsedTimer clock;
    clock.start();
    scene.setGeometry(buildPartGeometry(simulation_->workpiece(), DisplayParams{}).scene);
    redrawSeconds_ = clock.elapsed() / 1000.0;
    sinceRedraw_.start();
  }
  const int pose = shownPose();
  showToolOverlay(scene, tool_, path.poses[static_cast<std::size_t>(pose)].pose,
                  isColliding(report, pose));
  std::vector<Eigen::Vector3d> marks;
  for (const planning::CollisionHit& hit : report.collisions)
    marks.push_back(path.poses[static_cast<std::size_t>(hit.pose)].contact);
  showCollisionMarkers(scene, marks);
  if (collisions_->count() != static_cast<int>(report.collisions.size())) {
    collisions_->clear();
    for (const planning::CollisionHit& hit : report.collisions)
      collisions_->addItem(tr("pose %1: %2 points").arg(hit.pose).arg(hit.stubbles));
  }
  removal_->clear();
  for (std::size_t i = 0; i < report.passes.size(); ++i)
    removal_->addItem(tr("pass %1: %2 mm³ (%3 poses)")
                          .arg(i + 1)
                          .arg(report.passes[i].removedVolumeMm3, 0, 'f', 4)
                          .arg(report.passes[i].poseCount));
  workbench_.partView.view().requestRender();
  updateControls();
}

void SimulationPlayback::updateControls() {
  const bool active = isActive();
  const bool playing = isPlaying();
  const int total = active ? static_cast<int>(simulation_->path().poses.size()) : 0;
  const int done = active ? simulation_->nextPose() : 0;
  play_->setEnabled(!playing && (!active || !simulation_->finished()));
  pause_->setEnabled(playing);
  step_->setEnabled(!active || !simulation_->finished());
  apply_->setEnabled(active && done > 0);
  cancel_->setEnabled(active);
  progress_->setValue(total > 0 ? static_cast<int>(1000.0 * done / total) : 0);
  if (!active) {
    status_->setText(tr("No playback"));
    collisionLabel_->setText({});
    return;
  }
  const planning::GrindingReport& report = simulation_->report();
  status_->setText(tr("Pose %1 of %2, removed %3 mm³")
                       .arg(done)
                       .arg(total)
                       .arg(report.removedVolumeMm3, 0, 'f', 4));
  collisionLabel_->setText(tr("Collisions: %1 poses; V-convexity violations: %2 poses")
                               .arg(report.collisions.size())
                               .arg(report.vConvexity.size()));
}

bool SimulationPlayback::apply() {
  if (!isActive() || simulation_->nextPose() == 0) return false;
  timer_->stop();
  // Take the simulation first: the push's change signal must find no playback to cancel.
  std::unique_ptr<planning::GrindingSimulation> simulation = std::move(simulation_);
  const planning::ToolPath& path = simulation->path();
  const int done = simulation->nextPose(), total = static_cast<int>(path.poses.size());
  std::string name = planning::afterPathStateName(path.name);
  if (done < total)
    name += " (poses 1-" + std::to_string(done) + " of " + std::to_string(total) + ")";
  const QString title = tr("Play simulation of '%1'").arg(QString::fromStdString(path.name));
  committing_ = true;
  const bool ok = runUserAction(workbench_.reportError, title, [&] {
    const std::vector<float>& heights = simulation->workpiece().allHeights();
    workbench_.document.push(std::make_unique<SetHeightsCommand>(
        workbench_.document, title, heights, planning::SimulationState{name, heights}));
  });
  committing_ = false;
  if (!ok) restoreDocumentSurface();
  hideToolOverlay(workbench_.partView.scene());
  updateControls();
  emit ended(ok);
  return ok;
}

void SimulationPlayback::cancel() {
  timer_->stop();
  if (!simulation_) return;
  simulation_.reset();
  restoreDocumentSurface();
  updateControls();
  emit ended(false);
}

void SimulationPlayback::restoreDocumentSurface() {
  PartView& view = workbench_.partView;
  hideToolOverlay(view.scene());
  showCollisionMarkers(view.scene(), {});
  if (const PartGeometry* geometry = view.geometry()) view.scene().setGeometry(geometry->scene);
  // setGeometry dropped the field colouring; re-applying the colour map restores it.
  if (!view.fieldDisplay().field.empty()) view.setColourMap(view.fieldDisplay().map);
  view.view().requestRender();
}

}  // namespace ddfcam::gui
