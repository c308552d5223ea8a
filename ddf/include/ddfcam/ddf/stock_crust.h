// SPDX-License-Identifier: MIT
// ddfcam: a crust that holds a stock allowance above the surface, and the crust's reach.
#pragma once

#include <ddfcam/ddf/displacement_field.h>
#include <ddfcam/ddf/triangle_mesh.h>

#include <optional>
#include <string>

namespace ddfcam::ddf {

/// @brief How far the +-1 crust of a DDF reaches above and below its represented surface,
/// measured along the surface normal at every stored raster point, mm:
/// above = (1 - h) (v . n), below = (1 + h) (v . n), n the unit normal of the raster surface
/// oriented to the side of v (the same normal workpieceWithAllowance() raises along).
struct CrustReach {
  double minAboveMm = 0.0;            ///< smallest reach above the surface
  double medianAboveMm = 0.0;         ///< median reach above the surface
  double minBelowMm = 0.0;            ///< smallest reach below the surface
  double medianBelowMm = 0.0;         ///< median reach below the surface
  int minAboveFace = -1;              ///< support face of the smallest reach above
  Vec3 minAbovePoint = Vec3::Zero();  ///< surface point of the smallest reach above, mm
};

/// @brief The crust reach of @p ddf over all its raster points (computed in parallel).
CrustReach crustReach(const DisplacementField& ddf);

/// @brief Where and why the crust cannot hold a requested allowance.
struct StockLimit {
  int face = -1;              ///< support face where the crust is too thin
  Vec3 point = Vec3::Zero();  ///< surface point there, mm
  /// Radius of the tightest concave curvature of the input near the point, mm (+inf where the
  /// limit has another cause, e.g. a thin wall or a neighbouring sheet).
  double concaveRadiusMm = 0.0;
  double largestAllowanceMm = 0.0;  ///< largest allowance the crust holds everywhere, mm
  std::string message;              ///< the refusal: place, radius, largest allowance
};

/// @brief Result of fitCrustToStock().
struct StockFit {
  double requestedMm = 0.0;         ///< the allowance asked for
  bool holds = false;               ///< the crust reaches requestedMm above everywhere
  CrustReach reach;                 ///< reach after the fit
  std::optional<StockLimit> limit;  ///< set when holds is false
};

/// @brief Parameters of fitCrustToStock().
struct StockCrustParams {
  double stockMm = 0.0;  ///< allowance the crust must reach above the surface, mm (> 0)
  /// Extra reach beyond the allowance, as a fraction of it (room for the raise's rounding and
  /// for a simulation's overshoot). Default 0.1.
  double marginFraction = 0.1;
};

/// @brief Chooses support offsets and vector lengths of @p ddf so that its crust reaches at
/// least params.stockMm (plus margin) above the surface represented by the heights of @p ddf
/// while the unique-projection property (constraint 3) still holds, then refills the heights
/// from @p input so the represented surface is unchanged. Where no choice works the field is
/// left valid with the largest reach found and the result's limit names the place.
/// @param ddf converted field (support, vectors, heights from @p input); changed in place.
/// @param input the input surface, mm, part frame.
/// @throws InvalidInput for a non-positive allowance.
StockFit fitCrustToStock(DisplacementField& ddf, const TriangleMesh& input,
                         const StockCrustParams& params);

}  // namespace ddfcam::ddf
