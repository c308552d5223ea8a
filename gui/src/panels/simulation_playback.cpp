// SPDX-License-Identifier: MIT
// ddfcam gui: SimulationPlayback: controls, the live simulation's lifetime, commit and cancel.
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
#include <QHBoxLayout>
#include <QLabel>
#include <QListWidget>
#include <QProgressBar>
#include <QPushButton>
#include <QSignalBlocker>
#include <QSlider>
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

QListWidget* makeList(const char* name, int height, QWidget* parent) {
  auto* list = new QListWidget(parent);
  list->setObjectName(name);
  list->setMaximumHeight(height);
  return list;
}

// Bounding-box diagonal of the support, mm: the display bound scales with the part.
double supportDiagonalMm(const ddf::DisplacementField& ddf) {
  if (ddf.vertexCount() == 0) return 1.0;
  ddf::Vec3 lo = ddf.position(0), hi = lo;
  for (int v = 1; v < ddf.vertexCount(); ++v) {
    lo = lo.cwiseMin(ddf.position(v));
    hi = hi.cwiseMax(ddf.position(v));
  }
  return std::max((hi - lo).norm(), 1e-3);
}

}  // namespace

SimulationPlayback::SimulationPlayback(Workbench& workbench, PlaybackParams params, QWidget* parent)
    : QWidget(parent), workbench_(workbench), params_(params) {
  buildControls();
  timer_ = new QTimer(this);
  timer_->setInterval(params_.tickMs);
  connect(timer_, &QTimer::timeout, this, &SimulationPlayback::tick);
  lodTimer_ = new QTimer(this);
  lodTimer_->setInterval(params_.lodCheckMs);
  connect(lodTimer_, &QTimer::timeout, this, [this] { updateLevelOfDetail(false); });
  connect(play_, &QPushButton::clicked, this, [this] { play(); });
  connect(pause_, &QPushButton::clicked, this, &SimulationPlayback::pause);
  connect(step_, &QPushButton::clicked, this, [this] { step(); });
  connect(apply_, &QPushButton::clicked, this, [this] { apply(); });
  connect(cancel_, &QPushButton::clicked, this, &SimulationPlayback::cancel);
  connect(speed_, &QComboBox::currentIndexChanged, this,
          [this] { setPosesPerSecond(speed_->currentData().toDouble()); });
  connect(timeline_, &QSlider::valueChanged, this, [this](int value) {
    if (isActive() && value != shownPosesCut_) seek(value);
  });
  connect(showOvercut_, &QPushButton::clicked, this, [this] {
    if (!isActive()) return;
    if (const auto& worst = live_->latestFrame()->largestOvercut) seek(worst->pose + 1);
  });
  // A listed event moves the timeline to the state just after its pose (tool drawn there).
  for (QListWidget* list : {collisions_, vConvexity_})
    connect(list, &QListWidget::itemClicked, this,
            [this](QListWidgetItem* item) { seek(item->data(Qt::UserRole).toInt() + 1); });
  connect(&workbench.document, &Document::changed, this, [this](Changes what) {
    // The playback cuts a copy of what the document held at begin(): an edit makes it stale.
    if (isActive() && !committing_ &&
        (what & (Change::Part | Change::Heights | Change::Tools | Change::Paths)))
      cancel();
  });
  clock_.start();
  updateControls();
}

SimulationPlayback::~SimulationPlayback() = default;

