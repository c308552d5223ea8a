// SPDX-License-Identifier: MIT
// ddfcam: the tool flow field (sec. 8.1, fig. 8.4c): a smoothed sign-free line field and its
// singularities.
#pragma once

#include <ddfcam/ddf/displacement_field.h>
#include <ddfcam/planning/analysis/curvature.h>
#include <ddfcam/planning/flow/flow_field_source.h>
#include <ddfcam/planning/flow/line_field.h>
#include <ddfcam/progress.h>

#include <cstdint>
#include <vector>

namespace ddfcam::planning {

/// @brief How flowField() solves the smoothing least-squares problem.
enum class FlowFieldSolver {
  /// Coarse to fine (default): the points are grouped into aggregates of about 15 neighbours,
  /// level after level, down to at most FlowFieldParams::directSolveLimit points, which Ceres
  /// solves by sparse Cholesky; each finer level starts from the prolongated coarse solution
  /// (smoothed by damped Jacobi, scaled by an exact line search) and runs
  /// FlowFieldParams::relaxationSweeps symmetric Gauss-Seidel sweeps. Fast, approximate: on
  /// the fig. 8.16 part within about 2 degrees of Direct (tests/bench); more near
  /// singularities, whose position may shift by a raster spacing.
  Multilevel,
  /// One Ceres sparse Cholesky (CHOLMOD) solve of the whole problem: the exact reference,
  /// seconds on the 127,500-point fig. 8.16 part.
  Direct
};

/// @brief Options of flowField().
struct FlowFieldParams {
  /// Raw direction (default: the direction of maximum curvature).
  FlowFieldSource source = FlowFieldSource::MaxCurvatureDirection;
  /// Direction for FlowFieldSource::FixedDirection, part frame, any length > 0 (default: +x).
  ddf::Vec3 fixedDirection = ddf::Vec3::UnitX();
  /// Smooth the raw field by least squares (default true).
  bool smoothing = true;
  /// Weight lambda of the smoothness term, dimensionless (default 0.02). With anisotropy
  /// weighting the field is smooth over lengths below about sqrt(lambda) / |k_max - k_min|,
  /// i.e. it follows the principal direction where that is much shorter than the region.
  double smoothnessWeight = 0.02;
  /// Weight the data term of a curvature source by the anisotropy |k_max - k_min| (1/mm) times
  /// sqrt(point area) (default true): scale-invariant, and umbilic regions are left to the
  /// smoothness term. When false, and for FixedDirection, every defined point has weight 1.
  bool anisotropyWeighting = true;
  /// Largest number of Ceres iterations of the Direct solve (default 10; the problem is
  /// linear, so 1-3 suffice).
  int iterations = 10;
  /// Support faces of the region to solve, one entry per face, non-zero = in the region
  /// (default empty: every face). Only the region's raster points (those with a copy on a
  /// region face) are computed and set, at all their copies; every other copy stays zero
  /// (undefined). The smoothness term couples region points only.
  std::vector<std::uint8_t> faceMask;
  /// Directions drawn by the user for FlowFieldSource::UserStrokes: polylines on or near the
  /// surface, mm, part frame; the order of the points of a stroke does not matter (default
  /// none). With smoothing, raster points within strokeRadiusSpacings of a stroke are tied
  /// (weight 1) to the tangent of the nearest stroke segment projected onto their tangent
  /// plane, and the smoothness term fills in the rest (harmonic interpolation); if no point is
  /// within reach, every point is tied to its nearest segment. Without smoothing every point
  /// takes the projected tangent of its nearest segment.
  std::vector<std::vector<ddf::Vec3>> strokes;
  /// Reach of a stroke's data term, in raster spacings (mean lattice edge length), > 0
  /// (default 2).
  double strokeRadiusSpacings = 2.0;
  /// Solver of the smoothing problem (default Multilevel).
  FlowFieldSolver solver = FlowFieldSolver::Multilevel;
  /// Multilevel: symmetric Gauss-Seidel sweeps on every level above the coarsest, >= 0
  /// (default 10); more is more accurate and slower.
  int relaxationSweeps = 10;
  /// Multilevel: the coarsest level, solved by Ceres' sparse Cholesky, has at most this many
  /// points, >= 1 (default 20000: one coarse level on the fig. 8.16 part, none on small parts).
  int directSolveLimit = 20000;
  /// Progress in [0, 1]; returning false cancels (default: none).
  ProgressCallback progress;
};

/// @brief The tool flow field of @p ddf: a unit tangent line field at every stored raster point
/// copy (LineField layout; copies of one point get the same line), in the part frame.
///
/// Raw field: at every distinct raster point the source directions of all its copies are
/// projected onto the point's tangent plane (normal: area-weighted normal of the incident
/// raster triangles) and averaged as doubled angles e^{2 i a}, so the result never depends on
/// the sign of any input direction. A point whose projections vanish or cancel is undefined
/// (zero vector). With smoothing, the solver (FlowFieldParams::solver) minimises over one
/// doubled-angle vector z_p in R^2 per point sum_p |w_p (z_p - e^{2 i a_p})|^2 + lambda sum_edges
/// |z_q - e^{2 i rho_pq} z_p|^2 over the lattice edges (rho_pq: discrete Levi-Civita transport
/// along the edge), then normalises: close to the raw field where it is weighted strongly, smooth
/// (harmonic) where it is not. Undefined raw points get weight 0 and are filled by the smoothness
/// term; a connected part of the region without any data (e.g. far from all strokes) stays
/// undefined.
/// @param curvature computeCurvature(ddf) or compatible (F * pointsPerFace entries); only the
/// size is checked for FixedDirection and UserStrokes.
/// @throws InvalidInput if the curvature size does not match the DDF, the DDF has no faces, the
/// fixed direction is zero or not finite, smoothnessWeight < 0, iterations < 1, the face mask
/// size is neither 0 nor the face count, UserStrokes has no stroke with two distinct points or
/// a non-finite point, strokeRadiusSpacings <= 0, relaxationSweeps < 0 or
/// directSolveLimit < 1.
/// @throws Cancelled if params.progress asks to stop.
LineField flowField(const ddf::DisplacementField& ddf, const CurvatureField& curvature,
                    const FlowFieldParams& params = {});

/// @brief A singularity of a line field inside one raster triangle.
struct FieldSingularity {
  int face = 0;                         ///< support face
  ddf::Vec3 bary = ddf::Vec3::Zero();   ///< barycentric (mu1, mu2, mu3) in the face: the centroid
                                        ///< of the raster triangle
  ddf::Vec3 point = ddf::Vec3::Zero();  ///< the represented surface point there, mm
  double index = 0.0;                   ///< index, a non-zero multiple of 1/2
};

/// @brief Singularities of line field @p field (LineField layout) on @p ddf: the index of every
/// raster triangle from the rotation of the field around it. Lines are compared as doubled
/// angles in the tangent frames of the raster points (the first copy of each point is used),
/// relative to discrete Levi-Civita transport along the triangle's edges, plus the triangle's
/// holonomy (angle excess), so on a closed support the indices sum to the Euler characteristic
/// of the support (2 for a sphere, 0 for a torus) whenever the field is defined everywhere.
/// Triangles touching an undefined (zero) line are skipped.
/// @throws InvalidInput if the field size does not match the DDF.
std::vector<FieldSingularity> findSingularities(const ddf::DisplacementField& ddf,
                                                const LineField& field);

}  // namespace ddfcam::planning
