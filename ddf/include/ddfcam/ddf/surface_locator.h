// SPDX-License-Identifier: MIT
// ddfcam: finding where points near a DDF's surface lie on it (contacts of paths planned here
// or read from files).
#pragma once

#include <ddfcam/ddf/displacement_field.h>
#include <ddfcam/ddf/surface_sampling.h>

#include <Eigen/Geometry>

#include <optional>
#include <vector>

namespace ddfcam::ddf {

/// @brief Locates points near the represented surface of a DDF: of the V-projections
/// (locateOnFace) onto the faces whose crust box holds the point, the one nearest to it. The
/// boxes span the support vertices +- their vectors, grown by a tenth of the longest vector,
/// and are built once; a query tests every box (O(faces)), so the locator suits a few thousand
/// contacts, not every raster point. Keeps a reference to @p ddf, which must outlive it.
class SurfaceLocator {
 public:
  explicit SurfaceLocator(const DisplacementField& ddf);

  /// @brief Where @p p (mm, part frame) lies on the surface; nullopt if no face's
  /// V-projection finds it.
  std::optional<SurfaceLocation> locate(const Vec3& p) const;

 private:
  const DisplacementField& ddf_;
  std::vector<Eigen::AlignedBox3d> boxes_;
};

}  // namespace ddfcam::ddf
