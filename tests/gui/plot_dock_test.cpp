// SPDX-License-Identifier: MIT
// Plot adapters and the Plots dock: bars against brute-force bin counts, exports read back.
#include "gui_test_registry.h"
#include <ddfcam/error.h>
#include <ddfcam/gui/adapters/plot_series.h>
#include <ddfcam/gui/plot_dock.h>
#include <ddfcam/planning/model/field_statistics.h>

#include <qcustomplot.h>

#include <QAction>
#include <QFile>
#include <QImage>
#include <QSet>
#include <QTemporaryDir>
#include <QToolButton>
#include <QtTest/QtTest>

#include <algorithm>
#include <cmath>
#include <limits>
#include <memory>
#include <vector>

using ddfcam::gui::PlotDock;
using ddfcam::planning::Histogram;

namespace {

// Bin edges -2 + 0.25 b are exact in binary, so "which bin" has one answer for every value,
// including the values placed exactly on edges and on hi.
constexpr double kLo = -2.0;
constexpr double kHi = 2.0;
constexpr int kBins = 16;

std::vector<float> sampleValues() {
  std::vector<float> values;
  for (int i = 0; i < 997; ++i) {
    values.push_back(static_cast<float>(2.6 * std::sin(0.37 * i) * std::cos(0.011 * i * i)));
  }
  values.insert(values.end(),
                {-2.0f, -1.75f, 0.0f, 1.75f, 2.0f, 2.0f, -2.5f, 3.0f,
                 std::numeric_limits<float>::quiet_NaN(), std::numeric_limits<float>::infinity()});
  return values;
}

// Brute force: a value belongs to bin b if it lies in [lo + b w, lo + (b+1) w), or in the last
// bin if it equals hi.
std::vector<double> bruteForceCounts(const std::vector<float>& values) {
  const double w = (kHi - kLo) / kBins;
  std::vector<double> counts(kBins, 0.0);
  for (float value : values) {
    const double v = value;
    for (int b = 0; b < kBins; ++b) {
      const bool inside = v >= kLo + b * w && v < kLo + (b + 1) * w;
      if (inside || (b == kBins - 1 && v == kHi)) counts[b] += 1.0;
    }
  }
  return counts;
}

QCPBars* histogramBars(QCustomPlot* plot) {
  for (int i = 0; i < plot->plottableCount(); ++i) {
    if (auto* bars = qobject_cast<QCPBars*>(plot->plottable(i))) return bars;
  }
  return nullptr;
}

struct CsvBlock {
  QString header;
  QString columns;
  std::vector<double> keys;
  std::vector<double> values;
};

std::vector<CsvBlock> parseCsv(const QString& path) {
  QFile file(path);
  if (!file.open(QIODevice::ReadOnly | QIODevice::Text)) return {};
  std::vector<CsvBlock> blocks;
  const QStringList lines = QString::fromUtf8(file.readAll()).split(QLatin1Char('\n'));
  for (const QString& line : lines) {
    if (line.isEmpty()) continue;
    if (line.startsWith(QLatin1Char('#'))) {
      blocks.push_back({line, {}, {}, {}});
    } else if (!blocks.empty() && blocks.back().columns.isEmpty()) {
      blocks.back().columns = line;
    } else if (!blocks.empty()) {
      const QStringList fields = line.split(QLatin1Char(','));
      blocks.back().keys.push_back(fields.value(0).toDouble());
      blocks.back().values.push_back(fields.value(1).toDouble());
    }
  }
  return blocks;
}

}  // namespace

class PlotDockTest : public QObject {
  Q_OBJECT

 private slots:
  void init();
  void cleanup() { dock_.reset(); }
  void barsEqualBruteForceCounts();
  void histogramOfFieldEqualsBruteForce();
  void histogramReplacesPreviousBars();
  void lineSeriesReplaceByName();
  void lineSeriesRejectsMismatchedLengths();
  void plotTabsAreCreatedOnce();
  void exportPng();
  void exportPdf();
  void exportCsvReadsBackTheNumbers();
  void exportRejectsUnknownSuffix();
  void exportUnwritablePathThrows_data();
  void exportUnwritablePathThrows();
  void exportActionUsesProviderAndReporter();

