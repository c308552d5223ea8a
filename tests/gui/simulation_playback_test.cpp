// SPDX-License-Identifier: MIT
// Simulation playback under Xvfb: play a demo path to the end and see the groove, undo it,
// pause and step one pose, cancel, the tool at the current pose, collisions listed and marked.
#include "gui_test_registry.h"
#include "frame_checks.h"
#include "simulation_fixture.h"
#include "playback_test_base.h"

#include <ddfcam/ddf/adaptive_triangulation.h>
#include <ddfcam/ddf/analytic_generators.h>
#include <ddfcam/planning/model/simulation_states.h>
#include <ddfcam/ddf/raster_mesh.h>
#include <ddfcam/gui/document.h>
#include <ddfcam/gui/document_command.h>
#include <ddfcam/gui/job_progress_widget.h>
#include <ddfcam/gui/panels/simulation_panel.h>
#include <ddfcam/gui/panels/simulation_playback.h>
#include <ddfcam/gui/part_scene.h>
#include <ddfcam/gui/part_view.h>
#include <ddfcam/gui/tool_overlay.h>
#include <ddfcam/gui/vtk_view.h>
#include <ddfcam/planning/simulation/path_simulation.h>

#include <QDockWidget>
#include <QLabel>
#include <QElapsedTimer>
#include <QListWidget>
#include <QPushButton>
#include <QSlider>
#include <QUndoStack>
#include <QtTest/QtTest>

#include <vtkPolyData.h>

#include <algorithm>
#include <cmath>
#include <cstdio>

using ddfcam::planning::Tool;

class SimulationPlaybackTest : public ddfcam::test::PlaybackTestBase {
  Q_OBJECT

 private slots:
  void initTestCase() { QVERIFY(openWorkbench(false)); }
  void playToTheEndCutsTheGrooveAndUndoRestores();
  void pauseAndStepAdvanceOnePose();
  void cancelLeavesTheDocumentUnchanged();
  void collisionsAreListedAndMarked();
  void timelineAndEventsSeekToTheStateOfThePose();
  void pauseAndStepActWithin100MsAndRatesAreShown();
  void toolMovesBetweenPosesWhilePlayingSlowly();
  void longPathsAreAnnouncedWithTheirEstimate();
};

