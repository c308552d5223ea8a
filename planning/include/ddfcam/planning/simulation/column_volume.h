// SPDX-License-Identifier: MIT
// ddfcam: the material volume of one raster column of a DDF face between two heights.
#pragma once

#include <ddfcam/ddf/displacement_field.h>

namespace ddfcam::planning {

/// @brief Volume terms of support face @p face of a DDF: the volume between two heights of a
/// raster point is its nodal weight (a third of the parameter area of its incident raster
/// sub-triangles, 1 / (6 n^2) each) times the integral over the height range of the Jacobian
/// det(e1 + h f1, e2 + h f2, v) of the map (bary, h) -> g + h v, so the volume between two
/// height fields is a sum over the raster points that differ (volumeBetween, and a
/// simulation's volume per pose from only the points a pose changed).
class FaceColumnVolume {
 public:
  FaceColumnVolume(const ddf::DisplacementField& field, int face);
  /// @brief Volume between heights @p h0 and @p h1 (units of h) at raster point (i, k), mm^3;
  /// positive when h0 > h1 on a positively oriented face.
  double column(int i, int k, double h0, double h1) const;

 private:
  const ddf::DisplacementField* field_;
  int face_;
  ddf::Vec3 e1_, e2_, f1_, f2_;
  int n_ = 1;
  double nodal_ = 1.0;
};

}  // namespace ddfcam::planning
