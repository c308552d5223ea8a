// SPDX-License-Identifier: MIT
// ddfcam gui adapters: histogram bars and named line graphs for QCustomPlot.
#include <ddfcam/error.h>
#include <ddfcam/gui/adapters/plot_series.h>

#include <qcustomplot.h>

#include <QVector>

#include <algorithm>
#include <string>

namespace ddfcam::gui {
namespace {

QCPAbstractPlottable* findPlottable(QCustomPlot* plot, const QString& name) {
  for (int i = 0; i < plot->plottableCount(); ++i) {
    if (plot->plottable(i)->name() == name) return plot->plottable(i);
  }
  return nullptr;
}

// Bars stand on the x axis: a range starting below 0 would float them, so y starts at 0.
void rescaleFromZero(QCustomPlot* plot) {
  plot->rescaleAxes();
  const QCPRange y = plot->yAxis->range();
  plot->yAxis->setRange(0.0, std::max(y.upper * 1.05, 1.0));
}

}  // namespace

void setHistogramBars(QCustomPlot* plot, const planning::Histogram& histogram,
                      const QString& xLabel) {
  const QString name = QString::fromLatin1(kHistogramBarsName);
  if (QCPAbstractPlottable* old = findPlottable(plot, name)) plot->removePlottable(old);
  auto* bars = new QCPBars(plot->xAxis, plot->yAxis);
  bars->setName(name);
  bars->setWidthType(QCPBars::wtPlotCoords);
  bars->setWidth(histogram.binWidth());
  bars->setPen(QPen(QColor(40, 70, 130)));
  bars->setBrush(QColor(90, 130, 200));
  QVector<double> keys;
  QVector<double> values;
  keys.reserve(static_cast<int>(histogram.counts.size()));
  values.reserve(static_cast<int>(histogram.counts.size()));
  for (std::size_t b = 0; b < histogram.counts.size(); ++b) {
    keys.push_back(histogram.binCentre(static_cast<int>(b)));
    values.push_back(static_cast<double>(histogram.counts[b]));
  }
  bars->setData(keys, values, true);
  plot->xAxis->setLabel(xLabel);
  plot->yAxis->setLabel(QStringLiteral("raster points"));
  rescaleFromZero(plot);
  // QCPBars widens the key range by half a bar through pixel coordinates, which is wrong
  // for a plot that has not been laid out yet; the bars cover [lo, hi], plus a small margin.
  if (!histogram.counts.empty()) {
    const double margin = 0.02 * (histogram.hi - histogram.lo);
    QCPRange x = plot->xAxis->range();
    x.expand(QCPRange(histogram.lo - margin, histogram.hi + margin));
    plot->xAxis->setRange(x);
  }
  plot->replot();
}

void setLineSeries(QCustomPlot* plot, const QString& name, const std::vector<double>& x,
                   const std::vector<double>& y, const QString& xLabel, const QString& yLabel) {
  if (x.size() != y.size()) {
    throw InvalidInput("line series '" + name.toStdString() + "': " + std::to_string(x.size()) +
                       " x values but " + std::to_string(y.size()) + " y values");
  }
  QCPAbstractPlottable* existing = findPlottable(plot, name);
  auto* graph = qobject_cast<QCPGraph*>(existing);
  if (graph == nullptr) {
    // A same-named plottable of another kind would make "replace by name" ambiguous.
    if (existing != nullptr) plot->removePlottable(existing);
    graph = plot->addGraph(plot->xAxis, plot->yAxis);
    graph->setName(name);
  }
  const QVector<double> keys(x.begin(), x.end());
  const QVector<double> values(y.begin(), y.end());
  graph->setData(keys, values, std::is_sorted(x.begin(), x.end()));
  plot->xAxis->setLabel(xLabel);
  plot->yAxis->setLabel(yLabel);
  plot->rescaleAxes();
  plot->replot();
}

QString plotToCsv(QCustomPlot* plot) {
  QString csv;
  for (int i = 0; i < plot->plottableCount(); ++i) {
    QCPAbstractPlottable* plottable = plot->plottable(i);
    QCPPlottableInterface1D* data = plottable->interface1D();
    if (data == nullptr) continue;
    const bool isBars = qobject_cast<QCPBars*>(plottable) != nullptr;
    if (!csv.isEmpty()) csv += QLatin1Char('\n');
    csv += QStringLiteral("# %1 \"%2\"; x: %3; y: %4\n")
               .arg(isBars ? QStringLiteral("bars") : QStringLiteral("graph"), plottable->name(),
                    plottable->keyAxis()->label(), plottable->valueAxis()->label());
    csv += isBars ? QStringLiteral("bin_centre,count\n") : QStringLiteral("x,y\n");
    for (int k = 0; k < data->dataCount(); ++k) {
      csv += QString::number(data->dataMainKey(k), 'g', QLocale::FloatingPointShortest) +
             QLatin1Char(',') +
             QString::number(data->dataMainValue(k), 'g', QLocale::FloatingPointShortest) +
             QLatin1Char('\n');
    }
  }
  return csv;
}

}  // namespace ddfcam::gui
