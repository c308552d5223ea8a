// SPDX-License-Identifier: MIT
// ddfcam: streamlines of a line field on a DDF, traced by RK4 in the support faces (sec. 8.3).
#pragma once

#include <ddfcam/ddf/displacement_field.h>
#include <ddfcam/ddf/surface_sampling.h>
#include <ddfcam/planning/flow/line_field.h>
#include <ddfcam/progress.h>

#include <cstddef>
#include <cstdint>
#include <vector>

namespace ddfcam::planning {

/// @brief Options of traceStreamline() and seedAlongTransverse().
struct StreamlineParams {
  /// RK4 step as arc length, mm; 0 picks the mean raster spacing (mean support edge length /
  /// (m - 1)) (default 0).
  double stepMm = 0.0;
  /// Largest length of the whole line (both directions together), mm (default 1e4).
  double maxLengthMm = 1e4;
  /// Largest number of RK4 steps of the whole line (default 1,000,000).
  int maxSteps = 1000000;
  /// A line closes a loop when, after at least minLoopLengthMm, it comes closer than this to
  /// the seed, mm; 0 picks the step (default 0).
  double loopToleranceMm = 0.0;
  /// Length before the loop test starts, mm; 0 picks 10 x loopTolerance (default 0).
  double minLoopLengthMm = 0.0;
  /// The line stops at a singularity when the weighted mean of the sign-aligned unit field
  /// vectors of the raster triangle around a point is shorter than this (their directions
  /// disagree), in [0, 1] (default 0.5). A zero (undefined) entry always stops the line.
  double minCoherence = 0.5;
  /// Polylines (points in mm, part frame) that the line must not come near (fig. 8.11: stop
  /// at a point that already belongs to a streamline) (default none).
  std::vector<std::vector<ddf::Vec3>> existingPaths;
  /// Distance to existingPaths at which the line stops (tested at every point after the seed),
  /// mm; 0 disables the test (default 0).
  double nearPathDistanceMm = 0.0;
  /// Support faces the line may run on, one entry per face (non-zero: allowed), e.g. the
  /// faces of one region; the line stops where it would enter a face that is not allowed.
  /// Empty: every face (default).
  std::vector<std::uint8_t> faceMask;
  /// Progress in [0, 1] (fraction of maxLengthMm or of the seeds); returning false cancels
  /// (default: none).
  ProgressCallback progress;
};

/// @brief A traced streamline: surface locations from one end to the other.
struct Streamline {
  /// Why an end of the line stopped.
  enum StopReason {
    Boundary,          ///< reached an open edge of the support
    RegionBoundary,    ///< reached the edge of the faces allowed by StreamlineParams::faceMask
    ClosedLoop,        ///< came back to the seed (then only one direction is traced)
    Singularity,       ///< undefined or incoherent field (umbilic, singular point)
    NearExistingPath,  ///< closer than nearPathDistanceMm to an existing path
    MaxLength          ///< maxLengthMm or maxSteps used up
  };
  /// Points on the DDF surface in order; consecutive points are at most one step apart.
  /// Seam crossings appear as points on the shared edge, located in the face being entered.
  std::vector<ddf::SurfaceLocation> points;
  StopReason stop = MaxLength;          ///< why the last point's end stopped
  StopReason backwardStop = MaxLength;  ///< why the first point's end stopped
  std::size_t seedIndex = 0;            ///< index of the seed in points
  double lengthMm = 0.0;                ///< polyline length, mm

  /// @brief The 3D points (#points, mm, part frame).
  std::vector<ddf::Vec3> polyline() const;

