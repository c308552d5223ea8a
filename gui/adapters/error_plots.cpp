// SPDX-License-Identifier: MIT
// ddfcam gui adapters: error-map plots.
#include <ddfcam/gui/adapters/error_plots.h>
#include <ddfcam/gui/adapters/plot_series.h>

#include <qcustomplot.h>

#include <QVector>

#include <algorithm>
#include <array>
#include <cmath>

namespace ddfcam::gui {
namespace {

struct ClassBars {
  planning::ToleranceClass cls;
  const char* name;
  QColor brush;
};

std::array<ClassBars, 3> classBars(const HistogramClassNames& names) {
  return {{
      {planning::ToleranceClass::MaterialLeft, names.above, QColor(70, 110, 220)},
      {planning::ToleranceClass::InTolerance, names.inside, QColor(46, 170, 72)},
      {planning::ToleranceClass::Overcut, names.below, QColor(215, 50, 45)},
  }};
}

void removeNamed(QCustomPlot* plot, const QString& name) {
  for (int i = plot->plottableCount() - 1; i >= 0; --i)
    if (plot->plottable(i)->name() == name) plot->removePlottable(i);
}

QCPBars* addBars(QCustomPlot* plot, const ClassBars& style, double width) {
  removeNamed(plot, QString::fromLatin1(style.name));
  auto* bars = new QCPBars(plot->xAxis, plot->yAxis);
  bars->setName(QString::fromLatin1(style.name));
  bars->setWidthType(QCPBars::wtPlotCoords);
  bars->setWidth(width);
  bars->setPen(QPen(style.brush.darker(140)));
  bars->setBrush(style.brush);
  return bars;
}

}  // namespace

void setAreaHistogramBars(QCustomPlot* plot, const planning::AreaHistogram& histogram,
                          const planning::ToleranceBand& band, const HistogramClassNames& names) {
  const double width = histogram.binWidthMm();
  double tallest = 0.0;
  for (const ClassBars& style : classBars(names)) {
    QCPBars* bars = addBars(plot, style, width);
    QVector<double> keys, values;
    for (std::size_t b = 0; b < histogram.areaMm2.size(); ++b) {
      const double centre = histogram.lowerMm + (static_cast<double>(b) + 0.5) * width;
      if (planning::classify(centre, band) != style.cls) continue;
      keys.push_back(centre);
      values.push_back(histogram.areaMm2[b]);
      tallest = std::max(tallest, histogram.areaMm2[b]);
    }
    bars->setData(keys, values, true);
  }
  plot->xAxis->setLabel(QStringLiteral("deviation [mm]"));
  plot->yAxis->setLabel(QStringLiteral("area [mm²]"));
  const double margin = 0.02 * (histogram.upperMm - histogram.lowerMm);
  plot->xAxis->setRange(histogram.lowerMm - margin, histogram.upperMm + margin);
  plot->yAxis->setRange(0.0, tallest > 0.0 ? tallest * 1.05 : 1.0);
  plot->legend->setVisible(true);
  plot->replot();
}

void setDeviationAlongPath(QCustomPlot* plot,
                           const std::vector<planning::PathDeviationSample>& samples,
                           const planning::ToleranceBand& band) {
  std::vector<double> s, e;
  for (const planning::PathDeviationSample& sample : samples) {
    if (!std::isfinite(sample.deviationMm)) continue;
    s.push_back(sample.arcLengthMm);
    e.push_back(sample.deviationMm);
  }
  const QString x = QStringLiteral("arc length [mm]"), y = QStringLiteral("deviation [mm]");
  const std::vector<double> ends =
      s.empty() ? std::vector<double>{} : std::vector<double>{s.front(), s.back()};
  setLineSeries(plot, QStringLiteral("upper tolerance"), ends,
                std::vector<double>(ends.size(), band.upperMm), x, y);
  setLineSeries(plot, QStringLiteral("lower tolerance"), ends,
                std::vector<double>(ends.size(), band.lowerMm), x, y);
  setLineSeries(plot, QStringLiteral("deviation"), s, e, x, y);
  for (int i = 0; i < plot->graphCount(); ++i) {
    QCPGraph* graph = plot->graph(i);
    const bool bandLine = graph->name() != QStringLiteral("deviation");
    graph->setPen(bandLine ? QPen(QColor(46, 170, 72), 1.0, Qt::DashLine)
                           : QPen(QColor(30, 60, 160), 1.5));
  }
  plot->replot();
}

}  // namespace ddfcam::gui