void SimulationPlayback::buildControls() {
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
  timeline_ = new QSlider(Qt::Horizontal, this);
  timeline_->setObjectName("timelineSlider");
  timeline_->setToolTip(tr("Timeline: drag to show the part after any pose"));
  layout->addWidget(timeline_);
  progress_ = new QProgressBar(this);
  progress_->setObjectName("playbackProgress");
  progress_->setRange(0, 1000);
  layout->addWidget(progress_);
  for (auto [label, name] : {std::pair{&status_, "playbackStatus"}, {&rates_, "playbackRates"},
                             {&collisionLabel_, "collisionLabel"}}) {
    *label = new QLabel(this);
    (*label)->setObjectName(name);
    (*label)->setWordWrap(true);
    // Never squeezed below their wrapped text by the lists (the panel is scrolled instead).
    (*label)->setSizePolicy(QSizePolicy::Preferred, QSizePolicy::Minimum);
    layout->addWidget(*label);
  }
  overcut_ = new QLabel(this);
  overcut_->setObjectName("overcutLabel");
  overcut_->setWordWrap(true);
  overcut_->setSizePolicy(QSizePolicy::Preferred, QSizePolicy::Minimum);
  layout->addWidget(overcut_);
  auto* overcutRow = new QHBoxLayout;
  showOvercut_ = makeButton(tr("Show the largest overcut"), "showOvercutButton", this);
  showOvercut_->setToolTip(tr("Move the timeline to the pose of the largest overcut"));
  overcutRow->addStretch(1);
  overcutRow->addWidget(showOvercut_);
  layout->addLayout(overcutRow);
  layout->addWidget(new QLabel(tr("Collisions (click: show the pose)"), this));
  collisions_ = makeList("collisionList", 70, this);
  layout->addWidget(collisions_);
  layout->addWidget(new QLabel(tr("V-convexity violations (click: show the pose)"), this));
  vConvexity_ = makeList("vConvexityList", 70, this);
  layout->addWidget(vConvexity_);
  layout->addWidget(new QLabel(tr("Removed volume per pass"), this));
  removal_ = makeList("removalList", 90, this);
  layout->addWidget(removal_);
}

bool SimulationPlayback::isPlaying() const {
  return live_ && live_->isPlaying();
}

const planning::GrindingSimulation* SimulationPlayback::simulation() const {
  return live_ && !live_->isPlaying() ? &live_->simulation() : nullptr;
}

int SimulationPlayback::posesCut() const {
  return live_ ? live_->latestFrame()->posesCut : -1;
}

int SimulationPlayback::shownPose() const {
  return live_ ? std::max(0, shownPosesCut_ - 1) : -1;
}

void SimulationPlayback::setPosesPerSecond(double posesPerSecond) {
  posesPerSecond_ = posesPerSecond;
  if (live_) live_->setPosesPerSecond(posesPerSecond);
  const int index = speed_->findData(static_cast<int>(std::lround(std::max(0.0, posesPerSecond))));
  if (index >= 0 && index != speed_->currentIndex()) {
    const QSignalBlocker block(speed_);
    speed_->setCurrentIndex(index);
  }
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
    path_ = path;
    planning::LiveSimulationParams live;
    live.simulation = simulationParams_;
    live.displayEpsMm = params_.displayEpsFraction * supportDiagonalMm(*p.part);
    live.posesPerSecond = posesPerSecond_;
    live.frameIntervalS = params_.frameIntervalMs / 1000.0;
    if (const planning::SimulationState* design = planning::designState(p.states))
      if (design->heights.size() == p.part->allHeights().size()) {
        live.designHeights = design->heights;
        live.overcutToleranceMm = params_.overcutToleranceMm;
        live.toleranceBand = {-params_.overcutToleranceMm, params_.overcutToleranceMm};
      }
    live_ = std::make_unique<planning::LiveSimulation>(*p.part, planning::toolMeshes(tool_), path,
                                                       live);
    const bool inspected = !live.designHeights.empty();
    surface_ = std::make_unique<LiveSurfacePolyData>(inspected ? p.part->faceCount() : 0,
                                                     p.part->raster().steps());
    SceneGeometry scene;
    scene.surface = surface_->polyData();
    scene.surfaceTexture = surface_->texture();
    surface_->uploadBeforeRendering(workbench_.partView.view().renderer());
    if (const PartGeometry* shown = workbench_.partView.geometry()) {
      scene.support = shown->scene.support;  // the support and the stubbles do not change
      scene.stubbles = shown->scene.stubbles;
    }
    workbench_.partView.scene().setGeometry(scene);
    const QSignalBlocker block(timeline_);
    timeline_->setRange(0, static_cast<int>(path.poses.size()));
    shownSerial_ = 0;
    shownCollisions_ = static_cast<std::size_t>(-1);
    frameTimesMs_.clear();
    updateLevelOfDetail(true);
    lodTimer_->start();
    showLatest();
  });
}