void SimulationPlaybackTest::playToTheEndCutsTheGrooveAndUndoRestores() {
  loadDemo({16.0, 24.0});
  const std::vector<float> stock = project().part->allHeights();
  const int count = undo().count();
  playback().setPosesPerSecond(0);  // as fast as the frame budget allows
  QVERIFY(playback().play());
  QVERIFY(playback().isPlaying());
  QTRY_VERIFY_WITH_TIMEOUT(!playback().isActive(), 30'000);
  QVERIFY2(f_.script.errors.isEmpty(), qPrintable(f_.script.errors.join("\n")));
  QCOMPARE(undo().count(), count + 1);
  QCOMPARE(project().states.size(), std::size_t{1});
  QCOMPARE(project().states[0].name, std::string("after demo passes"));
  QCOMPARE(project().states[0].heights, project().part->allHeights());
  // Oracle 1: the same path ground by planning::simulatePath on a copy of the stock.
  ddfcam::ddf::DisplacementField copy = *demo_.project.part;
  ddfcam::planning::simulatePath(copy, demo_.project.tools[0], demo_.project.paths[0]);
  const auto& after = project().part->allHeights();
  double worst = 0.0;
  for (std::size_t i = 0; i < after.size(); ++i)
    worst = std::max(worst, std::abs(double(after[i]) - double(copy.allHeights()[i])));
  QVERIFY2(worst < 1e-6, qPrintable(QString::number(worst)));
  // Oracle 2 (analytic): the roll is sunk 0.02 mm below the design at every contact, and its
  // mesh has a vertex on its lowest line. Raster points on a contact line within 0.08 mm
  // (along the feed) of a contact lie 0.02 mm below the design up to the rise of the roll's
  // 48-gon there (< 0.005 mm); every point of the line lies below the design by at least
  // 0.02 mm minus the feed scallop (0.5^2 / 8 (1/R + 1/12 mm)) and the 48-gon's chord error
  // R (1 - cos(pi / 48)). Far from the passes the stock is untouched.
  const auto& part = *project().part;
  const int n = part.raster().steps();
  const auto& design = dynamic_cast<const ddfcam::ddf::HeightFieldSurface&>(*demo_.design);
  const double radius = demo_.project.tools[0].radiusMm;
  const double rise = 0.25 / 8.0 * (1.0 / radius + 1.0 / 12.0) +
                      radius * (1.0 - std::cos(M_PI / demo_.project.tools[0].segments));
  double nearLo = 1e9, nearHi = -1e9, lineHi = -1e9;
  std::size_t nearCount = 0, far = 0, farChanged = 0;
  for (int f = 0; f < part.faceCount(); ++f)
    for (int k = 0; k <= n; ++k)
      for (int i = 0; i + k <= n; ++i) {
        const auto q = part.surfacePoint(f, i, k);
        const double dz = q.z() - design.pointAbove(q.x(), q.y()).z();
        const bool inLine = std::min(std::abs(q.x() - 16.0), std::abs(q.x() - 24.0)) < 0.15;
        if (inLine && q.y() > 8.0 && q.y() < 22.0) {
          lineHi = std::max(lineHi, dz);
          const double toContact = std::abs(q.y() - 6.0 - 0.5 * std::round((q.y() - 6.0) / 0.5));
          if (toContact < 0.08) {
            ++nearCount;
            nearLo = std::min(nearLo, dz);
            nearHi = std::max(nearHi, dz);
          }
        }
        if (q.x() < 8.0 || q.y() < 3.0) {
          ++far;
          const std::size_t at = f * part.pointsPerFace() + part.raster().index(i, k);
          if (after[at] != stock[at]) ++farChanged;
        }
      }
  QVERIFY(nearCount > 10);
  QVERIFY2(nearLo > -0.02 - 0.002 && nearHi < -0.02 + 0.005,
           qPrintable(QString("groove depth at contacts %1 .. %2 mm").arg(nearLo).arg(nearHi)));
  QVERIFY2(lineHi < -0.02 + rise + 0.002,
           qPrintable(QString("groove line up to %1 mm, rise %2").arg(lineHi).arg(rise)));
  QVERIFY(far > 100);
  QCOMPARE(farChanged, std::size_t{0});
  // Removed volume per pass listed.
  auto* removal = f_.window->findChild<QListWidget*>("removalList");
  QCOMPARE(removal->count(), 2);
  QVERIFY(removal->item(1)->text().startsWith("pass 2"));
  f_.window->view()->viewFrom(ddfcam::gui::ViewDirection::PlusZ);
  ddfcam::test::dumpFrame(f_.window->view()->renderImage(), "playback_groove");
  undo().undo();
  QCOMPARE(project().part->allHeights(), stock);
  QVERIFY(project().states.empty());
}

void SimulationPlaybackTest::pauseAndStepAdvanceOnePose() {
  loadDemo();
  QVERIFY(playback().step());
  QCOMPARE(playback().simulation()->nextPose(), 1);
  QVERIFY(toolOverlayAt(0));
  QVERIFY(playback().step());
  QCOMPARE(playback().simulation()->nextPose(), 2);
  QCOMPARE(playback().shownPose(), 1);
  QVERIFY(toolOverlayAt(1));
  playback().setPosesPerSecond(30);
  QVERIFY(playback().play());
  QTRY_VERIFY_WITH_TIMEOUT(playback().posesCut() >= 5, 5'000);
  playback().pause();
  QVERIFY(!playback().isPlaying());
  const int paused = playback().simulation()->nextPose();
  QVERIFY(paused < static_cast<int>(project().paths[0].poses.size()));
  QTest::qWait(200);
  QCOMPARE(playback().simulation()->nextPose(), paused);
  QVERIFY(playback().step());
  QCOMPARE(playback().simulation()->nextPose(), paused + 1);
  QVERIFY(toolOverlayAt(paused));
  auto* status = f_.window->findChild<QLabel*>("playbackStatus");
  QVERIFY2(status->text().startsWith(QString("Pose %1 of %2").arg(paused + 1).arg(37)),
           qPrintable(status->text()));
  // The live surface: the view shows the simulated part, not the document's.
  ddfcam::test::dumpFrame(f_.window->view()->renderImage(), "playback_paused");
  // Apply commits the poses cut so far.
  const int count = undo().count();
  QVERIFY(playback().apply());
  QCOMPARE(undo().count(), count + 1);
  QCOMPARE(project().states.back().name,
           "after demo passes (poses 1-" + std::to_string(paused + 1) + " of 37)");
  QVERIFY(!playback().isActive());
}

void SimulationPlaybackTest::cancelLeavesTheDocumentUnchanged() {
  loadDemo();
  const std::vector<float> stock = project().part->allHeights();
  const long long shownCells = scene().cellCount(ddfcam::gui::Layer::Surface);
  const int count = undo().count();
  for (int i = 0; i < 6; ++i) QVERIFY(playback().step());
  QCOMPARE(project().part->allHeights(), stock);  // the playback cuts a copy
  playback().cancel();
  QVERIFY(!playback().isActive());
  QCOMPARE(project().part->allHeights(), stock);
  QCOMPARE(undo().count(), count);
  QVERIFY(project().states.empty());
  QCOMPARE(scene().cellCount(ddfcam::gui::Layer::Surface), shownCells);
  QVERIFY(!scene().hasOverlay(ddfcam::gui::kCollisionOverlay));
  // Back to the selected path's tool at its first pose.
  QVERIFY(toolOverlayAt(0));
  // A document edit during playback cancels it (the playback's copy would be stale).
  QVERIFY(playback().step());
  f_.window->document().push(
      std::make_unique<ddfcam::gui::SetHeightsCommand>(f_.window->document(), "edit", stock));
  QVERIFY(!playback().isActive());
  QVERIFY(f_.script.errors.isEmpty());
}

void SimulationPlaybackTest::collisionsAreListedAndMarked() {
  // Flanges of radius 4.9 mm against the side faces of the 5 mm roll: the roll sinks 0.22 mm
  // into the stock, so the flanges (0.1 mm inside the rim) reach into the material.
  auto demo = ddfcam::test::smallDemo();
  demo.project.tools[0].holderRadiusMm = 4.9;
  demo.project.tools[0].holderLengthMm = 1.0;
  demo_ = demo;
  load(demo.project);
  playback().setPathIndex(0);
  for (int i = 0; i < 8; ++i) QVERIFY(playback().step());
  const auto& report = playback().simulation()->report();
  QVERIFY(!report.collisions.empty());
  auto* list = f_.window->findChild<QListWidget*>("collisionList");
  QCOMPARE(list->count(), static_cast<int>(report.collisions.size()));
  QCOMPARE(scene().overlayCellCount(ddfcam::gui::kCollisionOverlay),
           static_cast<long long>(report.collisions.size()));
  auto* label = f_.window->findChild<QLabel*>("collisionLabel");
  QVERIFY2(label->text().startsWith(QString("Collisions: %1 poses").arg(report.collisions.size())),
           qPrintable(label->text()));
  QVERIFY(scene().hasOverlay(ddfcam::gui::kToolNonCuttingOverlay));
  f_.window->view()->viewFrom(ddfcam::gui::ViewDirection::Isometric);
  ddfcam::test::dumpFrame(f_.window->view()->renderImage(), "playback_collisions");
  auto* panel = f_.window->findChild<ddfcam::gui::SimulationPanel*>();
  QVERIFY(raisePanel("simulation"));
  ddfcam::test::dumpFrame(panel->grab().toImage(), "playback_panel");
  ddfcam::test::dumpFrame(playback().grab().toImage(), "playback_controls");
  playback().cancel();
  // Without a non-cutting part nothing collides.
  loadDemo();
  for (int i = 0; i < 8; ++i) QVERIFY(playback().step());
  QVERIFY(playback().simulation()->report().collisions.empty());
  QCOMPARE(list->count(), 0);
  playback().cancel();
}

// Heights after planning::simulatePath of the first @p poses poses of @p path on @p stock.
static std::vector<float> headHeights(const ddfcam::test::SmallDemo& demo, int poses) {
  ddfcam::planning::ToolPath head = demo.project.paths[0];
  head.poses.resize(static_cast<std::size_t>(poses));
  std::erase_if(head.passStarts, [&](int s) { return s >= poses; });
  ddfcam::ddf::DisplacementField copy = *demo.project.part;
  if (poses > 0) ddfcam::planning::simulatePath(copy, demo.project.tools[0], head);
  return copy.allHeights();
}

void SimulationPlaybackTest::timelineAndEventsSeekToTheStateOfThePose() {
  auto demo = ddfcam::test::smallDemo();
  demo.project.tools[0].holderRadiusMm = 4.9;  // flanges that collide (see above)
  demo.project.tools[0].holderLengthMm = 1.0;
  demo_ = demo;
  load(demo.project);
  playback().setPathIndex(0);
  for (int i = 0; i < 12; ++i) QVERIFY(playback().step());
  auto* timeline = f_.window->findChild<QSlider*>("timelineSlider");
  QCOMPARE(timeline->maximum(), 37);
  QCOMPARE(timeline->value(), 12);
  // Dragging the timeline back: the state is that of cutting the first 4 poses only (the
  // recorded cut is undone), bit for bit, and the tool stands at pose 3.
  timeline->setValue(4);
  QCOMPARE(playback().simulation()->nextPose(), 4);
  QCOMPARE(playback().simulation()->workpiece().allHeights(), headHeights(demo_, 4));
  QVERIFY(toolOverlayAt(3));
  // The surface shown is the live triangulation of that state: a fresh ch. 7 triangulation of
  // the same heights at the playback's bound (PlaybackParams: 2e-4 of the support's diagonal,
  // coarser per face where the view sees it small) has as many triangles.
  ddfcam::ddf::DisplacementField state = *demo_.project.part;
  state.allHeights() = headHeights(demo_, 4);
  const auto support = ddfcam::ddf::extractSupportMesh(state);
  const auto [lo, hi] = support.bounds();
  ddfcam::ddf::AdaptiveTriangulationParams bound;
  bound.epsMm = 2e-4 * (hi - lo).norm();
  bound.faceEpsMm = playback().latestFrame()->faceEps;
  QVERIFY(!bound.faceEpsMm.empty());
  QVERIFY(*std::min_element(bound.faceEpsMm.begin(), bound.faceEpsMm.end()) >=
          static_cast<float>(bound.epsMm));
  QCOMPARE(scene().cellCount(ddfcam::gui::Layer::Surface),
           static_cast<long long>(ddfcam::ddf::triangulateAdaptive(state, bound).triangles.size()));
  // Forward again by the timeline: re-cut from pose 4.
  timeline->setValue(9);
  QCOMPARE(playback().simulation()->workpiece().allHeights(), headHeights(demo_, 9));
  // A click on a listed collision moves the timeline to just after its pose.
  timeline->setValue(12);
  auto* list = f_.window->findChild<QListWidget*>("collisionList");
  QVERIFY(list->count() > 0);
  QListWidgetItem* first = list->item(0);
  const int pose = first->data(Qt::UserRole).toInt();
  const QRect rect = list->visualItemRect(first);
  QTest::mouseClick(list->viewport(), Qt::LeftButton, {}, rect.center());
  QCOMPARE(playback().simulation()->nextPose(), pose + 1);
  QCOMPARE(timeline->value(), pose + 1);
  QVERIFY(toolOverlayAt(pose));
  QCOMPARE(playback().simulation()->workpiece().allHeights(), headHeights(demo_, pose + 1));
  // Nothing reached the document.
  QCOMPARE(project().part->allHeights(), demo_.project.part->allHeights());
  playback().cancel();
}

void SimulationPlaybackTest::pauseAndStepActWithin100MsAndRatesAreShown() {
  loadDemo({12.0, 16.0, 20.0, 24.0, 28.0});
  playback().setPosesPerSecond(30);
  QVERIFY(playback().play());
  QTest::qWait(700);
  QVERIFY(playback().isPlaying());
  // The display follows at its own rate: frames were shown while the simulation ran.
  QVERIFY2(playback().framesPerSecond() > 5.0, qPrintable(QString::number(playback().framesPerSecond())));
  auto* rates = f_.window->findChild<QLabel*>("playbackRates");
  QVERIFY2(rates->text().startsWith("Simulating "), qPrintable(rates->text()));
  QVERIFY2(rates->text().contains("(set: 30 poses/s)"), qPrintable(rates->text()));
  auto* status = f_.window->findChild<QLabel*>("playbackStatus");
  QVERIFY2(status->text().contains("elapsed") && status->text().contains("left"),
           qPrintable(status->text()));
  QElapsedTimer clock;
  clock.start();
  playback().pause();
  const qint64 pauseMs = clock.elapsed();
  QVERIFY(!playback().isPlaying());
  const int paused = playback().simulation()->nextPose();
  QCOMPARE(playback().posesCut(), paused);
  clock.restart();
  QVERIFY(playback().step());
  const qint64 stepMs = clock.elapsed();
  std::printf("playback: pause %lld ms, step %lld ms, %.1f frames/s shown\n",
              static_cast<long long>(pauseMs), static_cast<long long>(stepMs),
              playback().framesPerSecond());
  QVERIFY2(pauseMs < 100, qPrintable(QString::number(pauseMs)));
  QVERIFY2(stepMs < 100, qPrintable(QString::number(stepMs)));
  QCOMPARE(playback().simulation()->nextPose(), paused + 1);
  // Playing at 30 poses/s for 0.7 s cannot have cut more than about 30 x 0.7 + 3 poses.
  QVERIFY2(paused <= 25, qPrintable(QString::number(paused)));
  playback().cancel();
}

void SimulationPlaybackTest::toolMovesBetweenPosesWhilePlayingSlowly() {
  loadDemo();
  playback().setPosesPerSecond(5);  // a pose every 200 ms; the view renders every 25 ms
  auto& view = *f_.window->view();
  QVERIFY(playback().play());
  QTRY_VERIFY_WITH_TIMEOUT(playback().posesCut() >= 2, 5000);
  const auto& poses = project().paths[0].poses;
  const Tool& tool = project().tools[0];
  const auto centre = [](const std::array<double, 6>& b) {
    return Eigen::Vector3d(b[0] + b[1], b[2] + b[3], b[4] + b[5]) / 2.0;
  };
  const std::uint64_t frames = view.renderedFrames();
  QElapsedTimer span;
  span.start();
  int between = 0;
  while (span.elapsed() < 800 && playback().isPlaying()) {
    QTest::qWait(15);
    const double at = playback().toolPosition();
    const int pose = playback().shownPose();
    QVERIFY2(at >= pose && at <= pose + 1.0, qPrintable(QString("%1 %2").arg(at).arg(pose)));
    const double f = at - pose;
    if (f < 0.05 || f > 0.95 || pose + 1 >= static_cast<int>(poses.size())) continue;
    // On the straight way from the last cut pose to the next (the poses 0.5 mm apart barely
    // turn the roll, so the centre of its bounds moves along the chord).
    double b[6];
    scene().overlayData(ddfcam::gui::kToolCuttingOverlay)->GetBounds(b);
    const Eigen::Vector3d from = centre(toolBounds(tool, poses[pose].pose));
    const Eigen::Vector3d to = centre(toolBounds(tool, poses[pose + 1].pose));
    const Eigen::Vector3d drawn = centre({b[0], b[1], b[2], b[3], b[4], b[5]});
    QVERIFY2((drawn - ((1.0 - f) * from + f * to)).norm() < 0.01 * (to - from).norm() + 1e-3,
             qPrintable(QString("pose %1 + %2").arg(pose).arg(f)));
    ++between;
  }
  const double rendered = (view.renderedFrames() - frames) / (span.elapsed() / 1000.0);
  std::printf("playback at 5 poses/s: %.1f frames/s rendered, %d samples between poses\n",
              rendered, between);
  QVERIFY2(between >= 5, qPrintable(QString::number(between)));
  // Far more frames than the 5 poses a second that change the surface.
  QVERIFY2(rendered > 15.0, qPrintable(QString::number(rendered)));
  // Paused, the tool is back at the last cut pose.
  playback().pause();
  QCOMPARE(playback().toolPosition(), static_cast<double>(playback().shownPose()));
  QVERIFY(toolOverlayAt(playback().shownPose()));
  playback().cancel();
}

void SimulationPlaybackTest::longPathsAreAnnouncedWithTheirEstimate() {
  loadDemo();
  auto* panel = f_.window->findChild<ddfcam::gui::SimulationPanel*>();
  const std::vector<float> stock = project().part->allHeights();
  // The default threshold lets the 37-pose path start without a question.
  QCOMPARE(panel->longPathPoses(), 5000);
  panel->setLongPathPoses(10);
  f_.script.longJobMessages.clear();
  f_.script.confirmLongJobs = false;
  QVERIFY(!panel->simulatePath(0));  // declined: nothing started, nothing changed
  QCOMPARE(f_.script.longJobMessages.size(), 1);
  const QString message = f_.script.longJobMessages.front();
  QVERIFY2(message.contains("has 37 poses") && message.contains("will take about") &&
               message.contains("ms per pose, timed on 16 of its poses"),
           qPrintable(message));
  QVERIFY(!f_.window->findChild<ddfcam::gui::JobProgressWidget*>()->isVisible());
  QCOMPARE(project().part->allHeights(), stock);
  f_.script.confirmLongJobs = true;
  QVERIFY(panel->simulatePath(0));
  waitOk();
  QVERIFY(project().part->allHeights() != stock);
  QCOMPARE(f_.script.longJobMessages.size(), 2);
  panel->setLongPathPoses(5000);
}

DDFCAM_GUI_TEST_MAIN(SimulationPlaybackTest)
#include "simulation_playback_test.moc"
