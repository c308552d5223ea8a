// SPDX-License-Identifier: MIT
// ddfcam tests: best fit of the shared formed part onto its target (springback-deepdrawn pair).
#include <ddfcam/io/mesh/mesh_io.h>
#include <ddfcam/planning/mould/surface_alignment.h>

#include <gtest/gtest.h>

#include <chrono>
#include <filesystem>
#include <iostream>

namespace ddfcam::test {
namespace {

const std::filesystem::path kPairDir =
    std::filesystem::path(DDFCAM_SHARED_DATA_DIR) / "meshes" / "springback-deepdrawn";

TEST(SurfaceAlignmentShared, BestFitOfFormedPartLowersRms) {
  if (!std::filesystem::exists(kPairDir / "target_AF_bs.stl")) GTEST_SKIP() << "no shared pair";
  const auto target = io::readMesh(kPairDir / "target_AF_bs.stl");
  const auto formed = io::readMesh(kPairDir / "mesh_ausgerichtet1.stl");
  const auto start = std::chrono::steady_clock::now();
  planning::BestFitParams params;
  params.maxSamples = 3000;
  const auto fit = planning::alignBestFit(formed, target, params);
  const double seconds =
      std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
  std::cout << "[shared pair best fit] trimmed RMS before " << fit.rmsBeforeMm << " mm, after "
            << fit.rmsMm << " mm; rotation " << planning::rotationAngleDeg(fit.transform)
            << " deg, translation (" << fit.transform.translation().transpose() << ") mm, "
            << fit.iterations << " iterations, converged " << fit.converged << ", " << seconds
            << " s\n";
  EXPECT_LT(fit.rmsMm, fit.rmsBeforeMm);
  // The file is already aligned by its author: best fit moves it only slightly.
  EXPECT_LT(planning::rotationAngleDeg(fit.transform), 5.0);
  EXPECT_LT(fit.transform.translation().norm(), 20.0);
}

}  // namespace
}  // namespace ddfcam::test