 private:
  Histogram handMadeHistogram() const;
  void fillDemoPlots();

  std::unique_ptr<PlotDock> dock_;
  QTemporaryDir tmp_;
  QStringList errors_;
  QString nextPath_;
};

void PlotDockTest::init() {
  QVERIFY(tmp_.isValid());
  errors_.clear();
  dock_ = std::make_unique<PlotDock>();
  dock_->setErrorReporter(
      [this](const QString& title, const QString& message) { errors_ << title + ": " + message; });
  dock_->setExportPathProvider([this] { return nextPath_; });
  dock_->resize(640, 420);
  dock_->show();
  QVERIFY(QTest::qWaitForWindowExposed(dock_.get()));
}

Histogram PlotDockTest::handMadeHistogram() const {
  Histogram h;
  h.lo = kLo;
  h.hi = kHi;
  for (double c : bruteForceCounts(sampleValues())) h.counts.push_back(std::size_t(c));
  return h;
}

void PlotDockTest::barsEqualBruteForceCounts() {
  QCustomPlot plot;
  ddfcam::gui::setHistogramBars(&plot, handMadeHistogram(), QStringLiteral("height (mm)"));
  QCPBars* bars = histogramBars(&plot);
  QVERIFY(bars != nullptr);
  const std::vector<double> expected = bruteForceCounts(sampleValues());
  QCOMPARE(bars->data()->size(), kBins);
  QCOMPARE(bars->width(), 0.25);
  QCOMPARE(bars->widthType(), QCPBars::wtPlotCoords);
  for (int b = 0; b < kBins; ++b) {
    const QCPBarsData& bar = *(bars->data()->constBegin() + b);
    QCOMPARE(bar.key, kLo + 0.125 + 0.25 * b);
    QCOMPARE(bar.value, expected[b]);
  }
  QCOMPARE(plot.xAxis->label(), QStringLiteral("height (mm)"));
  QCOMPARE(plot.yAxis->label(), QStringLiteral("raster points"));
  QVERIFY(plot.xAxis->range().lower <= kLo && plot.xAxis->range().upper >= kHi);
  QCOMPARE(plot.yAxis->range().lower, 0.0);
  QVERIFY(plot.yAxis->range().upper >= *std::max_element(expected.begin(), expected.end()));
}

void PlotDockTest::histogramOfFieldEqualsBruteForce() {
  const std::vector<float> values = sampleValues();
  dock_->showHistogram(ddfcam::planning::histogram(values, kBins, kLo, kHi),
                       QStringLiteral("height"));
  QCOMPARE(dock_->currentPlotName(), PlotDock::kHistogramTab);
  QCPBars* bars = histogramBars(dock_->findPlot(PlotDock::kHistogramTab));
  QVERIFY(bars != nullptr);
  const std::vector<double> expected = bruteForceCounts(values);
  QCOMPARE(bars->data()->size(), kBins);
  QCOMPARE(bars->width(), (kHi - kLo) / kBins);
  for (int b = 0; b < kBins; ++b) {
    QCOMPARE((bars->data()->constBegin() + b)->value, expected[b]);
  }
}

void PlotDockTest::histogramReplacesPreviousBars() {
  dock_->showHistogram(handMadeHistogram(), QStringLiteral("a"));
  Histogram small;
  small.lo = 0.0;
  small.hi = 3.0;
  small.counts = {4, 5, 6};
  dock_->showHistogram(small, QStringLiteral("b"));
  QCustomPlot* plot = dock_->findPlot(PlotDock::kHistogramTab);
  QCOMPARE(plot->plottableCount(), 1);
  QCOMPARE(histogramBars(plot)->data()->size(), 3);
  QCOMPARE(histogramBars(plot)->width(), 1.0);
  QCOMPARE(plot->xAxis->label(), QStringLiteral("b"));
}

