// SPDX-License-Identifier: MIT
// ddfcam: a crust that holds a stock allowance above the surface, and the crust's reach.
#pragma once

#include <ddfcam/ddf/displacement_field.h>
#include <ddfcam/ddf/triangle_mesh.h>
#include <ddfcam/progress.h>

#include <limits>
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
  int minBelowFace = -1;              ///< support face of the smallest reach below
  Vec3 minBelowPoint = Vec3::Zero();  ///< surface point of the smallest reach below, mm
};

/// @brief The crust reach of @p ddf over all its stored raster points (shared copies counted
/// once per face; computed in parallel). The normal is ddf::rasterNormal. A point whose
/// vector is tangent to the surface has reach 0. An empty field gives the zero defaults.
CrustReach crustReach(const DisplacementField& ddf);

/// @brief Radius of the tightest concave curvature of @p mesh near @p point, mm (+inf where
/// the mesh is convex or flat there).
///
/// Estimator: the triangles whose centroid lies within @p neighbourhoodMm of @p point (the
/// radius is doubled up to six times until at least 8 are found; at most the 256 nearest are
/// used) give pairs (centroid c, unit front normal n, as (v1 - v0) x (v2 - v0)); in the tangent
/// frame of the nearest one's normal the tangential part of n is fitted by least squares as an
/// affine function of the tangential part of c - point. The symmetrised linear part is the shape
/// operator (the derivative of the normal along the surface); its smallest eigenvalue, when
/// negative, is the largest concave curvature (curving towards the front side), and the
/// radius is its inverse. On a circle both tangential parts are sin(angle) times 1 and r, so
/// the fit is exact for any neighbourhood; on a faceted cylinder of radius r it returns the
/// radius of the centroids (r cos(pi / N) to within the facets' offsets). A sharp concave edge
/// gives a radius of the order of the triangle size.
/// @param neighbourhoodMm search radius, mm (> 0), e.g. the allowance or a few edge lengths.
double concaveRadiusNear(const TriangleMesh& mesh, const Vec3& point, double neighbourhoodMm);

/// @brief Where and why the crust cannot hold a requested allowance.
struct StockLimit {
  int face = -1;              ///< support face where the crust is too thin
  Vec3 point = Vec3::Zero();  ///< surface point there, mm
  /// Radius of the tightest concave curvature of the input near the point, mm (+inf where the
  /// limit has another cause, e.g. a thin wall or a neighbouring sheet).
  double concaveRadiusMm = 0.0;
  /// Support face whose crust the crust of @p face would meet (a neighbouring sheet across a
  /// gap or a thin wall), or -1.
  int otherFace = -1;
  /// Largest allowance the fitted crust holds everywhere, mm: its smallest reach above (so
  /// workpieceWithAllowance accepts it, and fitCrustToStock asked for it holds).
  double largestAllowanceMm = 0.0;
  std::string message;  ///< the refusal: place, radius, largest allowance
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
  /// The crust limits of the unmoved support are used at safety x h0 (as in sec. 4.4), and
  /// every fitted face must keep crust heights >= 1 / safety. In (0, 1]. Default 0.95.
  double safety = 0.95;
  /// Choose the vector directions too (see fitCrustToStock); false keeps the converted ones.
  /// Default true.
  bool chooseDirections = true;
  /// Angle bound of the chosen directions against the represented surface's normals at the
  /// vertex, degrees (a direction already further off keeps at least its converted angle), as
  /// SupportReductionParams::maxAngleDeg. In (0, 90). Default 45.
  double maxAngleDeg = 45.0;
  /// Passes of averaging each chosen direction with its neighbours' (>= 0): more passes make
  /// the stubbles over a concave crease more nearly parallel, but on a coarse reduced support
  /// rotate long stubbles further (see fitCrustToStock). Default 4.
  int smoothingPasses = 4;
  /// Re-choose the chosen directions near folds (see fitCrustToStock). Default true.
  bool repairFolds = true;
  /// Angle bound of a direction re-chosen near a fold (see fitCrustToStock) against the
  /// surface normals at the vertex, degrees (a direction already further off keeps at least
  /// its converted angle). In [maxAngleDeg, 90). Default 60.
  double foldRepairAngleDeg = 60.0;
  /// Bound on the shrink passes per settle and on the non-adjacent conflict rounds.
  /// Default 30.
  int maxRounds = 30;
  /// Progress in [0, 1] and cancellation (throws Cancelled, @p ddf unchanged). Default none.
  ProgressCallback progress;
};

