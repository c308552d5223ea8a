// SPDX-License-Identifier: MIT
// ddfcam gui adapters: core statistics and series -> QCustomPlot plottables. Conversion only.
#pragma once

#include <ddfcam/planning/model/field_statistics.h>

#include <QString>

#include <vector>

class QCustomPlot;

namespace ddfcam::gui {

/// @brief Name of the QCPBars plottable setHistogramBars draws (and replaces on the next call).
inline constexpr const char* kHistogramBarsName = "histogram";

/// @brief Draws @p histogram into @p plot as one QCPBars plottable named kHistogramBarsName:
/// bar b at key histogram.binCentre(b) with height counts[b] and width histogram.binWidth()
/// (plot coordinates, so neighbouring bars touch). A previous plottable of that name is
/// replaced; other plottables stay. The x axis is labelled @p xLabel (the field, with unit),
/// the y axis "raster points"; axes are rescaled with the y range starting at 0, then the
/// plot is replotted. An empty histogram (no bins) leaves an empty plot.
void setHistogramBars(QCustomPlot* plot, const planning::Histogram& histogram,
                      const QString& xLabel);

/// @brief Adds the line graph @p name with points (x[i], y[i]) to @p plot, or replaces the
/// data of the graph of that name (e.g. the error along a path, a convergence history).
/// Points are drawn in order of increasing x (QCPGraph sorts its keys). Axes are labelled
/// @p xLabel / @p yLabel, rescaled, and the plot is replotted.
/// @throws InvalidInput if x and y differ in length (the message names the series).
void setLineSeries(QCustomPlot* plot, const QString& name, const std::vector<double>& x,
                   const std::vector<double>& y, const QString& xLabel, const QString& yLabel);

/// @brief Every plottable of @p plot as CSV text, one block per plottable in plot order,
/// blocks separated by an empty line. A block starts with a comment line
/// `# <kind> "<name>"; x: <x axis label>; y: <y axis label>` (kind "bars" or "graph"), then
/// the column line "bin_centre,count" (bars) or "x,y" (anything else), then one "key,value"
/// line per data point in key order. Numbers use the shortest text that reads back to the
/// same double. A plot with no plottables gives an empty string.
QString plotToCsv(QCustomPlot* plot);

}  // namespace ddfcam::gui
