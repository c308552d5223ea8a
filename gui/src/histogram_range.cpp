// SPDX-License-Identifier: MIT
// ddfcam gui: HistogramRangeMarkers.
#include <ddfcam/gui/histogram_range.h>

#include <qcustomplot.h>

#include <QMouseEvent>

#include <algorithm>
#include <cmath>

namespace ddfcam::gui {

HistogramRangeMarkers::HistogramRangeMarkers(QObject* parent) : QObject(parent) {}

HistogramRangeMarkers::~HistogramRangeMarkers() {
  removeLines();
}

void HistogramRangeMarkers::removeLines() {
  if (!plot_) return;
  for (QCPItemStraightLine*& line : lines_)
    if (line && plot_->hasItem(line)) plot_->removeItem(line);
  lines_ = {};
  disconnect(plot_, nullptr, this, nullptr);
}

void HistogramRangeMarkers::show(QCustomPlot* plot, double lo, double hi) {
  if (plot != plot_) {
    removeLines();
    plot_ = plot;
    if (!plot) return;
    connect(plot, &QCustomPlot::mousePress, this, &HistogramRangeMarkers::onPress);
    connect(plot, &QCustomPlot::mouseMove, this, &HistogramRangeMarkers::onMove);
    connect(plot, &QCustomPlot::mouseRelease, this, &HistogramRangeMarkers::onRelease);
  }
  ends_ = {lo, hi};
  for (int end = 0; end < 2; ++end) {
    QCPItemStraightLine*& line = lines_[static_cast<std::size_t>(end)];
    if (!line || !plot->hasItem(line)) {
      line = new QCPItemStraightLine(plot);
      line->setPen(QPen(QColor(230, 120, 20), 2.0, Qt::DashLine));
      line->setSelectable(false);
    }
    place(end, ends_[static_cast<std::size_t>(end)]);
  }
  plot->replot();
}

void HistogramRangeMarkers::place(int end, double x) {
  QCPItemStraightLine* line = lines_[static_cast<std::size_t>(end)];
  line->point1->setCoords(x, 0.0);
  line->point2->setCoords(x, 1.0);
}

double HistogramRangeMarkers::linePixel(int end) const {
  if (!plot_) return -1.0;
  return plot_->xAxis->coordToPixel(ends_[static_cast<std::size_t>(end)]);
}

void HistogramRangeMarkers::onPress(QMouseEvent* event) {
  if (!plot_ || event->button() != Qt::LeftButton) return;
  const double x = event->position().x();
  double best = kGrabPixels;
  for (int end = 0; end < 2; ++end) {
    const double d = std::abs(linePixel(end) - x);
    if (d <= best) best = d, grabbed_ = end;
  }
  if (grabbed_ < 0) return;
  // The press would also start panning the axes; the line is what the user took.
  plotDragged_ = plot_->interactions().testFlag(QCP::iRangeDrag);
  plot_->setInteraction(QCP::iRangeDrag, false);
}

void HistogramRangeMarkers::onMove(QMouseEvent* event) {
  if (!plot_ || grabbed_ < 0) return;
  const double x = plot_->xAxis->pixelToCoord(event->position().x());
  const double other = ends_[static_cast<std::size_t>(1 - grabbed_)];
  // The ends never cross: a sliver of the axis range apart at least.
  const double gap = 1e-3 * plot_->xAxis->range().size();
  ends_[static_cast<std::size_t>(grabbed_)] =
      grabbed_ == 0 ? std::min(x, other - gap) : std::max(x, other + gap);
  place(grabbed_, ends_[static_cast<std::size_t>(grabbed_)]);
  plot_->replot(QCustomPlot::rpQueuedReplot);
}

void HistogramRangeMarkers::onRelease(QMouseEvent* event) {
  if (!plot_ || grabbed_ < 0) return;
  onMove(event);
  grabbed_ = -1;
  plot_->setInteraction(QCP::iRangeDrag, plotDragged_);
  emit rangeEdited(ends_[0], ends_[1]);
}

}  // namespace ddfcam::gui
