// SPDX-License-Identifier: MIT
// Tool paths in the part view under Xvfb: cuts, links and the selected path drawn so that they
// cannot be mistaken for one another or for a region, and each path shown or hidden by the box
// by its name in the path list.
#include "gui_test_registry.h"
#include "frame_checks.h"
#include "workbench_test.h"

#include <ddfcam/gui/path_list.h>
#include <ddfcam/gui/path_overlay.h>
#include <ddfcam/gui/part_scene.h>
#include <ddfcam/gui/part_view.h>
#include <ddfcam/gui/vtk_view.h>
#include <ddfcam/planning/analysis/region_editing.h>
#include <ddfcam/planning/model/demo_project.h>

#include <QColor>
#include <QtTest/QtTest>

#include <algorithm>
#include <cstdlib>

class PathOverlayTest : public ddfcam::test::WorkbenchTest {
  Q_OBJECT

 private slots:
  void initTestCase() { QVERIFY(openWorkbench(false)); }
  void init();
  void cutsLinksAndTheSelectedPathLookApart();
  void theBoxByANameHidesThePath();
  void pathLooksNeverMatchARegionColour();

 private:
  ddfcam::gui::PathListWidget& list() const {
    return *f_.window->findChild<ddfcam::gui::PathListWidget*>();
  }
  /// The pixel of a fresh render where @p world is drawn.
  QRgb pixelAt(const Eigen::Vector3d& world) const {
    auto& view = *f_.window->view();
    const QImage image = view.renderImage();
    const QPointF p = view.widgetPosition(world) * view.devicePixelRatioF();
    return image.pixel(static_cast<int>(p.x()), static_cast<int>(p.y()));
  }
  /// The contact halfway along pass @p pass of the demo path.
  Eigen::Vector3d midPass(int pass) const {
    const auto& path = project().paths[0];
    const int begin = path.passStarts[pass];
    const int end = pass + 1 < static_cast<int>(path.passStarts.size())
                        ? path.passStarts[pass + 1]
                        : static_cast<int>(path.poses.size());
    return path.poses[(begin + end) / 2].contact;
  }
  static QString describe(QRgb p) {
    return QString("%1 %2 %3").arg(qRed(p)).arg(qGreen(p)).arg(qBlue(p));
  }
};

void PathOverlayTest::init() {
  load(ddfcam::planning::demoProject());
  QVERIFY(project().paths.size() == 1 && project().paths[0].passStarts.size() >= 2);
  f_.window->view()->viewFrom(ddfcam::gui::ViewDirection::PlusZ);
}

void PathOverlayTest::cutsLinksAndTheSelectedPathLookApart() {
  // The list selects the new path, and the view highlights it: saturated yellow.
  QCOMPARE(list().selectedPath(), 0);
  QCOMPARE(f_.window->partView().selectedPath(), 0);
  ddfcam::test::dumpFrame(f_.window->view()->renderImage(), "path_overlay_selected");
  const QRgb selected = pixelAt(midPass(1));
  QVERIFY2(qRed(selected) > 200 && qGreen(selected) > 170 && qBlue(selected) < 90,
           qPrintable(describe(selected)));
  // Not selected: a white cut.
  list().selectPath(-1);
  QCOMPARE(f_.window->partView().selectedPath(), -1);
  ddfcam::test::dumpFrame(f_.window->view()->renderImage(), "path_overlay_cuts");
  const QRgb cut = pixelAt(midPass(1));
  QVERIFY2(std::min({qRed(cut), qGreen(cut), qBlue(cut)}) > 200, qPrintable(describe(cut)));
  // A link: the straight move between two passes, darker than the part beside it.
  const auto& path = project().paths[0];
  const int start = path.passStarts[1];
  const Eigen::Vector3d link = 0.5 * (path.poses[start - 1].contact + path.poses[start].contact);
  QCOMPARE(f_.window->partView().scene().overlayCellCount(ddfcam::gui::kPathLinksOverlay),
           static_cast<long long>(path.passStarts.size() - 1));
  const QRgb onLink = pixelAt(link);
  const QRgb beside = pixelAt(link + Eigen::Vector3d(0.0, 1.5, 0.0));
  QVERIFY2(qGray(onLink) + 40 < qGray(beside),
           qPrintable(describe(onLink) + " vs " + describe(beside)));
}

void PathOverlayTest::theBoxByANameHidesThePath() {
  auto& scene = f_.window->partView().scene();
  const long long passes = static_cast<long long>(project().paths[0].passStarts.size());
  QCOMPARE(scene.overlayCellCount(ddfcam::gui::kPathCutsOverlay), passes);
  const QRgb before = pixelAt(midPass(1));
  list().setPathChecked(0, false);
  QVERIFY(!f_.window->partView().isPathVisible(project().paths[0].name));
  QCOMPARE(scene.overlayCellCount(ddfcam::gui::kPathCutsOverlay), 0LL);
  QCOMPARE(scene.overlayCellCount(ddfcam::gui::kSelectedPathOverlay), 0LL);
  const QRgb hidden = pixelAt(midPass(1));
  const int change = std::max({std::abs(qRed(hidden) - qRed(before)),
                               std::abs(qGreen(hidden) - qGreen(before)),
                               std::abs(qBlue(hidden) - qBlue(before))});
  QVERIFY2(change > 60, qPrintable(describe(hidden) + " vs " + describe(before)));
  list().setPathChecked(0, true);
  QCOMPARE(scene.overlayCellCount(ddfcam::gui::kPathCutsOverlay), passes);
  // Hidden paths stay hidden across edits of the path list (by name), not across parts.
  list().setPathChecked(0, false);
  load(ddfcam::planning::demoProject());
  QVERIFY(f_.window->partView().isPathVisible(project().paths[0].name));
}

void PathOverlayTest::pathLooksNeverMatchARegionColour() {
  // Region colours have saturations from 0.35 to 0.75 (edits) or 0.6 (segmentation); the path
  // looks have about 0 (cuts, links) and 1 (the selected path).
  std::vector<ddfcam::planning::Region> regions;
  for (int i = 0; i < 40; ++i) {
    ddfcam::planning::Region r;
    r.color = ddfcam::planning::distinctRegionColor(regions);
    regions.push_back(r);
  }
  const auto saturation = [](const std::array<double, 3>& c) {
    return QColor::fromRgbF(c[0], c[1], c[2]).hsvSaturationF();
  };
  QVERIFY(saturation(ddfcam::gui::pathCutStyle().rgb) < 0.05);
  QVERIFY(saturation(ddfcam::gui::pathLinkStyle().rgb) < 0.25);
  QVERIFY(saturation(ddfcam::gui::selectedPathStyle().rgb) > 0.95);
  for (const auto& r : regions) {
    const double s = saturation({r.color[0], r.color[1], r.color[2]});
    QVERIFY2(s > 0.3 && s < 0.8, qPrintable(QString::number(s)));
  }
}

DDFCAM_GUI_TEST_MAIN(PathOverlayTest)
#include "path_overlay_test.moc"
