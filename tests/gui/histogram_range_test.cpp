// SPDX-License-Identifier: MIT
// The colour range on the shown field's histogram under Xvfb: two lines at its ends, dragged
// with the mouse to set the range the part is coloured over.
#include "gui_test_registry.h"
#include "frame_checks.h"
#include "workbench_test.h"

#include <ddfcam/gui/histogram_range.h>
#include <ddfcam/gui/panels/fields_panel.h>
#include <ddfcam/gui/part_scene.h>
#include <ddfcam/gui/part_view.h>
#include <ddfcam/gui/plot_dock.h>
#include <ddfcam/planning/model/demo_project.h>

#include <qcustomplot.h>
#include <QtTest/QtTest>

#include <cmath>

class HistogramRangeTest : public ddfcam::test::WorkbenchTest {
  Q_OBJECT

 private slots:
  void initTestCase() { QVERIFY(openWorkbench(false)); }
  void init();
  void draggingTheLowLineSetsTheColourRange();
  void aPressAwayFromTheLinesLeavesTheRange();

 private:
  ddfcam::gui::HistogramRangeMarkers& markers() const {
    return *f_.window->findChild<ddfcam::gui::HistogramRangeMarkers*>();
  }
  QCustomPlot& plot() const {
    return *f_.window->plots().findPlot(ddfcam::gui::PlotDock::kHistogramTab);
  }
  void drag(int fromX, int toX) {
    const int y = plot().height() / 2;
    QTest::mousePress(&plot(), Qt::LeftButton, Qt::NoModifier, QPoint(fromX, y));
    for (int x = fromX; x != toX; x += toX > fromX ? 5 : -5) QTest::mouseMove(&plot(), QPoint(x, y));
    QTest::mouseRelease(&plot(), Qt::LeftButton, Qt::NoModifier, QPoint(toX, y));
    QApplication::processEvents();
  }
};

void HistogramRangeTest::init() {
  f_.script.errors.clear();
  load(ddfcam::planning::demoProject());
  QVERIFY(f_.window->findChild<ddfcam::gui::FieldsPanel*>()->compute(
      ddfcam::gui::FieldKind::HeightMm));
  waitOk();
  f_.window->plots().raise();
  QApplication::processEvents();
  QVERIFY(plot().isVisible() && plot().width() > 200);
  plot().replot();
}

void HistogramRangeTest::draggingTheLowLineSetsTheColourRange() {
  const auto& display = f_.window->partView().fieldDisplay();
  QVERIFY(display.autoRange);
  const double hi = display.hi;
  QCOMPARE(markers().range().first, display.lo);
  const int from = static_cast<int>(std::lround(markers().linePixel(0)));
  const int to = from + 60;
  const double expected = plot().xAxis->pixelToCoord(to);
  drag(from, to);
  QVERIFY(!display.autoRange);
  const double pixel = std::abs(plot().xAxis->pixelToCoord(1) - plot().xAxis->pixelToCoord(0));
  QVERIFY2(std::abs(display.lo - expected) <= 1.5 * pixel,
           qPrintable(QString("%1 vs %2").arg(display.lo).arg(expected)));
  QCOMPARE(display.hi, hi);
  // The part is coloured over the new range, and the line stands where it was dropped.
  QCOMPARE(f_.window->partView().scene().scalarRange().lo, display.lo);
  QCOMPARE(markers().range().first, display.lo);
  ddfcam::test::dumpFrame(f_.window->grab().toImage(), "histogram_range_dragged");
}

void HistogramRangeTest::aPressAwayFromTheLinesLeavesTheRange() {
  const auto& display = f_.window->partView().fieldDisplay();
  const double lo = display.lo, hi = display.hi;
  const int middle = static_cast<int>(std::lround(0.5 * (markers().linePixel(0) +
                                                          markers().linePixel(1))));
  drag(middle, middle + 40);
  QCOMPARE(display.lo, lo);
  QCOMPARE(display.hi, hi);
  QVERIFY(display.autoRange);
}

DDFCAM_GUI_TEST_MAIN(HistogramRangeTest)
#include "histogram_range_test.moc"
