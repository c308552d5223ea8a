// SPDX-License-Identifier: MIT
// ddfcam: the point of a triangle nearest to a query point.
#pragma once

#include <ddfcam/ddf/support_mesh.h>

namespace ddfcam::ddf {

/// @brief The point of triangle (a, b, c) nearest to @p p (Ericson, Real-Time Collision Detection
/// 5.1.5: the Voronoi region of @p p decides between a corner, an edge and the interior). A
/// degenerate triangle returns a point of it that bounds the distance from above. All in mm, any
/// common frame.
Vec3 closestPointOnTriangle(const Vec3& p, const Vec3& a, const Vec3& b, const Vec3& c);

}  // namespace ddfcam::ddf
