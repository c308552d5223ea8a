// SPDX-License-Identifier: MIT
// ddfcam: unique-projection crust heights of support triangles and crust intersection (sec. 4.3).
#pragma once

#include <ddfcam/ddf/crust_hash.h>
#include <ddfcam/ddf/displacement_field.h>
#include <ddfcam/ddf/support_mesh.h>

#include <array>
#include <limits>
#include <span>
#include <vector>

namespace ddfcam::ddf {

/// @brief Largest crust heights with the unique-projection property of one support triangle,
/// for both sides, as magnitudes in units of the vertex vectors (dimensionless).
struct CrustHeights {
  /// h0 of the h-crust, h > 0; +inf when no height bounds it.
  double positive = std::numeric_limits<double>::infinity();
  /// |h0| of the -h-crust, h < 0; +inf when no height bounds it.
  double negative = std::numeric_limits<double>::infinity();
  /// @brief min(positive, negative): the +-h crust is unique for h below this.
  double min() const { return positive < negative ? positive : negative; }
};

/// @brief Unique-projection crust heights (h0 of sec. 4.3) of the triangle (p1, p2, p3) with
/// vertex vectors (v1, v2, v3).
///
/// The determinant det[sum mu_i v_i, dp12 + h dv12, dp13 + h dv13] of the dissertation is the
/// Jacobian determinant of Phi(mu, h) = sum mu_i (p_i + h v_i) and is linear in mu: it equals
/// sum mu_i D_i(h) with the quadratics D_i(h) = v_i . (e12(h) x e13(h)), e1k(h) the edges of
/// the h-offset triangle. Under constraint 1 every D_i(0) = v_i . n > 0. A linear function on
/// the simplex vanishes somewhere exactly when its smallest vertex value is <= 0, so h0 is the
/// smallest positive root over the three D_i (and likewise for h < 0). This is the exact
/// minimum of the dissertation's optimisation, in closed form.
/// @param p1,p2,p3 vertices, mm. @param v1,v2,v3 vertex vectors, mm per unit height.
/// @return Both heights are 0 when constraint 1 is violated (some D_i(0) <= 0).
CrustHeights crustHeights(const Vec3& p1, const Vec3& p2, const Vec3& p3, const Vec3& v1,
                          const Vec3& v2, const Vec3& v3);

/// @brief Crust heights of support face @p face of @p ddf with its current vectors.
CrustHeights crustHeights(const DisplacementField& ddf, int face);

/// @brief Crust heights of every support face of @p ddf (#F entries, computed in parallel).
std::vector<CrustHeights> allCrustHeights(const DisplacementField& ddf);

/// @brief A triangle in space, three vertices in mm.
using SpaceTriangle = std::array<Vec3, 3>;

/// @brief Triangulated boundary of the +-@p height crust of support face @p face: the two
/// offset triangles at h = -height and h = +height and the three ruled side patches, each
/// split into @p edgeSteps strips along the edge and two rows in h (at -height, 0, +height).
/// The ruled patches are bilinear; their triangulation deviates from them by the patch twist.
/// @return 2 + 12 edgeSteps triangles, mm.
std::vector<SpaceTriangle> crustBoundary(const DisplacementField& ddf, int face,
                                         double height = 1.0, int edgeSteps = 3);

/// @brief Parameters of the crust intersection test.
struct CrustIntersectionParams {
  /// Strips per side patch in the boundary triangulation (see crustBoundary). Default 3.
  int edgeSteps = 3;
  /// Crust half-thickness tested, in units of the vectors. Default 1 (the +-1 crust).
  double height = 1.0;
};

/// @brief Whether the +-height crusts of support faces @p s and @p t of @p ddf intersect.
///
/// Each crust lies in the convex hull of its six corners p_i +- height v_i, so a separating
/// axis of the two hulls (from the support normals, side-wall normals and edge cross products)
/// proves them disjoint. Otherwise the triangulated boundaries are tested pairwise, and the
/// centroid stubble of each face (at h = 0 and +-height) is tested for containment in the other
/// crust by V-projection (a point is inside the crust of s iff it has a V-projection on s with
/// mu inside and |h| <= height), which catches one crust inside the other and stacked crusts
/// with coplanar walls. Exactly touching crusts may go either way. Meant for faces sharing no
/// vertex: adjacent crusts touch along shared boundaries and are reported as intersecting.
bool crustsIntersect(const DisplacementField& ddf, int s, int t,
                     const CrustIntersectionParams& params = {});

/// @brief Per vertex of @p ddf, the smallest index of a vertex at the same position within
/// @p toleranceMm (0 = 1e-9 x the bounding-box diagonal): classes of coincident vertices, as in
/// an unwelded STL. #V entries.
std::vector<int> coincidentVertexClasses(const DisplacementField& ddf, double toleranceMm = 0.0);

/// @brief Whether support faces @p s and @p t have a vertex in common; with @p vertexClasses
/// (from coincidentVertexClasses) a common position counts as a common vertex.
bool facesShareVertex(const DisplacementField& ddf, int s, int t,
                      std::span<const int> vertexClasses = {});

/// @brief Pairs of support faces that share no vertex and whose crusts intersect (the
/// non-adjacent part of constraint 3), found among the candidates of @p hash.
/// @param hash crust hash of @p ddf built for its current vectors (it covers the +-1 crusts,
/// so params.height must not exceed 1).
/// @param faces the faces to check against all their candidates.
/// @param vertexClasses optional coincident-vertex classes: faces meeting at a common position
/// count as adjacent (their crusts touch there).
/// @return pairs (s, t) with s < t, sorted, unique. Runs in parallel over @p faces.
std::vector<std::array<int, 2>> findCrustConflicts(const DisplacementField& ddf,
                                                   const CrustHash& hash,
                                                   std::span<const int> faces,
                                                   const CrustIntersectionParams& params = {},
                                                   std::span<const int> vertexClasses = {});

/// @brief As above, checking every face of @p ddf.
std::vector<std::array<int, 2>> findAllCrustConflicts(const DisplacementField& ddf,
                                                      const CrustHash& hash,
                                                      const CrustIntersectionParams& params = {},
                                                      std::span<const int> vertexClasses = {});

/// @brief Whether point @p x (mm) lies in the +-@p height crust of face @p face (V-projection
/// with mu inside and |h| <= height, within 1e-9 relative tolerance).
bool crustContains(const DisplacementField& ddf, int face, const Vec3& x, double height = 1.0);

/// @brief Whether triangles @p a and @p b (mm) intersect, by edge-against-triangle tests with
/// signed volumes; touching counts. Exactly coplanar pairs are reported as disjoint (a case of
/// measure zero that crustsIntersect covers by its containment tests).
bool trianglesIntersect(const SpaceTriangle& a, const SpaceTriangle& b);

}  // namespace ddfcam::ddf
