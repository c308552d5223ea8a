// SPDX-License-Identifier: MIT
// Test support: the z-map DDF of the simulation tests (a planar patch with vertical vectors).
#pragma once

#include <ddfcam/ddf/analytic_generators.h>

namespace ddfcam::test {

/// z-map: planar support z = 0 over [0, sx] x [0, sy] (mm) in cx x cy cells at resolution m,
/// vectors (0, 0, L), surface z = 0, so a height h is z = h L mm.
inline ddf::DisplacementField zmap(double sx, double sy, int cx, int cy, int m, double lengthMm) {
  return ddf::planePatch({.origin = {0.0, 0.0},
                          .size = {sx, sy},
                          .cellsX = cx,
                          .cellsY = cy,
                          .m = m,
                          .planeZMm = 0.0,
                          .vectorLengthMm = lengthMm})
      .ddf;
}

}  // namespace ddfcam::test
