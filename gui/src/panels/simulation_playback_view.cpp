// SPDX-License-Identifier: MIT
// ddfcam gui: SimulationPlayback: showing a frame of the live simulation (surface, tool,
// events, volumes, timeline, progress with the simulated and the displayed rate).
#include <ddfcam/gui/panels/simulation_playback.h>

#include <ddfcam/gui/duration_text.h>
#include <ddfcam/gui/part_view.h>
#include <ddfcam/gui/tool_overlay.h>
#include <ddfcam/gui/vtk_view.h>

#include <QComboBox>
#include <QLabel>
#include <QListWidget>
#include <QProgressBar>
#include <QPushButton>
#include <QSignalBlocker>
#include <QSlider>

#include <Eigen/Geometry>

#include <algorithm>
#include <cmath>

namespace ddfcam::gui {

namespace {

bool isColliding(const planning::GrindingReport& report, int pose) {
  return std::ranges::binary_search(report.collisions, pose, {}, &planning::CollisionHit::pose);
}


// Refills @p list with one item per event (pose, stubble count) unless it already has them.
template <class Events>
void listEvents(QListWidget* list, const Events& events) {
  if (list->count() == static_cast<int>(events.size())) return;
  list->clear();
  for (const auto& e : events) {
    auto* item = new QListWidgetItem(
        QObject::tr("pose %1: %2 points").arg(e.pose).arg(static_cast<qulonglong>(e.stubbles)),
        list);
    item->setData(Qt::UserRole, e.pose);
  }
}

// The level of detail in force: triangles and the pixel error they keep.
QString detailText(const planning::LiveFrame& frame) {
  const QString triangles = QObject::tr("; %1 triangles").arg(frame.triangleFace.size());
  if (frame.viewPixelError <= 0.0) return triangles;
  return triangles + QObject::tr(" within %1 px").arg(frame.viewPixelError, 0, 'g', 2);
}

}  // namespace

double SimulationPlayback::framesPerSecond() const {
  if (frameTimesMs_.size() < 2) return 0.0;
  const double span = (frameTimesMs_.back() - frameTimesMs_.front()) / 1000.0;
  return span > 0.0 ? (frameTimesMs_.size() - 1) / span : 0.0;
}

void SimulationPlayback::showLatest() {
  if (!live_) return;
  const std::shared_ptr<const planning::LiveFrame> frame = live_->latestFrame();
  if (frame->serial == shownSerial_) return;
  shownSerial_ = frame->serial;
  showFrame(*frame);
}

void SimulationPlayback::showFrame(const planning::LiveFrame& frame) {
  surface_->apply(frame);
  shownPosesCut_ = frame.posesCut;
  const planning::ToolPath& path = path_;
  PartScene& scene = workbench_.partView.scene();
  const int pose = std::max(0, frame.posesCut - 1);
  shownColliding_ = isColliding(frame.report, pose);
  showToolAt(pose);
  shownAtMs_ = renderedAtMs_ = clock_.elapsed();
  // Markers and lists change only with new events: rebuilt then, not every frame.
  if (frame.report.collisions.size() != shownCollisions_) {
    std::vector<Eigen::Vector3d> marks;
    for (const planning::CollisionHit& hit : frame.report.collisions)
      marks.push_back(path.poses[static_cast<std::size_t>(hit.pose)].contact);
    showCollisionMarkers(scene, marks);
    shownCollisions_ = frame.report.collisions.size();
  }
  showReport(frame.report);
  {
    const QSignalBlocker block(timeline_);
    timeline_->setValue(frame.posesCut);
  }
  if (live_->isPlaying()) {  // the display rate counts the frames shown while playing
    frameTimesMs_.push_back(clock_.elapsed());
    while (frameTimesMs_.size() > 2 && frameTimesMs_.back() - frameTimesMs_.front() > 1000)
      frameTimesMs_.pop_front();
  }
  showStatus(frame);
  showOvercut(frame);
  workbench_.partView.view().requestRender();
  updateControls();
}

void SimulationPlayback::showToolAt(double position) {
  const auto& poses = path_.poses;
  if (poses.empty()) return;
  const double last = static_cast<double>(poses.size() - 1);
  position = std::clamp(position, 0.0, last);
  const auto i = static_cast<std::size_t>(std::floor(position));
  const double f = position - static_cast<double>(i);
  Eigen::Isometry3d pose = poses[i].pose;
  if (f > 0.0 && i + 1 < poses.size()) {
    const Eigen::Isometry3d& next = poses[i + 1].pose;
    const Eigen::Quaterniond from(pose.rotation()), to(next.rotation());
    pose.linear() = from.slerp(f, to).toRotationMatrix();
    pose.translation() = (1.0 - f) * pose.translation() + f * next.translation();
  }
  toolPosition_ = position;
  // Red only at the colliding pose itself: on the way to the next one it is not known yet.
  showToolOverlay(workbench_.partView.scene(), tool_, pose, shownColliding_ && f == 0.0);
}

void SimulationPlayback::moveToolBetweenPoses() {
  // At or above the display rate every frame already moves the tool by a pose or more; as
  // fast as the machine can (rate <= 0) there is no rate to move at.
  const double rate = posesPerSecond_;
  if (rate <= 0.0 || rate * params_.frameIntervalMs >= 1000.0 || shownPosesCut_ <= 0) return;
  const std::int64_t now = clock_.elapsed();
  if (now - renderedAtMs_ < params_.frameIntervalMs) return;
  // The next pose is cut about 1 / rate after the last one: the tool gets there meanwhile and
  // waits there for the frame of that cut.
  const double ahead = std::min(1.0, static_cast<double>(now - shownAtMs_) * rate / 1000.0);
  showToolAt(shownPosesCut_ - 1 + ahead);
  renderedAtMs_ = now;
  workbench_.partView.view().requestRender();
}

void SimulationPlayback::settleTool() {
  if (!live_ || toolPosition_ == std::floor(toolPosition_)) return;
  showToolAt(std::max(0, shownPosesCut_ - 1));
  workbench_.partView.view().requestRender();
}

void SimulationPlayback::showReport(const planning::GrindingReport& report) {
  listEvents(collisions_, report.collisions);
  listEvents(vConvexity_, report.vConvexity);
  while (removal_->count() > static_cast<int>(report.passes.size()))
    delete removal_->takeItem(removal_->count() - 1);
  for (std::size_t i = 0; i < report.passes.size(); ++i) {
    const QString text = tr("pass %1: %2 mm³ (%3 poses)")
                             .arg(i + 1)
                             .arg(report.passes[i].removedVolumeMm3, 0, 'f', 4)
                             .arg(report.passes[i].poseCount);
    if (static_cast<int>(i) < removal_->count())
      removal_->item(static_cast<int>(i))->setText(text);  // in place: no relayout of the list
    else
      removal_->addItem(text);
  }
  collisionLabel_->setText(tr("Collisions: %1 poses; V-convexity violations: %2 poses")
                               .arg(report.collisions.size())
                               .arg(report.vConvexity.size()));
}

void SimulationPlayback::showStatus(const planning::LiveFrame& frame) {
  QString text = tr("Pose %1 of %2, removed %3 mm³")
                     .arg(frame.posesCut)
                     .arg(frame.totalPoses)
                     .arg(frame.report.removedVolumeMm3, 0, 'f', 4);
  const double rate = frame.simulatedPosesPerSecond > 0.0 ? frame.simulatedPosesPerSecond
                                                          : std::max(posesPerSecond_, 0.0);
  if (frame.elapsedSeconds > 0.0) {
    text += tr("; %1 elapsed").arg(durationText(frame.elapsedSeconds));
    if (rate > 0.0 && frame.posesCut < frame.totalPoses)
      text += tr(", about %1 left").arg(durationText((frame.totalPoses - frame.posesCut) / rate));
  }
  status_->setText(text);
  if (!live_->isPlaying()) {
    rates_->setText(tr("Paused; display update %1 ms").arg(1e3 * frame.displayUpdateSeconds, 0,
                                                          'f', 1) +
                    detailText(frame));
    return;
  }
  const QString requested = posesPerSecond_ > 0.0 ? tr("%1 poses/s").arg(posesPerSecond_)
                                                  : tr("as fast as possible");
  rates_->setText(tr("Simulating %1 poses/s (set: %2), showing %3 frames/s; display update "
                     "%4 ms")
                      .arg(frame.simulatedPosesPerSecond, 0, 'f', 1)
                      .arg(requested)
                      .arg(framesPerSecond(), 0, 'f', 1)
                      .arg(1e3 * frame.displayUpdateSeconds, 0, 'f', 1) +
                  detailText(frame));
}

void SimulationPlayback::showOvercut(const planning::LiveFrame& frame) {
  showOvercut_->setEnabled(frame.largestOvercut.has_value());
  if (!frame.inspected) {
    overcut_->setText(tr("Overcut: not inspected (no design state; Raise by stock allowance "
                         "records one)"));
  } else if (!frame.largestOvercut) {
    overcut_->setText(tr("Overcut: none beyond %1 mm so far").arg(params_.overcutToleranceMm));
  } else {
    overcut_->setText(tr("Largest overcut so far: %1 mm at pose %2; %3 poses beyond %4 mm")
                          .arg(frame.largestOvercut->depthMm, 0, 'f', 4)
                          .arg(frame.largestOvercut->pose)
                          .arg(frame.overcutPoses)
                          .arg(params_.overcutToleranceMm));
  }
  if (surface_ && surface_->texture() && frame.inspected)
    overcut_->setText(overcut_->text() +
                      tr("\nColours per raster point against the design: blue stock left "
                         "(above +%1 mm), green within ±%1 mm, red overcut (below -%1 mm)")
                          .arg(params_.overcutToleranceMm));
}

void SimulationPlayback::updateControls() {
  const bool active = isActive();
  const bool playing = isPlaying();
  const bool finished = active && live_->finished();
  const int total = active ? live_->latestFrame()->totalPoses : 0;
  const int done = active ? live_->latestFrame()->posesCut : 0;
  play_->setEnabled(!playing && !finished);
  pause_->setEnabled(playing);
  step_->setEnabled(!finished);
  apply_->setEnabled(active && done > 0);
  cancel_->setEnabled(active);
  timeline_->setEnabled(active);
  progress_->setValue(total > 0 ? static_cast<int>(1000.0 * done / total) : 0);
  if (!active) {
    status_->setText(tr("No playback"));
    rates_->clear();
    overcut_->clear();
    showOvercut_->setEnabled(false);
    collisionLabel_->clear();
    collisions_->clear();
    vConvexity_->clear();
  }
}

}  // namespace ddfcam::gui
