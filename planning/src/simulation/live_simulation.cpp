// SPDX-License-Identifier: MIT
// ddfcam: LiveSimulation: the worker that cuts at a set rate and publishes display frames.
#include <ddfcam/ddf/incremental_triangulation.h>
#include <ddfcam/error.h>
#include <ddfcam/planning/simulation/live_simulation.h>

#include <algorithm>
#include <atomic>
#include <chrono>
#include <deque>
#include <mutex>
#include <string>
#include <thread>

namespace ddfcam::planning {
namespace {

using Clock = std::chrono::steady_clock;

double secondsBetween(Clock::time_point a, Clock::time_point b) {
  return std::chrono::duration<double>(b - a).count();
}

GrindingSimulationParams withUndo(GrindingSimulationParams params) {
  params.recordUndo = true;  // seek() goes back
  return params;
}

// Longest single sleep of the worker, so that pause() never waits for a slow rate.
constexpr auto kMaxSleep = std::chrono::milliseconds(5);
// Poses a slow machine may owe the set rate: more are dropped rather than cut in a burst.
constexpr double kMaxCredit = 2.0;

// Frame deadlines on a fixed grid of the interval: a frame is due after the first pose that
// ends past the deadline, and the next deadline is one interval after the last one, not after
// the frame. (Counted from the frame, the frame rate would fall to 1 / (interval rounded up to
// whole poses): 33 instead of 40 frames per second at 100 poses per second.) A deadline missed
// by more than an interval is dropped rather than made up in a burst.
class FrameClock {
 public:
  explicit FrameClock(double intervalS)
      : interval_(std::chrono::duration_cast<Clock::duration>(
            std::chrono::duration<double>(std::max(intervalS, 0.0)))),
        deadline_(Clock::now() + interval_) {}
  bool due(Clock::time_point now) {
    if (now < deadline_) return false;
    deadline_ += interval_;
    if (deadline_ <= now) deadline_ = now + interval_;
    return true;
  }

 private:
  Clock::duration interval_;
  Clock::time_point deadline_;
};

}  // namespace

struct LiveSimulation::State {
  GrindingSimulation simulation;
  LiveSimulationParams params;
  std::unique_ptr<ddf::IncrementalTriangulation> display;
  std::optional<CutInspection> inspection;
  std::optional<LiveToleranceMap> tolerance;
  std::thread worker;
  std::atomic<bool> stop{false}, playing{false};
  std::atomic<double> posesPerSecond{30.0};
  mutable std::mutex frameMutex;
  std::shared_ptr<const LiveFrame> frame;
  std::mutex errorMutex;
  std::exception_ptr error;
  std::uint64_t serial = 0;
  double elapsedSeconds = 0.0;  // playing time of finished plays
  Clock::time_point playStart;
  std::deque<Clock::time_point> recentPoses;  // poses cut in the last second
  double lastUpdateSeconds = 0.0;
  std::mutex viewMutex;
  std::optional<ddf::ViewBoundsParams> pendingView;  // set by the viewer, taken by publish()
  std::optional<ddf::ViewBoundsParams> view;         // in force
  double budgetFactor = 1.0;                         // pixel error multiplier for the budget

  State(ddf::DisplacementField workpiece, const ToolMeshes& tool, const ToolPath& path,
        const LiveSimulationParams& p)
      : simulation(std::move(workpiece), tool, path, withUndo(p.simulation)), params(p) {
    posesPerSecond = p.posesPerSecond;
    display = std::make_unique<ddf::IncrementalTriangulation>(simulation.workpiece(),
                                                              p.displayEpsMm);
    if (!p.designHeights.empty()) {
      ddf::DisplacementField design = simulation.workpiece();
      if (p.designHeights.size() != design.allHeights().size())
        throw InvalidInput("LiveSimulation: the design has " +
                           std::to_string(p.designHeights.size()) + " heights, the part " +
                           std::to_string(design.allHeights().size()));
      design.allHeights() = p.designHeights;
      tolerance.emplace(design, p.toleranceBand);
      tolerance->updateAll(simulation.workpiece());
      inspection.emplace(std::move(design), p.overcutToleranceMm);
    }
  }

  // Cuts the next pose and inspects it.
  void cutOne() {
    simulation.advance(1);
    if (inspection) inspection->follow(simulation);
  }