void PlotDockTest::lineSeriesReplaceByName() {
  QCustomPlot* plot = dock_->plot(QStringLiteral("Error"));
  ddfcam::gui::setLineSeries(plot, "error", {0, 1, 2}, {1, 4, 9}, "s (mm)", "e (mm)");
  ddfcam::gui::setLineSeries(plot, "bound", {0, 2}, {5, 5}, "s (mm)", "e (mm)");
  ddfcam::gui::setLineSeries(plot, "error", {0, 1}, {7, 8}, "s (mm)", "e (mm)");
  QCOMPARE(plot->graphCount(), 2);
  QCPGraph* error = plot->graph(0);
  QCOMPARE(error->name(), QStringLiteral("error"));
  QCOMPARE(error->data()->size(), 2);
  QCOMPARE(error->data()->constBegin()->value, 7.0);
  QCOMPARE((error->data()->constBegin() + 1)->value, 8.0);
  QCOMPARE(plot->graph(1)->data()->size(), 2);
  QCOMPARE(plot->xAxis->label(), QStringLiteral("s (mm)"));
  QCOMPARE(plot->yAxis->label(), QStringLiteral("e (mm)"));
  QVERIFY(plot->yAxis->range().contains(7.0) && plot->yAxis->range().contains(8.0));
}

void PlotDockTest::lineSeriesRejectsMismatchedLengths() {
  QCustomPlot plot;
  try {
    ddfcam::gui::setLineSeries(&plot, "convergence", {1, 2, 3}, {1, 2}, "x", "y");
    QFAIL("no exception");
  } catch (const ddfcam::InvalidInput& e) {
    QVERIFY(QString(e.what()).contains("convergence"));
  }
  QCOMPARE(plot.graphCount(), 0);
}

void PlotDockTest::plotTabsAreCreatedOnce() {
  QCOMPARE(dock_->objectName(), QStringLiteral("plotDock"));
  QCOMPARE(dock_->windowTitle(), QStringLiteral("Plots"));
  QVERIFY(!dock_->exportAction()->isEnabled());
  QCustomPlot* a = dock_->plot("A");
  QCOMPARE(a->objectName(), QStringLiteral("plot_A"));
  QCOMPARE(dock_->plot("A"), a);
  QVERIFY(dock_->plot("B") != a);
  QCOMPARE(dock_->plotNames(), QStringList({"A", "B"}));
  QCOMPARE(dock_->findChild<QCustomPlot*>("plot_B"), dock_->findPlot("B"));
  QVERIFY(dock_->findPlot("C") == nullptr);
  QVERIFY(dock_->exportAction()->isEnabled());
  QVERIFY(!dock_->exportPlot("C", tmp_.filePath("c.png")));
  QVERIFY(!QFile::exists(tmp_.filePath("c.png")));
}

void PlotDockTest::fillDemoPlots() {
  dock_->showHistogram(handMadeHistogram(), QStringLiteral("height (mm)"));
  QCoreApplication::processEvents();
}

void PlotDockTest::exportPng() {
  fillDemoPlots();
  const QString path = tmp_.filePath("histogram.png");
  QVERIFY(dock_->exportPlot(PlotDock::kHistogramTab, path));
  QImage image(path);
  QVERIFY(!image.isNull());
  QCustomPlot* plot = dock_->findPlot(PlotDock::kHistogramTab);
  QCOMPARE(image.size(), plot->size());
  QSet<QRgb> colours;
  int barPixels = 0;
  for (int y = 0; y < image.height(); ++y) {
    for (int x = 0; x < image.width(); ++x) {
      const QRgb pixel = image.pixel(x, y);
      colours.insert(pixel);
      if (qAbs(qRed(pixel) - 90) < 8 && qAbs(qGreen(pixel) - 130) < 8 &&
          qAbs(qBlue(pixel) - 200) < 8) {
        ++barPixels;
      }
    }
  }
  QVERIFY2(colours.size() > 2, "the exported image is uniform");
  // The bars cover a visible part of the plot, but not all of it.
  QVERIFY(barPixels > image.width() * image.height() / 50);
  QVERIFY(barPixels < image.width() * image.height() * 9 / 10);
}