  bool operator==(const Streamline&) const = default;
};

/// @brief The streamline of line field @p field through @p seed, traced in both directions
/// and joined (the backward half reversed, then the forward half; "forward" is the sign of
/// the field at the seed whose largest-magnitude component is positive, so negating any field
/// entries gives the same line). Each step is a classical RK4 step of length stepMm in the
/// barycentric domain of the current support face: the field is interpolated linearly over
/// the raster triangle (after aligning each entry's sign with the previous step), projected
/// onto the tangent plane of the DDF surface g + h v there and normalised, and mapped to the
/// parameter domain by the least-squares inverse of the surface Jacobian. A step leaving the
/// face is cut at the edge; the crossing point carries its barycentric weights exactly over
/// to the neighbouring face across that support edge (shared vertices) and the line goes on
/// there. Stops: see Streamline::StopReason.
/// @param field line field laid out like ddf.allHeights() (zero entries: undefined).
/// @param seed a location on the surface (face, bary; h and point are recomputed).
/// @throws InvalidInput if the field size is wrong, the seed face is out of range or its
/// barycentric coordinates are not finite, a length or step parameter is negative, or the
/// face mask is not empty and not sized like the faces. A seed on a face outside the mask
/// gives a one-point line stopped at RegionBoundary at both ends.
/// @throws Cancelled if params.progress asks to stop.
Streamline traceStreamline(const ddf::DisplacementField& ddf, const LineField& field,
                           const ddf::SurfaceLocation& seed, const StreamlineParams& params = {});

/// @brief The streamline tracers of sec. 8.3.
enum class StreamlineMethod {
  Rk4,         ///< traceStreamline(): RK4 in the support faces' parameter domains
  RasterWalk,  ///< traceStreamlineRasterWalk(): raster walk, error compensation, low-pass
  Continuous   ///< traceStreamlineContinuous(): 3D steps re-projected by V-projection
};

/// @brief The streamline through @p seed traced by @p method with that method's default
/// options (RasterWalkParams, ContinuousStreamlineParams); stops, sign rule and joining are the
/// same for every method (see traceStreamline()).
/// @throws InvalidInput, Cancelled as traceStreamline(); InvalidInput for an unknown method.
Streamline traceStreamlineWith(StreamlineMethod method, const ddf::DisplacementField& ddf,
                               const LineField& field, const ddf::SurfaceLocation& seed,
                               const StreamlineParams& params = {});

struct RasterWalkParams;
struct ContinuousStreamlineParams;

/// @brief As above with the method's own options (declared in streamline_raster_walk.h and
/// streamline_continuous.h); the options of the other methods are ignored. Pass a crust hash
/// in @p continuous when tracing many lines with the continuous method.
Streamline traceStreamlineWith(StreamlineMethod method, const ddf::DisplacementField& ddf,
                               const LineField& field, const ddf::SurfaceLocation& seed,
                               const StreamlineParams& params, const RasterWalkParams& walk,
                               const ContinuousStreamlineParams& continuous);

/// @brief Short lower-case name of @p method ("rk4", "raster-walk", "continuous").
const char* streamlineMethodName(StreamlineMethod method);

/// @brief A family of streamlines of @p field seeded along one streamline of
/// @p transverseField (figs. 8.11/8.13): the transverse line through @p seed is traced, seeds
/// are placed on it every @p spacingMm of arc length in both directions from @p seed
/// (including @p seed), and the field's streamline is traced from each, in order along the
/// transverse line. Each line is traced with @p params independently of the others.
/// @param spacingMm seed spacing w along the transverse line, mm (> 0).
/// @throws InvalidInput as traceStreamline, or if spacingMm <= 0 or a field size is wrong.
/// @throws Cancelled if params.progress asks to stop.
std::vector<Streamline> seedAlongTransverse(const ddf::DisplacementField& ddf,
                                            const LineField& field,
                                            const LineField& transverseField,
                                            const ddf::SurfaceLocation& seed, double spacingMm,
                                            const StreamlineParams& params = {});

/// @brief The seed locations used by seedAlongTransverse(): points of @p transverse every
/// @p spacingMm of arc length from its seed point in both directions, in order along the line
/// (the seed included).
/// @throws InvalidInput if spacingMm <= 0.
std::vector<ddf::SurfaceLocation> seedsAlong(const ddf::DisplacementField& ddf,
                                             const Streamline& transverse, double spacingMm);

/// @brief Moving-average low-pass filter of sec. 8.3: point i becomes the mean of the
/// 2 k' + 1 points around it with k' = min(halfWindow, i, N - 1 - i), so the end points stay
/// and the window stays centred. The result is not re-projected onto the surface (its
/// deviation is O(k^2 step^2 curvature)).
/// @param points #N points, mm.
/// @param halfWindow k >= 0 (0 returns the input).
/// @throws InvalidInput if halfWindow < 0.
std::vector<ddf::Vec3> smoothMovingAverage(const std::vector<ddf::Vec3>& points, int halfWindow);

/// @brief smoothMovingAverage of @p line's polyline, put back onto the DDF surface: each
/// filtered point is located (ddf::locateOnFace) on the faces of the raw points in its window
/// and the nearest surface point wins (the filter also slides points along the line, possibly
/// off their raw face). A filtered point whose foot lies on none of those faces is clamped
/// onto the nearest of them; one no face of its window can locate keeps its raw location.
/// Stop reasons and seed index are kept; lengthMm is recomputed.
/// @param line a streamline on @p ddf (faces in range).
/// @param halfWindow k >= 0 (0 re-locates the raw points).
/// @return the smoothed line, #line.points locations (mm, part frame).
/// @throws InvalidInput if halfWindow < 0.
Streamline smoothOnSurface(const ddf::DisplacementField& ddf, const Streamline& line,
                           int halfWindow);

/// @brief smoothOnSurface of every line of @p lines (same order).
/// @throws InvalidInput if halfWindow < 0.
std::vector<Streamline> smoothOnSurface(const ddf::DisplacementField& ddf,
                                        const std::vector<Streamline>& lines, int halfWindow);

}  // namespace ddfcam::planning
