// SPDX-License-Identifier: MIT
// ddfcam: ready-made DDFs of analytic surfaces with their exact surface (test parts, demo part).
#pragma once

#include <ddfcam/ddf/analytic_surface.h>
#include <ddfcam/ddf/bspline_patch.h>
#include <ddfcam/ddf/displacement_field.h>

#include <Eigen/Core>

#include <memory>
#include <numbers>
#include <vector>

namespace ddfcam::ddf {

/// @brief A generated DDF and the exact surfaces it was made from.
///
/// Every raster point q = g + h v of @c ddf lies on @c surface up to the float rounding of h
/// (|h| <= 1): the heights are roots of surface->value(g + h v) = 0 solved to ~1e-12 in double.
struct GeneratedSurface {
  DisplacementField ddf;                           ///< the field, heights filled
  std::shared_ptr<const AnalyticSurface> surface;  ///< exact surface of the raster points
  /// Design (target) surface of the part: the same object as @c surface unless the generator
  /// added a stock allowance (demoPart), in which case @c surface is the stock.
  std::shared_ptr<const AnalyticSurface> design;
};

/// @brief Fills the heights of a DDF on (@p support, @p vectors, @p m) so that its raster points
/// lie on @p surface: for every raster point the root of value(g + h v) = 0 nearest to h = 0 in
/// [-1, 1] is bracketed (scan outwards from 0 in steps of 1/8) and refined by Newton's method
/// safeguarded by bisection to |dh| < 1e-13. Faces are processed in parallel (TBB). Copies of
/// points on shared edges and vertices are computed per face and agree up to the last bit of g
/// and v (summation order differs); synchronizeShared(SharedPolicy::Canonical) makes them equal.
/// @param support oriented support mesh, mm. @param vectors one vector per support vertex, mm.
/// @param m raster resolution (>= 2). @param surface the exact surface (not null).
/// @returns the DDF with @c surface and @c design both set to @p surface.
/// @throws InvalidInput for a null surface, a vector count mismatch, m < 2, or when a stubble
/// g + [-1, 1] v does not cross the surface (the message names the face and raster point of the
/// lowest failing face).
GeneratedSurface fromAnalytic(const SupportMesh& support, std::vector<Vec3> vectors, int m,
                              std::shared_ptr<const AnalyticSurface> surface);

/// @brief Plane patch z = planeZMm over a planar grid support in z = 0 with parallel vectors
/// (0, 0, vectorLengthMm): a z-map with all heights planeZMm / vectorLengthMm.
struct PlanePatchParams {
  Eigen::Vector2d origin{0.0, 0.0};  ///< lower-left support corner (x, y), mm (default: 0, 0)
  Eigen::Vector2d size{40.0, 30.0};  ///< support extent (x, y), mm (default: 40 x 30)
  int cellsX = 20;                   ///< grid cells in x, 2 triangles each (default: 20)
  int cellsY = 15;                   ///< grid cells in y (default: 15 -> 600 triangles)
  int m = 17;                        ///< raster resolution (default: 17)
  double planeZMm = 0.25;            ///< plane height c, |c| < vectorLengthMm (default: 0.25)
  double vectorLengthMm = 1.0;       ///< crust half-thickness, mm (default: 1)
};
/// @throws InvalidInput for non-positive sizes, counts or length, or |planeZMm| >= length.
GeneratedSurface planePatch(const PlanePatchParams& params = {});

/// @brief Sphere of radius R at the origin; support = icosahedron inscribed in the sphere with
/// each triangle split into 4 (midpoints pushed onto the sphere) @c subdivisions times
/// (20 * 4^s triangles, all vertices on the sphere); radial vectors of length crustFraction R.
struct SphereParams {
  double radiusMm = 10.0;      ///< R, mm (default: 10)
  int subdivisions = 3;        ///< refinement levels s, 0..7 (default: 3 -> 1280 triangles)
  int m = 17;                  ///< raster resolution (default: 17)
  double crustFraction = 0.5;  ///< vector length / R, in (0, 1) (default: 0.5)
};
/// @throws InvalidInput for R <= 0, s outside 0..7, m < 2 or crustFraction outside (0, 1).
GeneratedSurface spherePart(const SphereParams& params = {});

/// @brief Open cylinder of radius r around the z axis for 0 <= z <= length; support = a
/// segments x rings quad strip with vertices on the cylinder, each quad split in 2 (outward
/// front side); radial vectors of length crustFraction r.
struct CylinderParams {
  double radiusMm = 10.0;      ///< r, mm (default: 10)
  double lengthMm = 30.0;      ///< extent along z, mm (default: 30)
  int segments = 48;           ///< quads around the axis, >= 3 (default: 48)
  int rings = 12;              ///< quads along the axis (default: 12 -> 1152 triangles)
  int m = 17;                  ///< raster resolution (default: 17)
  double crustFraction = 0.5;  ///< vector length / r, in (0, 1) (default: 0.5)
};
/// @throws InvalidInput for non-positive sizes, segments < 3, rings < 1, m < 2 or a
/// crustFraction outside (0, 1).
GeneratedSurface cylinderPart(const CylinderParams& params = {});

/// @brief Closed torus (TorusSurface) with a segmentsU x segmentsV (u, v) grid support on the
/// torus; vectors are the exact tube normals of length crustFraction min(r, R - r), which keeps
/// the crust inside the tube (radius r) and clear of the axis side (the inner equator's parallel
/// radius of curvature is R - r).
struct TorusParams {
  double majorRadiusMm = 30.0;  ///< R, mm (default: 30)
  double minorRadiusMm = 10.0;  ///< r < R, mm (default: 10)
  int segmentsU = 48;           ///< quads around the z axis, >= 3 (default: 48)
  int segmentsV = 24;           ///< quads around the tube, >= 3 (default: 24 -> 2304 triangles)
  int m = 17;                   ///< raster resolution (default: 17)
  double crustFraction = 0.5;   ///< vector length / min(r, R - r), in (0, 1) (default: 0.5)
};
/// @throws InvalidInput for invalid radii, segment counts < 3, m < 2 or a crustFraction
/// outside (0, 1).
GeneratedSurface torusPart(const TorusParams& params = {});

/// @brief Sampling of a graph surface z = f(x, y): a cellsX x cellsY grid over the rectangle,
/// vertices lifted onto the surface (x, y, f(x, y)), each cell split in 2 triangles (front side
/// up); vectors are exact unit normals times L = min(maxVectorLengthMm, curvatureFraction /
/// kmax) with kmax the largest |principal curvature| at the grid vertices and cell centres.
/// L < 1/kmax keeps the +-1 crust a unique-projection neighbourhood; the grid must be fine
/// enough that the chord sag (~ kmax h^2 / 8 for a cell size h) stays well inside L.
struct GraphPatchParams {
  Eigen::Vector2d origin{-10.0, -10.0};  ///< lower-left (x, y) of the grid, mm (default: -10)
  Eigen::Vector2d size{20.0, 20.0};      ///< extent (x, y), mm (default: 20 x 20)
  int cellsX = 20;                       ///< grid cells in x (default: 20)
  int cellsY = 20;                       ///< grid cells in y (default: 20 -> 800 triangles)
  int m = 17;                            ///< raster resolution (default: 17)
  double maxVectorLengthMm = 2.0;        ///< upper bound on L, mm (default: 2)
  double curvatureFraction = 0.5;        ///< L <= this / kmax, in (0, 1) (default: 0.5)
};
/// @brief DDF of any height field over the grid of @p params (see GraphPatchParams).
/// @throws InvalidInput for a null surface, non-positive sizes or counts, m < 2, a fraction
/// outside (0, 1), or (from fromAnalytic) a stubble that misses the surface.
GeneratedSurface graphPatch(std::shared_ptr<const HeightFieldSurface> surface,
                            const GraphPatchParams& params);

/// @brief Saddle z = a x^2 - b y^2 over the default 20 x 20 mm grid centred at the origin
/// (L = min(2, 0.5 / 0.1) = 2 mm for a = b = 0.05).
struct SaddleParams {
  double a = 0.05;        ///< x curvature coefficient, 1/mm (default: 0.05)
  double b = 0.05;        ///< y curvature coefficient, 1/mm (default: 0.05)
  GraphPatchParams grid;  ///< sampling (default: GraphPatchParams defaults)
};
/// @throws InvalidInput as graphPatch.
GeneratedSurface saddlePatch(const SaddleParams& params = {});

/// @brief z = A sin(x/s) sin(y/s) over one period [-pi s, pi s]^2 (the curvature oracle for
/// A = s = 1; L = 0.5 mm there since kmax = 1/mm).
struct SinSinParams {
  double amplitudeMm = 1.0;  ///< A, mm (default: 1)
  double scaleMm = 1.0;      ///< s, mm (default: 1); the grid below is for s = 1
  /// Sampling (default: [-pi, pi]^2, 24 x 24 cells -> 1152 triangles); scale it with s.
  GraphPatchParams grid{.origin = {-std::numbers::pi, -std::numbers::pi},
                        .size = {2.0 * std::numbers::pi, 2.0 * std::numbers::pi},
                        .cellsX = 24,
                        .cellsY = 24};
};
/// @throws InvalidInput as graphPatch or for s <= 0.
GeneratedSurface sinSinPatch(const SinSinParams& params = {});

/// @brief The dissertation-like free-form patch (sec. 6.3, fig. 6.17: a B-spline patch
/// triangulated with 20,000 triangles and 4 x 100 boundary edges): makeBumpPatch(shape) sampled
/// on a cellsX x cellsY grid.
struct FreeformPatchParams {
  BumpPatchParams shape;           ///< B-spline (default: 100 x 100 mm, 10 x 10 spans, A = 8)
  int cellsX = 100;                ///< grid cells in x (default: 100)
  int cellsY = 100;                ///< grid cells in y (default: 100 -> 20,000 triangles)
  int m = 10;                      ///< raster resolution (default: 10, the coarsest of fig. 6.19)
  double maxVectorLengthMm = 2.0;  ///< upper bound on L, mm (default: 2)
  double curvatureFraction = 0.5;  ///< L <= this / kmax (default: 0.5)
};
/// @throws InvalidInput as graphPatch or makeBumpPatch.
GeneratedSurface freeformPatch(const FreeformPatchParams& params = {});

/// @brief The built-in demo part of the workbench and the CLI: a 40 x 30 mm free-form B-spline
/// patch (makeBumpPatch, 8 x 6 spans, A = 2.5 mm; z in about [-1.5, 1.7] mm) on a 32 x 24 grid
/// (1,536 support triangles, 1.25 mm cells) at m = 17 (~0.08 mm raster spacing, 235,008 stored
/// heights). Its smallest radius of curvature is about 12 mm (convex) and its smallest concave
/// one, seen from above, about 18 mm: larger than the 5 mm default grinding roll and ball, so a
/// tool from above can reach every point without gouging.
/// The support lies on the design surface with its exact normals of length L = 1 mm as vectors;
/// the heights represent the stock: the design raised by allowanceMm = 0.2 mm along z
/// (RaisedHeightField), a typical finish-grinding allowance, at h ~ 0.2 in the crust so that
/// h in [-1, 0) remains to show over-grinding. GeneratedSurface::design is the B-spline,
/// GeneratedSurface::surface the stock.
struct DemoPartParams {
  BumpPatchParams shape{.origin = {0.0, 0.0},
                        .size = {40.0, 30.0},
                        .spansX = 8,
                        .spansY = 6,
                        .amplitudeMm = 2.5};  ///< design surface (default: see above)
  int cellsX = 32;                            ///< grid cells in x (default: 32)
  int cellsY = 24;                            ///< grid cells in y (default: 24)
  int m = 17;                                 ///< raster resolution (default: 17)
  double maxVectorLengthMm = 1.0;             ///< upper bound on L, mm (default: 1)
  double curvatureFraction = 0.5;             ///< L <= this / kmax (default: 0.5)
  double allowanceMm = 0.2;                   ///< stock above the design along z, mm (0.2)
};
/// @throws InvalidInput as graphPatch, or for an allowance < 0 or >= 0.9 L.
GeneratedSurface demoPart(const DemoPartParams& params = {});

/// @brief Ellipsoid (EllipsoidSurface) with semi-axes (a, b, c); support = the icosphere of
/// spherePart scaled by (a, b, c) (vertices on the ellipsoid); vectors are the exact unit
/// normals times crustFraction * rmin, where rmin = min(axis)^2 / max(axis) is the smallest
/// radius of curvature, which keeps the crust a unique-projection neighbourhood.
struct EllipsoidParams {
  Vec3 axesMm{3.0, 2.0, 1.0};  ///< semi-axes (a, b, c), mm (default: 3, 2, 1)
  int subdivisions = 3;        ///< icosphere levels s, 0..7 (default: 3 -> 1280 triangles)
  int m = 17;                  ///< raster resolution (default: 17)
  double crustFraction = 0.5;  ///< vector length / rmin, in (0, 1) (default: 0.5)
};
/// @throws InvalidInput for non-positive axes, s outside 0..7, m < 2, a crustFraction outside
/// (0, 1), or (from fromAnalytic) a stubble that misses the surface.
GeneratedSurface ellipsoidPart(const EllipsoidParams& params = {});

}  // namespace ddfcam::ddf
