// SPDX-License-Identifier: MIT
// ddfcam: 3D convex hull of a point set as a closed, outward-oriented triangle mesh (quickhull).
#pragma once

#include <ddfcam/ddf/triangle_mesh.h>

#include <Eigen/Core>

#include <span>

namespace ddfcam::ddf {

/// @brief Parameters of convexHull().
struct ConvexHullParams {
  /// Points closer than this fraction of the bounding-box diagonal to a hull plane count as on
  /// the plane (they are dropped), which keeps nearly coplanar input (cylinder caps, a tool
  /// translated in the plane of a face) from producing slivers or inconsistent topology.
  /// Default 1e-9.
  double relativeTolerance = 1e-9;
};

/// @brief Convex hull of @p points (#P x 3, mm, any frame) by quickhull with conflict lists:
/// each face keeps the points above it, the farthest is added, the faces it sees are replaced
/// by a fan from the horizon. Expected O(P log P).
/// @returns a closed 2-manifold triangle mesh, counter-clockwise seen from outside (positive
/// signedVolume()), whose vertices are a subset of @p points; coplanar hull facets come out as
/// several triangles.
/// @throws InvalidInput when the points span no volume (fewer than 4 points, or all within the
/// tolerance of one plane); the message gives the point count and the extent.
TriangleMesh convexHull(std::span<const Eigen::Vector3d> points,
                        const ConvexHullParams& params = {});

}  // namespace ddfcam::ddf
