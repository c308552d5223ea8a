// SPDX-License-Identifier: MIT
// ddfcam: the workpiece of a grinding simulation as a DDF on the support of the desired surface
// (sec. 8.4): the goal raised by a stock allowance, or a stock mesh converted onto the support.
#pragma once

#include <ddfcam/ddf/depth_buffer.h>
#include <ddfcam/ddf/displacement_field.h>
#include <ddfcam/ddf/triangle_mesh.h>
#include <ddfcam/progress.h>

#include <cstddef>
#include <cstdint>
#include <vector>

namespace ddfcam::planning {

/// @brief The goal @p goal with every height raised so that the represented surface moves by
/// @p allowanceMm along its unit surface normal n: dh = allowance / (v . n) per raster point.
/// n is the normal of the goal's raster surface at the point (ddf::rasterNormal: area-weighted
/// normal of the raster triangles around it), oriented to the side of v; ddf::crustReach
/// measures the room for it along the same normal. Shared copies are made equal afterwards
/// (SharedPolicy::Canonical). Support and vectors are those of @p goal, so produced and desired
/// surfaces can be compared height by height (sec. 8.4.1).
/// @param allowanceMm stock thickness along the normal, mm; may be 0 or negative (undersize).
/// @throws InvalidInput when a raised height leaves the crust [-1, 1] or v . n <= 0 at a
/// point; the message names the allowance, the face and raster point, and the room left in
/// the crust there in mm along the normal, and says to convert the part with a stock allowance
/// (ddf::fitCrustToStock through ConversionParams::stockMm) so that the crust holds it.
ddf::DisplacementField workpieceWithAllowance(const ddf::DisplacementField& goal,
                                              double allowanceMm);

/// @brief Parameters of workpieceFromStockMesh().
struct StockWorkpieceParams {
  /// Throw when a stubble misses the stock mesh; otherwise such points keep the goal height and
  /// are counted. Default true.
  bool requireFullCoverage = true;
  /// Fill kernel settings and progress/cancel (see ddf::FillParams). Default FillParams{}.
  ddf::FillParams fill;
};

/// @brief Result of workpieceFromStockMesh().
struct StockWorkpiece {
  ddf::DisplacementField workpiece;       ///< goal support and vectors, heights from the stock mesh
  std::size_t missing = 0;                ///< stored heights (all copies) whose stubble missed it
  std::vector<std::uint8_t> missingMask;  ///< per stored height: 1 where missing
};

/// @brief The workpiece as the stock surface @p stock (part frame, mm) converted onto the
/// support and vectors of @p goal by ddf::fillFromMesh (the intersection of each stubble
/// segment [-1, 1] nearest to the support).
/// @throws InvalidInput when requireFullCoverage is set and some stubble misses the stock (the
/// message gives the count); Cancelled through params.fill.progress.
StockWorkpiece workpieceFromStockMesh(const ddf::DisplacementField& goal,
                                      const ddf::TriangleMesh& stock,
                                      const StockWorkpieceParams& params = {});

/// @brief Volume between two height fields on the same DDF (heights @p before >= @p after
/// give a positive volume), mm^3. Quadrature: per support face the map (u, h) -> g(u) + h v(u)
/// is linear in the barycentric u for fixed h, so its Jacobian is a quadratic polynomial in h;
/// it is integrated exactly in h between the two heights at every raster point, and over the
/// face by the raster's nodal rule (each raster sub-triangle gives a third of its area to each
/// corner). Exact for a z-map (planar support, constant vectors) with piecewise linear heights;
/// otherwise second order in the raster spacing.
/// @param before, after one value per stored height (DisplacementField::allHeights order).
/// @throws InvalidInput on a size mismatch.
double volumeBetween(const ddf::DisplacementField& ddf, const std::vector<float>& before,
                     const std::vector<float>& after);

}  // namespace ddfcam::planning
