// SPDX-License-Identifier: MIT
// ddfcam gui: the colour range of the shown field as two lines on its histogram, dragged with
// the mouse.
#pragma once

#include <QObject>
#include <QPointer>

#include <array>
#include <utility>

class QCPItemStraightLine;
class QCustomPlot;
class QMouseEvent;

namespace ddfcam::gui {

/// @brief Two vertical lines on a histogram plot at the low and high end of the colour range.
/// A left press within kGrabPixels of a line grabs it (the plot's own drag is held off
/// meanwhile), moving drags it, and the release emits rangeEdited() with the new ends (the low
/// end kept below the high end). Values outside the range are the histogram's bars beyond the
/// lines, which the out-of-range colours of the scalar bar show on the part.
class HistogramRangeMarkers : public QObject {
  Q_OBJECT

 public:
  /// How close to a line a press grabs it, pixels.
  static constexpr double kGrabPixels = 6.0;

  explicit HistogramRangeMarkers(QObject* parent = nullptr);
  ~HistogramRangeMarkers() override;

  /// @brief Draws the lines at @p lo and @p hi (field unit) on @p plot, replacing the ones drawn
  /// before (on this plot or another).
  void show(QCustomPlot* plot, double lo, double hi);
  /// @brief The ends the lines stand at.
  std::pair<double, double> range() const { return {ends_[0], ends_[1]}; }
  /// @brief Widget x of line @p end (0 low, 1 high), pixels; -1 without a plot.
  double linePixel(int end) const;

 signals:
  /// @brief A line was dragged and released: the new colour range.
  void rangeEdited(double lo, double hi);

 private:
  void onPress(QMouseEvent* event);
  void onMove(QMouseEvent* event);
  void onRelease(QMouseEvent* event);
  void place(int end, double x);
  void removeLines();

  QPointer<QCustomPlot> plot_;
  std::array<QCPItemStraightLine*, 2> lines_{};
  std::array<double, 2> ends_{0.0, 1.0};
  int grabbed_ = -1;
  bool plotDragged_ = false;  ///< the plot's own range drag, off while a line is grabbed
};

}  // namespace ddfcam::gui
