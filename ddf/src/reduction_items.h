// SPDX-License-Identifier: MIT
// ddfcam (private): item buffers of the support reduction (sec. 6.2): the input triangles a
// support face's V-rays hit, and the checks that need them (coverage, angle, containment).
#pragma once

#include "cut_kernel.h"

#include <ddfcam/ddf/support_mesh.h>

#include <Eigen/Geometry>

#include <array>
#include <span>
#include <vector>

namespace ddfcam::ddf::detail {

/// @brief The input triangles (items) of the reduction with what the checks need of them.
struct ReductionItems {
  std::vector<Vec3> points;                  ///< input vertices, mm
  std::vector<std::array<int, 3>> vertices;  ///< per item its three input vertices
  std::vector<Vec3> normals;                 ///< per item its unit normal (zero if degenerate)
  std::vector<Eigen::AlignedBox3d> boxes;    ///< per item its bounds
  std::vector<double> diagonals;             ///< per item the length of its bounds' diagonal

  /// @brief The faces of @p mesh as items (item index = face index).
  static ReductionItems fromMesh(const SupportMesh& mesh);
  int size() const { return static_cast<int>(vertices.size()); }
  const Vec3& corner(int item, int k) const { return points[vertices[item][k]]; }
};

/// @brief One support face's item buffer: per raster point the nearest item its V-ray hits
/// within |h| <= 1 (-1 when none), and every item hit by some ray within |h| <= 1.
struct FaceItems {
  std::vector<int> hit;    ///< per raster point (Raster order), nearest item or -1
  std::vector<double> h;   ///< per raster point, the height of that hit
  std::vector<int> items;  ///< sorted, unique items hit by a ray within |h| <= 1
  void clear() { hit.clear(), h.clear(), items.clear(); }
};

/// @brief Bounds of the +-1 crust of @p face (the hull of p_i +- v_i holds it).
Eigen::AlignedBox3d crustBox(const FaceCorners& face);

/// @brief V-shoots the raster of resolution @p m of @p face at the @p candidates whose bounds
/// meet the face's crust box, restricted per row to the ranges where a hit is possible (the
/// depth buffer's interval kernel of sec. 5.2), and fills @p out. Equal heights are resolved
/// towards the item whose normal is closest to the ray direction.
void rasterFace(const FaceCorners& face, int m, const ReductionItems& items,
                std::span<const int> candidates, FaceItems& out);

/// @brief Whether every raster point of @p f hit an item (constraint b).
bool everyRayHits(const FaceItems& f);

/// @brief Whether the angle between the interpolated vector at every hit raster point and the
/// normal of the item it hits is at most acos(@p minCosine).
bool anglesBounded(const FaceCorners& face, int m, const FaceItems& f, const ReductionItems& items,
                   double minCosine);

/// @brief Whether @p q lies strictly between the planes of the h = 1 and h = -1 offset
/// triangles of @p face, on the support's side of both. Each stubble line crosses each plane
/// once (at h = +-1), so such a point has no V-projection with |h| > 1 and mu inside.
bool betweenOffsets(const FaceCorners& face, const Vec3& q);

/// @brief How a vertex of an item lies relative to a set of faces' crusts.
enum class VertexPlace {
  Outside,  ///< V-projects onto none of the faces (with mu inside)
  Inside,   ///< V-projects onto one of them with |h| <= 1
  Beyond    ///< V-projects onto one with mu inside, but only with |h| > 1
};

/// @brief Where point @p q lies relative to the +-1 crusts of @p faces (V-projection, sec. 4.1).
VertexPlace placeVertex(const Vec3& q, std::span<const FaceCorners> faces);

}  // namespace ddfcam::ddf::detail
