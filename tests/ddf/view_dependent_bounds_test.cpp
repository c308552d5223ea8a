// SPDX-License-Identifier: MIT
// Tests of the view-dependent error bounds against a pinhole camera: a face's bound projects to
// at most the pixel error at the face's nearest corner (and more than half of it unless
// clamped); faces out of view take the coarsest bound; a parallel view is uniform.
#include <ddfcam/ddf/analytic_generators.h>
#include <ddfcam/ddf/view_dependent_bounds.h>
#include <ddfcam/error.h>

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <numbers>

namespace ddfcam::ddf {
namespace {

DisplacementField plate() {
  return planePatch({.origin = {0.0, 0.0}, .size = {40.0, 30.0}, .cellsX = 20, .cellsY = 15,
                     .m = 5, .planeZMm = 0.0})
      .ddf;
}

TEST(ViewDependentBounds, ABoundProjectsToAtMostThePixelErrorAtItsNearestCorner) {
  const DisplacementField ddf = plate();
  ViewBoundsParams view;
  // Looking down at the plate from beyond its near edge, wide angle: the whole plate in view at
  // depths from about 20 to 44 mm.
  view.eyeMm = Vec3(20.0, -10.0, 20.0);
  view.direction = Vec3(0.0, 25.0, -20.0).normalized();
  view.viewAngleDeg = 90.0;
  view.viewportHeightPx = 600;
  view.aspect = 1.5;
  view.pixelError = 1.0;
  view.minEpsMm = 0.005;
  view.maxEpsMm = 5.0;
  const std::vector<float> bounds = viewDependentBounds(ddf, view);
  ASSERT_EQ(bounds.size(), static_cast<std::size_t>(ddf.faceCount()));
  // Pinhole: a length L across the view at depth z covers L f / z pixels, f = (H/2)/tan(a/2).
  const double focal = 0.5 * view.viewportHeightPx / std::tan(45.0 * std::numbers::pi / 180.0);
  const int n = ddf.raster().steps();
  float lo = 1e9f, hi = 0.0f;
  for (int f = 0; f < ddf.faceCount(); ++f) {
    double nearest = 1e300;
    for (const auto& [i, k] : {std::pair{0, 0}, {n, 0}, {0, n}})
      nearest = std::min(nearest, (ddf.surfacePoint(f, i, k) - view.eyeMm).dot(view.direction));
    const double pixels = bounds[f] * focal / nearest;
    EXPECT_LE(pixels, view.pixelError * (1.0 + 1e-6)) << "face " << f;
    if (bounds[f] > view.minEpsMm) EXPECT_GT(2.0 * pixels, 0.5 * view.pixelError) << f;
    // Powers of two of the finest bound.
    const double level = std::log2(bounds[f] / view.minEpsMm);
    EXPECT_NEAR(level, std::round(level), 1e-5) << "face " << f;
    lo = std::min(lo, bounds[f]);
    hi = std::max(hi, bounds[f]);
  }
  EXPECT_GE(hi, 2.0f * lo);  // near faces fine, far faces coarse
}

TEST(ViewDependentBounds, FacesOutOfViewAreCoarsestAndAParallelViewIsUniform) {
  const DisplacementField ddf = plate();
  ViewBoundsParams view;
  view.eyeMm = Vec3(20.0, 15.0, 100.0);
  view.direction = Vec3(1.0, 0.0, 0.0);  // looking away along +x, the plate below the frustum
  view.viewAngleDeg = 20.0;
  for (float b : viewDependentBounds(ddf, view)) EXPECT_EQ(b, static_cast<float>(view.maxEpsMm));
  view.parallel = true;
  view.parallelScaleMm = 20.0;
  view.viewportHeightPx = 500;
  view.pixelError = 1.0;
  // 40 mm over 500 px: 0.08 mm per pixel -> 0.01 * 2^3.
  for (float b : viewDependentBounds(ddf, view)) EXPECT_FLOAT_EQ(b, 0.08f);
}

TEST(ViewDependentBounds, RejectsABadView) {
  const DisplacementField ddf = plate();
  ViewBoundsParams view;
  view.viewportHeightPx = 0;
  EXPECT_THROW(viewDependentBounds(ddf, view), InvalidInput);
  view = {};
  view.direction = Vec3::Zero();
  EXPECT_THROW(viewDependentBounds(ddf, view), InvalidInput);
  view = {};
  view.maxEpsMm = 0.001;
  EXPECT_THROW(viewDependentBounds(ddf, view), InvalidInput);
}

}  // namespace
}  // namespace ddfcam::ddf