/// @brief Chooses support offsets and vector lengths of @p ddf so that its crust reaches at
/// least params.stockMm (plus margin) above the surface represented by the heights of @p ddf
/// while the unique-projection property (constraint 3) still holds, then refills the heights
/// from @p input so the represented surface is unchanged. Where no choice works the field is
/// left valid with the largest reach found and the result's limit names the place.
///
/// Directions (params.chooseDirections). The normal-limited reach of a concave region exists
/// only for vectors near the surface normals; so every vertex first gets a direction d: the
/// corner-angle weighted mean of the represented surface's normals around it, averaged
/// params.smoothingPasses times with its neighbours' (stubbles of a face then converge less),
/// each step blended back towards the converted direction as far as needed to keep
/// constraint 1 on every incident support face and d within params.maxAngleDeg of the surface
/// normals there. Near a fold the directions are then re-chosen: a support face's crust folds
/// on its top side when the tops of its stubbles, p + hi d, are displaced across the face by
/// more than its width, which a sliver face (a fraction of a mm wide, several mm long) next to a
/// tight convex edge of a reduced support does at a few tenths of a mm wherever its vertices'
/// directions differ: a vertex whose support faces wrap around the edge must keep its vector
/// nearly tangent to some of them (constraint 1), and seen along that vector a small difference
/// of the tops' heights is a large shift. So every face gets a fold score, the smaller of its
/// crust height h0+ with each vertex vector sized to the top the fit will need there (2 x the
/// reach over the vector's cosine with the surface normals, the cosine at least 0.3) against
/// 1.2 and of its unit-vector h0- against 1.2 x the converted lengths, and each vertex of a
/// face scoring below 1 tries its neighbours' directions, their mean, and blends towards them
/// (within constraint 1 and params.foldRepairAngleDeg), keeping the one with the best smallest
/// score over its faces; a few passes (params.repairFolds). A vertex moves from the converted
/// vector (s = 0) to its target (s = 1) along both direction and interval. Where the chosen
/// directions do not hold the allowance, the fit is repeated with the chosen directions unrepaired
/// and with the converted directions, and the largest smallest reach is kept.
///
/// Design. Every vertex gets a crust interval [lo, hi] of offsets along d from its support
/// point p: the support moves to p + (lo + hi)/2 d and the
/// vector becomes (hi - lo)/2 d, so with the surface at offset sigma the reach above is about
/// (hi - sigma)(d . n) and below (sigma - lo)(d . n). A symmetric crust (longer vectors, the
/// sec. 4.4 choice with a larger maximum length) can only grow until the tighter side's crust
/// height h0 of the unmoved support is reached; on a convex region that is the inside (the
/// normals meet at the centre of curvature) while the outside is unbounded, so the interval
/// is made asymmetric: hi = min(safety h0+, sigma + stock (1 + margin) / (d . n)), and the
/// reach below is the same as above where safety h0- allows it, else what h0- allows. The
/// outward offset this implies is what a concave region forbids: there h0+ is the concave
/// radius (the offset sheets of the two sides meet), which is then the limit.
/// The interval always contains the converted one ([-L, L] of the vector length L), so the
/// reach below never falls below the converted field's; that is the minimum kept for a
/// simulation's gouges. Faces whose fitted crust heights fall below 1 / safety, or whose +-1
/// crusts meet those of non-adjacent faces (findCrustConflicts on a CrustHash), pull their
/// vertices' intervals back towards the converted ones until none does; a face or pair that
/// already failed in @p ddf is left as it was. The reach is then measured per raster point
/// and vertices short of it get a longer interval (up to six correction passes, the best kept).
/// After every refill, a face with a raster point whose stubble misses the input and whose kept
/// height lies further off the input than the converted point did gets its vertices' converted
/// directions back, and on a second such drift their converted vectors, so the represented
/// surface is the converted one.
/// @param ddf converted field (support, vectors, heights from @p input); changed in place.
/// @param input the input surface, mm, part frame.
/// @throws InvalidInput for a non-positive allowance or a parameter out of range; Cancelled
/// through params.progress.
StockFit fitCrustToStock(DisplacementField& ddf, const TriangleMesh& input,
                         const StockCrustParams& params);

}  // namespace ddfcam::ddf
