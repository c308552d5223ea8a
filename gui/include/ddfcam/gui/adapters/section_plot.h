// SPDX-License-Identifier: MIT
// ddfcam gui adapters: cross-section curves (planning::sectionCurves) -> QCustomPlot curves.
#pragma once

#include <Eigen/Core>

#include <QColor>
#include <QString>

#include <vector>

class QCustomPlot;

namespace ddfcam::gui {

/// @brief Draws @p polylines (plane coordinates (s, t), mm) into @p plot as one QCPCurve named
/// @p name in @p colour (replacing a plottable of that name; others stay), polylines separated
/// by a gap (NaN point) so they are not joined; axes "s along the line [mm]" / "t [mm]", equal
/// scale is not forced. Rescales and replots.
void setSectionCurve(QCustomPlot* plot, const QString& name,
                     const std::vector<std::vector<Eigen::Vector2d>>& polylines,
                     const QColor& colour);

/// @brief Number of QCPCurve plottables in @p plot (for tests and the export).
int sectionCurveCount(QCustomPlot* plot);

}  // namespace ddfcam::gui
