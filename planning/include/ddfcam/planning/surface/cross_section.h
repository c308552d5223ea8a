// SPDX-License-Identifier: MIT
// ddfcam: section curves of surfaces cut by the plane of a user-drawn line.
#pragma once

#include <ddfcam/ddf/triangle_mesh.h>

#include <Eigen/Core>

#include <vector>

namespace ddfcam::planning {

/// @brief A section plane with 2D coordinates (s, t): s along a -> b from a, t along the
/// in-plane normal of the line.
struct SectionPlane {
  Eigen::Vector3d origin = Eigen::Vector3d::Zero();    ///< a, mm
  Eigen::Vector3d sAxis = Eigen::Vector3d::UnitX();    ///< unit, along a -> b
  Eigen::Vector3d tAxis = Eigen::Vector3d::UnitZ();    ///< unit, in the plane, perpendicular to s
  Eigen::Vector3d normal = -Eigen::Vector3d::UnitY();  ///< unit plane normal, sAxis x tAxis
  double lengthMm = 1.0;                               ///< |b - a| measured along sAxis, mm
};

/// @brief The plane through @p a and @p b containing @p viewDirection (the direction the user
/// looks along when drawing the line). tAxis points towards the viewer (against the view
/// direction), so for a top view (viewDirection = -z) t is the height z.
/// @throws InvalidInput if a point is not finite, |b - a| is below 1e-9 mm or the view
/// direction is parallel to b - a (or zero).
SectionPlane sectionPlaneFromView(const Eigen::Vector3d& a, const Eigen::Vector3d& b,
                                  const Eigen::Vector3d& viewDirection);

/// @brief The plane through @p a with normal @p planeNormal; sAxis is b - a projected into the
/// plane, tAxis = normal x sAxis.
/// @throws InvalidInput if the normal is zero or b - a is (nearly) parallel to it.
SectionPlane sectionPlaneFromNormal(const Eigen::Vector3d& a, const Eigen::Vector3d& b,
                                    const Eigen::Vector3d& planeNormal);

/// @brief 3D point (mm) of plane coordinates @p st.
Eigen::Vector3d sectionToWorld(const SectionPlane& plane, const Eigen::Vector2d& st);

/// @brief Options of sectionCurves.
struct SectionParams {
  bool clipToSegment = true;  ///< keep only 0 <= s <= lengthMm; default true
};

/// @brief Intersection of @p mesh with @p plane as polylines in plane coordinates (s, t), mm.
///
/// Each triangle crossing the plane gives a segment; segments sharing a mesh edge are chained,
/// so a connected surface gives one polyline per connected cut (closed loops repeat their first
/// point at the end). Vertices lying exactly on the plane are nudged to its positive side,
/// which keeps every cut point on an edge. Each polyline runs towards increasing s (from its
/// end with smaller s); the list is sorted by the first point's s.
/// @return possibly empty; every polyline has at least 2 points.
/// @throws InvalidInput if a triangle refers to a vertex out of range.
std::vector<std::vector<Eigen::Vector2d>> sectionCurves(const ddf::TriangleMesh& mesh,
                                                        const SectionPlane& plane,
                                                        const SectionParams& params = {});

}  // namespace ddfcam::planning