bool SimulationPlayback::play() {
  if (!isActive() && !begin(pathIndex_)) return false;
  live_->setPosesPerSecond(posesPerSecond_);
  if (!live_->play()) return false;
  frameTimesMs_.clear();
  workbench_.partView.view().setMotionRendering(true);
  timer_->start();
  updateControls();
  return true;
}

void SimulationPlayback::pause() {
  timer_->stop();
  workbench_.partView.view().setMotionRendering(false);
  if (!isActive()) return;
  live_->pause();
  if (!checkWorker()) return;
  showLatest();
  settleTool();
}

bool SimulationPlayback::step() {
  if (!isActive() && !begin(pathIndex_)) return false;
  timer_->stop();
  bool cut = false;
  if (!runUserAction(workbench_.reportError, tr("Step simulation"),
                     [&] { cut = live_->step(); })) {
    cancel();
    return false;
  }
  showLatest();
  finishIfDone();
  return cut;
}

bool SimulationPlayback::seek(int posesCut) {
  if (!isActive()) return false;
  timer_->stop();
  const int total = live_->latestFrame()->totalPoses;
  const bool ok = runUserAction(workbench_.reportError, tr("Move the timeline"),
                                [&] { live_->seek(std::clamp(posesCut, 0, total)); });
  showLatest();
  return ok;
}

void SimulationPlayback::tick() {
  if (!isActive()) {
    timer_->stop();
    return;
  }
  if (!checkWorker()) return;
  showLatest();
  if (live_->isPlaying()) moveToolBetweenPoses();
  if (!live_->isPlaying()) {
    timer_->stop();
    workbench_.partView.view().setMotionRendering(false);
    showLatest();  // the worker's final frame
    settleTool();
    finishIfDone();
    updateControls();
  }
}

bool SimulationPlayback::checkWorker() {
  if (std::exception_ptr error = live_->takeError()) {
    // A failed cut is reported once and ends the playback (the next pose would fail again).
    runUserAction(workbench_.reportError, tr("Play simulation"),
                  [&] { std::rethrow_exception(error); });
    cancel();
    return false;
  }
  return true;
}

void SimulationPlayback::finishIfDone() {
  if (live_ && live_->finished() && posesCut() == live_->latestFrame()->totalPoses) apply();
}

bool SimulationPlayback::apply() {
  if (!isActive()) return false;
  timer_->stop();
  lodTimer_->stop();
  workbench_.partView.view().setMotionRendering(false);
  live_->pause();
  if (live_->simulation().nextPose() == 0) return false;
  // Take the simulation first: the push's change signal must find no playback to cancel.
  std::unique_ptr<planning::LiveSimulation> live = std::move(live_);
  surface_.reset();
  const planning::GrindingSimulation& simulation = live->simulation();
  const planning::ToolPath& path = simulation.path();
  const int done = simulation.nextPose(), total = static_cast<int>(path.poses.size());
  std::string name = planning::afterPathStateName(path.name);
  if (done < total)
    name += " (poses 1-" + std::to_string(done) + " of " + std::to_string(total) + ")";
  const QString title = tr("Play simulation of '%1'").arg(QString::fromStdString(path.name));
  committing_ = true;
  const bool ok = runUserAction(workbench_.reportError, title, [&] {
    const std::vector<float>& heights = simulation.workpiece().allHeights();
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
  lodTimer_->stop();
  workbench_.partView.view().setMotionRendering(false);
  if (!live_) return;
  live_.reset();
  surface_.reset();
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