  double playingSeconds() const {
    return elapsedSeconds + (playing ? secondsBetween(playStart, Clock::now()) : 0.0);
  }

  void notePose(Clock::time_point at) {
    recentPoses.push_back(at);
    while (!recentPoses.empty() && secondsBetween(recentPoses.front(), at) > 1.0)
      recentPoses.pop_front();
  }

  double poseRate() const {
    if (recentPoses.size() < 2) return 0.0;
    const double span = secondsBetween(recentPoses.front(), recentPoses.back());
    return span > 0.0 ? (recentPoses.size() - 1) / span : 0.0;
  }

  void publish();
  bool applyView();
  // The view's bounds as the display takes them: the budget's pixel error, displayEpsMm up to
  // coarsestEpsFactor times it.
  ddf::ViewBoundsParams bounds(const ddf::ViewBoundsParams& camera) const;
  void copyTriangles(LiveFrame& out) const;
  void run();
  void join() {
    stop = true;
    if (worker.joinable()) worker.join();
    stop = false;
  }
};

// Takes a new view, or coarsens the current one while the mesh exceeds the triangle budget;
// true if the bounds were set again (the budget is then checked once more).
bool LiveSimulation::State::applyView() {
  bool dirty = false;
  {
    const std::lock_guard lock(viewMutex);
    if (pendingView) {
      view = std::exchange(pendingView, std::nullopt);
      budgetFactor = 1.0;
      dirty = true;
    }
  }
  if (!view) return false;
  if (!dirty && display->triangleCount() > params.triangleBudget && budgetFactor < 16.0) {
    budgetFactor *= 2.0;
    dirty = true;
  }
  if (!dirty) return false;
  display->setFaceEps(ddf::viewDependentBounds(simulation.workpiece(), bounds(*view)));
  return true;
}

ddf::ViewBoundsParams LiveSimulation::State::bounds(const ddf::ViewBoundsParams& camera) const {
  ddf::ViewBoundsParams out = camera;
  out.pixelError *= budgetFactor;
  out.minEpsMm = params.displayEpsMm;
  out.maxEpsMm = params.displayEpsMm * std::max(1.0, params.coarsestEpsFactor);
  return out;
}

void LiveSimulation::State::copyTriangles(LiveFrame& out) const {
  const int faces = simulation.workpiece().faceCount();
  out.triangles.reserve(3 * display->triangleCount());
  out.triangleFace.reserve(display->triangleCount());
  if (tolerance) out.cornerParams.reserve(6 * display->triangleCount());
  for (int f = 0; f < faces; ++f) {
    for (const auto& t : display->faceTriangles(f)) {
      out.triangles.insert(out.triangles.end(), t.begin(), t.end());
      out.triangleFace.push_back(f);
    }
    if (!tolerance) continue;
    for (const ddf::TriangleParams& corners : display->faceTriangleParams(f))
      for (const auto& ik : corners) out.cornerParams.insert(out.cornerParams.end(), ik.begin(),
                                                             ik.end());
  }
  if (tolerance) out.toleranceClasses = tolerance->classes();
}

void LiveSimulation::State::publish() {
  const auto start = Clock::now();
  const std::vector<int> changed = simulation.takeChangedFaces();
  if (!changed.empty()) display->update(changed);
  if (tolerance) tolerance->update(simulation.workpiece(), changed);
  while (applyView()) {
  }
  lastUpdateSeconds = secondsBetween(start, Clock::now());
  auto out = std::make_shared<LiveFrame>();
  out->serial = ++serial;
  out->posesCut = simulation.nextPose();
  out->totalPoses = static_cast<int>(simulation.path().poses.size());
  out->faceCount = simulation.workpiece().faceCount();
  out->rasterSteps = simulation.workpiece().raster().steps();
  out->report = simulation.report();
  const auto& vertices = display->vertices();
  const auto& normals = display->normals();
  out->positions.resize(3 * vertices.size());
  out->normals.resize(3 * vertices.size());
  for (std::size_t v = 0; v < vertices.size(); ++v)
    for (int c = 0; c < 3; ++c) {
      out->positions[3 * v + c] = static_cast<float>(vertices[v][c]);
      out->normals[3 * v + c] = static_cast<float>(normals[v][c]);
    }
  copyTriangles(*out);
  out->simulatedPosesPerSecond = poseRate();
  out->displayUpdateSeconds = lastUpdateSeconds;
  out->viewPixelError = view ? view->pixelError * budgetFactor : 0.0;
  if (view) out->faceEps = display->faceEps();
  out->elapsedSeconds = playingSeconds();
  if (inspection) {
    inspection->follow(simulation);
    out->inspected = true;
    out->largestOvercut = inspection->largest();
    out->overcutPoses = inspection->overcutPoses();
  }
  const std::lock_guard lock(frameMutex);
  frame = std::move(out);
}

void LiveSimulation::State::run() {
  try {
    FrameClock frames(params.frameIntervalS);
    Clock::time_point last = Clock::now();
    double credit = 1.0;  // the first pose at once
    while (!stop && !simulation.finished()) {
      const double rate = posesPerSecond.load();
      const Clock::time_point now = Clock::now();
      if (rate > 0.0) {
        credit = std::min(credit + rate * secondsBetween(last, now), kMaxCredit);
        last = now;
        if (credit < 1.0) {
          const auto due = std::chrono::duration<double>((1.0 - credit) / rate);
          std::this_thread::sleep_for(
              std::min(std::chrono::duration_cast<Clock::duration>(due),
                       std::chrono::duration_cast<Clock::duration>(kMaxSleep)));
          continue;
        }
        credit -= 1.0;
      }
      cutOne();
      notePose(Clock::now());
      if (frames.due(Clock::now())) publish();
    }
  } catch (...) {
    const std::lock_guard lock(errorMutex);
    error = std::current_exception();
  }
  // The time is booked before the last frame, and playing cleared after it, so that a viewer
  // that sees the worker stopped also sees its final frame.
  elapsedSeconds += secondsBetween(playStart, Clock::now());
  playStart = Clock::now();
  try {
    publish();
  } catch (...) {
    const std::lock_guard lock(errorMutex);
    if (!error) error = std::current_exception();
  }
  playing = false;
}

LiveSimulation::LiveSimulation(ddf::DisplacementField workpiece, const ToolMeshes& tool,
                               const ToolPath& path, LiveSimulationParams params) {
  if (!(params.displayEpsMm > 0.0))
    throw InvalidInput("LiveSimulation: the display error bound must be > 0 mm, got " +
                       std::to_string(params.displayEpsMm));
  state_ = std::make_unique<State>(std::move(workpiece), tool, path, params);
  state_->publish();
}

LiveSimulation::~LiveSimulation() {
  state_->join();
}

bool LiveSimulation::play() {
  State& s = *state_;
  if (s.playing) return true;
  s.join();  // a worker that ran to the end
  if (s.simulation.finished()) return false;
  s.recentPoses.clear();
  s.playStart = Clock::now();
  s.playing = true;
  s.worker = std::thread([&s] { s.run(); });
  return true;
}

void LiveSimulation::pause() {
  state_->join();
}

bool LiveSimulation::step() {
  pause();
  State& s = *state_;
  if (s.simulation.finished()) return false;
  s.cutOne();
  s.publish();
  return true;
}

void LiveSimulation::seek(int pose) {
  pause();
  state_->simulation.seek(pose);
  state_->publish();
}

void LiveSimulation::setView(const ddf::ViewBoundsParams& view) {
  State& s = *state_;
  ddf::validateViewBounds(s.bounds(view));
  {
    const std::lock_guard lock(s.viewMutex);
    s.pendingView = view;
  }
  if (!s.playing) s.publish();
}

void LiveSimulation::setPosesPerSecond(double posesPerSecond) {
  state_->posesPerSecond = posesPerSecond;
}

bool LiveSimulation::isPlaying() const {
  return state_->playing;
}

bool LiveSimulation::finished() const {
  return !state_->playing && state_->simulation.finished();
}

std::shared_ptr<const LiveFrame> LiveSimulation::latestFrame() const {
  const std::lock_guard lock(state_->frameMutex);
  return state_->frame;
}

std::exception_ptr LiveSimulation::takeError() {
  const std::lock_guard lock(state_->errorMutex);
  return std::exchange(state_->error, nullptr);
}

const GrindingSimulation& LiveSimulation::simulation() const {
  if (state_->playing)
    throw InvalidInput("LiveSimulation::simulation: pause the playback before reading its state");
  return state_->simulation;
}

}  // namespace ddfcam::planning
