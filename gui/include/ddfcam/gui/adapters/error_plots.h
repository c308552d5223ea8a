// SPDX-License-Identifier: MIT
// ddfcam gui adapters: error-map plots for QCustomPlot (area histogram by tolerance class,
// deviation along a path with the band). Conversion only.
#pragma once

#include <ddfcam/planning/inspection/error_map.h>

#include <QString>

#include <vector>

class QCustomPlot;

namespace ddfcam::gui {

/// @brief Names of the three QCPBars setAreaHistogramBars draws (replaced on the next call).
inline constexpr const char* kMaterialLeftBarsName = "material left";
inline constexpr const char* kInToleranceBarsName = "in tolerance";
inline constexpr const char* kOvercutBarsName = "overcut";
/// @brief Names of the classes above and below the band when a formed part is compared with its
/// mould (the deviation's sign then says short of or beyond the mould).
inline constexpr const char* kShortOfMouldBarsName = "short of the mould";
inline constexpr const char* kBeyondMouldBarsName = "beyond the mould";

/// @brief Legend names of the three bar sets of setAreaHistogramBars (defaults: the error map's).
struct HistogramClassNames {
  const char* above = kMaterialLeftBarsName;  ///< deviation above the band (blue)
  const char* inside = kInToleranceBarsName;  ///< inside the band (green)
  const char* below = kOvercutBarsName;       ///< below the band (red)
};

/// @brief Draws @p histogram into @p plot as three QCPBars plottables (material left in blue,
/// in tolerance in green, overcut in red, each bin in the class of its centre per
/// planning::classify with @p band), x = deviation [mm], y = area [mm²]; previous bars of
/// those names are replaced, other plottables stay; then replots. @p names gives the legend.
void setAreaHistogramBars(QCustomPlot* plot, const planning::AreaHistogram& histogram,
                          const planning::ToleranceBand& band,
                          const HistogramClassNames& names = {});

/// @brief Draws the deviation of @p samples over their arc length as graph "deviation" and
/// the band as graphs "upper tolerance" and "lower tolerance" (flat lines over the same arc
/// length); samples without a value (NaN) are left out. Replots.
void setDeviationAlongPath(QCustomPlot* plot,
                           const std::vector<planning::PathDeviationSample>& samples,
                           const planning::ToleranceBand& band);

}  // namespace ddfcam::gui