void PlotDockTest::exportPdf() {
  fillDemoPlots();
  const QString path = tmp_.filePath("histogram.PDF");
  QVERIFY(dock_->exportPlot(PlotDock::kHistogramTab, path));
  QFile file(path);
  QVERIFY(file.open(QIODevice::ReadOnly));
  QCOMPARE(file.read(4), QByteArray("%PDF"));
  QVERIFY(file.size() > 500);
}

void PlotDockTest::exportCsvReadsBackTheNumbers() {
  fillDemoPlots();
  QCustomPlot* plot = dock_->findPlot(PlotDock::kHistogramTab);
  const std::vector<double> x = {-1.9, -1.0 / 3.0, 1e-12, 0.1, 1.7};
  const std::vector<double> y = {2.5e7, -0.3, 1.0 / 7.0, 0.0, 123.456};
  ddfcam::gui::setLineSeries(plot, "error", x, y, "height (mm)", "raster points");
  const QString path = tmp_.filePath("histogram.csv");
  QVERIFY(dock_->exportPlot(PlotDock::kHistogramTab, path));
  const std::vector<CsvBlock> blocks = parseCsv(path);
  QCOMPARE(blocks.size(), std::size_t(2));
  QVERIFY(blocks[0].header.contains("histogram"));
  QVERIFY(blocks[0].header.contains("height (mm)"));
  QVERIFY(blocks[0].header.contains("raster points"));
  QCOMPARE(blocks[0].columns, QStringLiteral("bin_centre,count"));
  const std::vector<double> counts = bruteForceCounts(sampleValues());
  QCOMPARE(blocks[0].keys.size(), std::size_t(kBins));
  for (int b = 0; b < kBins; ++b) {
    QCOMPARE(blocks[0].keys[b], kLo + 0.125 + 0.25 * b);
    QCOMPARE(blocks[0].values[b], counts[b]);
  }
  QVERIFY(blocks[1].header.contains("error"));
  QCOMPARE(blocks[1].columns, QStringLiteral("x,y"));
  QVERIFY(blocks[1].keys == x);  // exact: the CSV must round-trip every double
  QVERIFY(blocks[1].values == y);
}

void PlotDockTest::exportRejectsUnknownSuffix() {
  fillDemoPlots();
  const QString path = tmp_.filePath("histogram.xyz");
  try {
    dock_->exportPlot(PlotDock::kHistogramTab, path);
    QFAIL("no exception");
  } catch (const ddfcam::IoError& e) {
    QVERIFY2(QString(e.what()).contains(path), e.what());
  }
  QVERIFY(!QFile::exists(path));
}

void PlotDockTest::exportUnwritablePathThrows_data() {
  QTest::addColumn<QString>("suffix");
  QTest::newRow("png") << "png";
  QTest::newRow("pdf") << "pdf";
  QTest::newRow("csv") << "csv";
}

void PlotDockTest::exportUnwritablePathThrows() {
  QFETCH(QString, suffix);
  fillDemoPlots();
  const QString path = tmp_.filePath("no_such_dir/plot.") + suffix;
  try {
    dock_->exportPlot(PlotDock::kHistogramTab, path);
    QFAIL("no exception");
  } catch (const ddfcam::IoError& e) {
    QVERIFY2(QString(e.what()).contains(path), e.what());
  }
}

void PlotDockTest::exportActionUsesProviderAndReporter() {
  fillDemoPlots();
  nextPath_ = tmp_.filePath("via_button.csv");
  auto* button = dock_->findChild<QToolButton*>("plotExportButton");
  QVERIFY(button != nullptr && button->isVisible());
  QTest::mouseClick(button, Qt::LeftButton);
  QVERIFY(QFile::exists(nextPath_));
  QVERIFY(errors_.isEmpty());

  nextPath_.clear();  // the user cancelled the dialog
  dock_->exportAction()->trigger();
  QVERIFY(errors_.isEmpty());

  nextPath_ = tmp_.filePath("no_such_dir/via_button.png");
  dock_->exportAction()->trigger();
  QCOMPARE(errors_.size(), 1);
  QVERIFY2(errors_[0].contains(nextPath_), qPrintable(errors_[0]));
}

DDFCAM_GUI_TEST_MAIN(PlotDockTest)
#include "plot_dock_test.moc"
