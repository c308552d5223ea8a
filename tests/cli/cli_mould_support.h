// SPDX-License-Identifier: MIT
// Shared set-up of the ddfcam-cli compare and compensate tests: analytic height-field meshes.
#pragma once

#include <ddfcam/ddf/triangle_mesh.h>
#include <ddfcam/io/mesh/mesh_io.h>

#include "../support/test_meshes.h"

#include <cmath>
#include <filesystem>
#include <functional>
#include <numbers>

namespace ddfcam::test {

/// The surface z = @p height(x, y) over [0, width] x [0, depth] mm, nx x ny cells.
inline ddf::TriangleMesh heightFieldMesh(double width, double depth, int nx, int ny,
                                         const std::function<double(double, double)>& height) {
  return heightFieldMesh(0.0, width, 0.0, depth, nx, ny, height);
}

/// Sheet of 40 x 10 mm: two periods of a sinusoid of wavelength 20 mm along x.
constexpr double kSheetWidth = 40.0, kSheetDepth = 10.0, kWavelength = 20.0;

/// A fine sinusoid z = amplitude sin(2 pi x / 20) (400 x 4 cells, 0.1 mm along x).
inline ddf::TriangleMesh sinusoidSheet(double amplitude) {
  return heightFieldMesh(kSheetWidth, kSheetDepth, 400, 4, [amplitude](double x, double) {
    return amplitude * std::sin(2.0 * std::numbers::pi * x / kWavelength);
  });
}

/// The flat mould z = 0 (20 x 5 cells of 2 mm).
inline ddf::TriangleMesh flatSheet() {
  return heightFieldMesh(kSheetWidth, kSheetDepth, 20, 5, [](double, double) { return 0.0; });
}

}  // namespace ddfcam::test
