// SPDX-License-Identifier: MIT
// Random points and barycentric coordinates for the randomized unit tests.
#pragma once

#include <ddfcam/ddf/support_mesh.h>

#include <random>

namespace ddfcam::test {

/// Point with coordinates uniform in [-scale, scale].
inline ddf::Vec3 randomVec(std::mt19937& rng, double scale = 1.0) {
  std::uniform_real_distribution<double> u(-scale, scale);
  return {u(rng), u(rng), u(rng)};
}

/// Barycentric coordinates inside the triangle (positive, summing to 1).
inline ddf::Vec3 randomBary(std::mt19937& rng) {
  std::uniform_real_distribution<double> u(0.0, 1.0);
  ddf::Vec3 mu(u(rng), u(rng), u(rng));
  return mu / mu.sum();
}

}  // namespace ddfcam::test
