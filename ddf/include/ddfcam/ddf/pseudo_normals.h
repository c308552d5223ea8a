// SPDX-License-Identifier: MIT
// ddfcam: vertex pseudo-normals of a support mesh, repaired to satisfy constraint 1 (ch. 3, 6).
#pragma once

#include <ddfcam/ddf/support_mesh.h>

#include <optional>
#include <span>
#include <vector>

namespace ddfcam::ddf {

/// @brief Parameters of the pseudo-normal computation.
struct PseudoNormalParams {
  /// A vertex normal v needs n_f . v > minFrontCosine for every incident face f (unit n_f):
  /// a margin of front-facing-ness for constraint 1. Default 0.05 (about 87 degrees).
  double minFrontCosine = 0.05;
};

/// @brief Unit vertex directions for a DDF vector field plus what had to be repaired.
struct PseudoNormalResult {
  std::vector<Vec3> normals;            ///< #V unit vectors (part frame)
  std::vector<int> repairedVertices;    ///< vertices moved off the angle-weighted normal
  std::vector<int> infeasibleVertices;  ///< vertices with no front-facing direction at all
};

/// @brief Angle-weighted vertex pseudo-normals of @p mesh, repaired for constraint 1.
///
/// The pseudo-normal sum_f alpha_f n_f (alpha_f the corner angle of face f at the vertex) does
/// not depend on how a flat region is triangulated. Where some incident face sees it at
/// n_f . v <= minFrontCosine, v is moved towards the maximin direction v* (maximising
/// min_f n_f . v) just far enough to reach the margin, or all the way when the best margin is
/// smaller. When even v* has min_f n_f . v* <= 0 (the incident faces' front half-spaces have no
/// common direction) the vertex keeps its pseudo-normal and is listed as infeasible.
/// Degenerate (zero-area) faces are ignored; a vertex without usable faces gets +z.
/// @param mesh support mesh (front side = counter-clockwise normal side).
PseudoNormalResult pseudoNormals(const SupportMesh& mesh, const PseudoNormalParams& params = {});

/// @brief The unit direction v maximising min_i n_i . v over unit vectors @p normals.
///
/// By duality, when the origin is outside the convex hull of the normals, it is the normalised
/// point of the hull nearest to the origin; in 3D that point lies on a hull vertex, edge or
/// triangle, so all of them are tried. O(k^4) for k normals: meant for vertex fans.
/// @return the direction and its margin min_i n_i . v; std::nullopt for an empty input. The
/// margin is the exact optimum when that is positive; otherwise (no common front direction)
/// only its sign (<= 0) is meaningful and the direction is merely the best candidate tried.
std::optional<std::pair<Vec3, double>> maximinDirection(std::span<const Vec3> normals);

}  // namespace ddfcam::ddf
