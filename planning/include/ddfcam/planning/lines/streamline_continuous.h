// SPDX-License-Identifier: MIT
// ddfcam: streamlines stepped in 3D and re-projected onto the DDF by V-projection (sec. 8.3).
#pragma once

#include <ddfcam/ddf/crust_hash.h>
#include <ddfcam/ddf/displacement_field.h>
#include <ddfcam/ddf/surface_sampling.h>
#include <ddfcam/planning/flow/line_field.h>
#include <ddfcam/planning/lines/streamline.h>

namespace ddfcam::planning {

/// @brief The 3D integration scheme of traceStreamlineContinuous().
enum class ContinuousIntegrator {
  Euler,  ///< the dissertation's literal step: one re-projection per step
  Heun,   ///< explicit trapezoid (RK2): two re-projections per step
  Rk4     ///< classical RK4: four re-projections per step
};

/// @brief Options of traceStreamlineContinuous() beyond StreamlineParams.
struct ContinuousStreamlineParams {
  /// Integration scheme; every stage point is re-projected onto the surface (default Heun).
  ContinuousIntegrator integrator = ContinuousIntegrator::Heun;
  /// Crust hash of the same DDF (same faces, positions and vectors) giving the candidate faces
  /// of each re-projection; not owned, must outlive the call. Null builds one per call, which
  /// costs about as much as a short line: pass one when tracing many lines (default null).
  const ddf::CrustHash* crustHash = nullptr;
};

/// @brief The streamline of line field @p field through @p seed by the dissertation's
/// continuous method (sec. 8.3, fig. 8.12): from a surface point p the line steps in 3D by
/// stepMm (StreamlineParams, default the mean raster spacing) along the interpolated field
/// (sign-aligned, projected onto the tangent plane, normalised) to q' = p + s w, and q' is
/// re-projected onto the DDF (surface point g + h(foot) v at the V-projection foot,
/// ddf::vProject): a root of the previous point's face with its foot on that face continues
/// the line (nearly every step, no search); else every face of the crust hash cell of q' is
/// V-projected and of the roots whose foot lies on its face the one whose surface point is
/// nearest the previous point wins. Roots with |h| > 2 are ignored. Heun and
/// RK4 re-project every stage point. Where q' has no foot on an allowed face, the step is cut
/// where the V-projection of q' onto the current face leaves that face: at an open edge the line
/// stops (Boundary), at a masked face (StreamlineParams::faceMask) it stops (RegionBoundary),
/// otherwise it goes on from the edge point in the neighbouring face. Sign rule, joining of both
/// halves and the other stop reasons are those of traceStreamline(). Consecutive points are
/// about one step apart and may lie in different faces.
/// @param field line field laid out like ddf.allHeights() (zero entries: undefined).
/// @param seed a location on the surface (face, bary; h and point are recomputed).
/// @throws InvalidInput as traceStreamline().
/// @throws Cancelled if params.progress asks to stop.
Streamline traceStreamlineContinuous(const ddf::DisplacementField& ddf, const LineField& field,
                                     const ddf::SurfaceLocation& seed,
                                     const StreamlineParams& params = {},
                                     const ContinuousStreamlineParams& continuous = {});

}  // namespace ddfcam::planning
