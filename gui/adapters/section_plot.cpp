// SPDX-License-Identifier: MIT
// ddfcam gui adapters: setSectionCurve, section polylines as QCPCurve plottables.
#include <ddfcam/gui/adapters/section_plot.h>

#include <qcustomplot.h>

#include <limits>

namespace ddfcam::gui {

void setSectionCurve(QCustomPlot* plot, const QString& name,
                     const std::vector<std::vector<Eigen::Vector2d>>& polylines,
                     const QColor& colour) {
  for (int i = plot->plottableCount() - 1; i >= 0; --i)
    if (plot->plottable(i)->name() == name) plot->removePlottable(i);
  auto* curve = new QCPCurve(plot->xAxis, plot->yAxis);
  curve->setName(name);
  curve->setPen(QPen(colour, 2.0));
  QVector<double> t, s, v;
  const double gap = std::numeric_limits<double>::quiet_NaN();
  for (const auto& line : polylines) {
    if (!s.isEmpty()) {
      t.push_back(t.size());
      s.push_back(gap);
      v.push_back(gap);
    }
    for (const Eigen::Vector2d& p : line) {
      t.push_back(t.size());
      s.push_back(p.x());
      v.push_back(p.y());
    }
  }
  curve->setData(t, s, v, true);
  plot->xAxis->setLabel(QStringLiteral("s along the line [mm]"));
  plot->yAxis->setLabel(QStringLiteral("t [mm]"));
  plot->legend->setVisible(true);
  plot->rescaleAxes();
  plot->replot();
}

int sectionCurveCount(QCustomPlot* plot) {
  int count = 0;
  for (int i = 0; i < plot->plottableCount(); ++i)
    if (qobject_cast<QCPCurve*>(plot->plottable(i))) ++count;
  return count;
}

}  // namespace ddfcam::gui
