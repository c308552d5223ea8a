// SPDX-License-Identifier: MIT
// ddfcam: the DDF surface as a chart of barycentric coordinates, with closest-point search.
#pragma once

#include <ddfcam/ddf/displacement_field.h>
#include <ddfcam/ddf/surface_sampling.h>

namespace ddfcam::planning::detail {

/// The DDF surface as a piecewise quadratic map of barycentric coordinates: the height is
/// linear over each raster triangle (as in interpolateOnFace), g and v are linear over the face.
class SurfaceChart {
 public:
  explicit SurfaceChart(const ddf::DisplacementField& ddf) : ddf_(ddf) {}

  /// Height and surface tangents at a point of a face.
  struct Local {
    double h = 0.0;
    ddf::Vec3 ja = ddf::Vec3::Zero();  ///< dS / d(a = e1 - e2), mm
    ddf::Vec3 jc = ddf::Vec3::Zero();  ///< dS / d(c = e3 - e2), mm
  };

  Local local(int face, const ddf::Vec3& mu) const;

  /// The surface location at (face, bary) (bary used as given).
  ddf::SurfaceLocation locate(int face, const ddf::Vec3& bary) const;

  /// The unit normal of the surface at @p at.
  ddf::Vec3 normal(const ddf::SurfaceLocation& at) const;

  /// The surface point nearest to @p target found from @p start; @p normal gets its unit normal.
  ddf::SurfaceLocation closestNear(const ddf::SurfaceLocation& start, const ddf::Vec3& target,
                                   ddf::Vec3* normal = nullptr) const;

 private:
  // The step from @p at by @p delta cut where it leaves the face and carried over to the
  // neighbour across that edge; on an open edge the whole step is clamped into the face.
  ddf::SurfaceLocation stepAcross(const ddf::SurfaceLocation& at, const ddf::Vec3& delta) const;

  const ddf::DisplacementField& ddf_;
};

}  // namespace ddfcam::planning::detail
