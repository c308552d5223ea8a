// SPDX-License-Identifier: MIT
// ddfcam gui: the facts of a part the Part panel and the status bar show: size, raster spacing
// and crust reach.
#pragma once

#include <ddfcam/ddf/displacement_field.h>
#include <ddfcam/ddf/stock_crust.h>

#include <array>
#include <optional>
#include <string>

namespace ddfcam::gui {

/// @brief Size, raster spacing and crust reach of one DDF.
struct PartFacts {
  /// Axis-aligned bounding box (min, max) of the represented surface (every stored raster
  /// point q = g + h v), mm, part frame.
  std::array<ddf::Vec3, 2> boundsMm = {ddf::Vec3::Zero(), ddf::Vec3::Zero()};
  /// Longest raster spacing: longest support edge / (m - 1), mm.
  double rasterSpacingMm = 0.0;
  /// How far the +-1 crust reaches above and below the surface (ddf::crustReach); nullopt if
  /// the field has no raster points.
  std::optional<ddf::CrustReach> reach;

  /// @brief (dx, dy, dz) of boundsMm, mm.
  std::array<double, 3> sizeMm() const;
};

/// @brief The facts of @p ddf: bounds over all raster points, the spacing from the support
/// edges and ddf::crustReach (parallel; a few milliseconds per 100,000 points).
PartFacts partFacts(const ddf::DisplacementField& ddf);

/// @brief "120 x 80 x 30 mm" (3 significant digits).
std::string sizeLine(const std::array<double, 3>& sizeMm);
/// @brief "support 1,234 faces, m = 10, spacing 0.523 mm" for @p ddf with @p facts.
std::string supportLine(const ddf::DisplacementField& ddf, const PartFacts& facts);
/// @brief "min 0.12 mm, median 0.5 mm" of the reach above (@p above) or below.
std::string reachLine(const ddf::CrustReach& reach, bool above);

}  // namespace ddfcam::gui
