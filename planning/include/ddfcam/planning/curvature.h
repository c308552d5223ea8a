// SPDX-License-Identifier: MIT
// ddfcam: principal curvatures and directions at every raster point of a DDF (sec. 8.2).
#pragma once

#include <ddfcam/ddf/displacement_field.h>
#include <ddfcam/planning/project.h>
#include <ddfcam/progress.h>

#include <cstdint>
#include <vector>

namespace ddfcam::planning {

/// @brief Options of computeCurvature().
struct CurvatureParams {
  /// Difference step d of eq. 8.2 in raster steps; 0 picks automaticCurvatureStep(m) (default 0).
  int step = 0;
  /// A point is flagged umbilic / near-isotropic when k_max - k_min <= umbilicTolerance *
  /// max(|k_max|, |k_min|) + flatCurvaturePerMm (default 0.05: 5 % anisotropy).
  double umbilicTolerance = 0.05;
  /// Curvature below which both directions count as meaningless (a plane is isotropic),
  /// 1/mm (default 1e-6).
  double flatCurvaturePerMm = 1e-6;
  /// Process faces in parallel with TBB (default true).
  bool parallel = true;
  /// Progress in [0, 1]; returning false cancels (default: none).
  ProgressCallback progress;
};

/// @brief Curvature of the represented surface at every stored raster point, laid out like
/// DisplacementField::allHeights() (face after face, Raster order; F * pointsPerFace entries).
/// Sign convention (tool side): the unit normal n points from the material to the tool, i.e.
/// to the +v side of the displacement vectors (cutting lowers h), and a normal curvature is
/// kappa = -II(t, t): positive where the surface bends away from the tool (convex, e.g. a
/// cylinder machined from outside), negative where it bends towards it (concave).
struct CurvatureField {
  std::vector<float> kMax;      ///< larger principal curvature, 1/mm
  std::vector<float> kMin;      ///< smaller principal curvature, 1/mm
  std::vector<float> mean;      ///< (kMax + kMin) / 2, 1/mm
  std::vector<float> gaussian;  ///< kMax * kMin, 1/mm^2
  /// Unit direction of kMax, part frame; a line field (the sign is arbitrary).
  std::vector<ddf::Vec3> dirMax;
  /// Unit direction of kMin, perpendicular to dirMax and to the normal; sign arbitrary.
  std::vector<ddf::Vec3> dirMin;
  /// 1 where the point is umbilic or near-isotropic (directions meaningless), else 0.
  std::vector<std::uint8_t> umbilic;
  int step = 1;  ///< the difference step d actually used, raster steps

  /// @brief Number of entries (F * pointsPerFace).
  std::size_t size() const { return kMax.size(); }
};

/// @brief The automatic difference step d of eq. 8.2 for resolution @p m: d = max(1,
/// round((m - 1) * delta)) with delta = (48 * 2^-24)^(1/4) ~ 0.041 the parameter step that
/// balances the truncation error of the central second difference (~ h'''' delta^2 / 12) with
/// the float rounding of the heights (~ 4 * 2^-24 / delta^2) for h'''' ~ 1 over a face, so that
/// high m does not corrupt the directions (fig. 8.8). m = 17..37 -> 1, 50 -> 2, 100 -> 4.
int automaticCurvatureStep(int m);

/// @brief Principal curvatures and directions of @p ddf at every raster point from its own
/// parametric form q(u, v) = g + h v (eq. 8.2): first and second fundamental forms by central
/// differences of h with step d over the raster lattice. Near support edges the stencil
/// continues into the neighbouring faces: the missing heights are those of the face's own
/// (affinely extended) stubble lines where they meet the neighbouring face's surface, with
/// that surface interpolated by cubic polynomials over its raster, so seams get the same
/// symmetric stencil as the interior. On the outer boundary of an open support the heights are
/// extrapolated by the cubic of the nearest raster cells.
/// @throws InvalidInput if params.step < 0 or the step is too large for the raster (3 d > m-1
/// needs m >= 4 and d <= (m - 1) / 3), or the DDF has no faces.
/// @throws Cancelled if params.progress asks to stop.
CurvatureField computeCurvature(const ddf::DisplacementField& ddf,
                                const CurvatureParams& params = {});

/// @brief Scalar quantities of a CurvatureField.
enum class CurvatureQuantity {
  KMax,     ///< "k_max", 1/mm
  KMin,     ///< "k_min", 1/mm
  Mean,     ///< "mean curvature", 1/mm
  Gaussian  ///< "Gaussian curvature", 1/mm^2
};

/// @brief One quantity of @p field as a signed ScalarField ("k_max", "k_min", "mean curvature",
/// "Gaussian curvature"; units "1/mm" or "1/mm^2").
ScalarField curvatureScalarField(const CurvatureField& field, CurvatureQuantity quantity);

}  // namespace ddfcam::planning
