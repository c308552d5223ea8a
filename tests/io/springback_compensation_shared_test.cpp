// SPDX-License-Identifier: MIT
// ddfcam tests: the compensation loop on the shared deep-drawn springback pair with the linear
// model calibrated to the measured first forming.
#include <ddfcam/ddf/mesh_conversion.h>
#include <ddfcam/io/mesh/mesh_io.h>
#include <ddfcam/planning/mould/springback_compensation.h>

#include <gtest/gtest.h>

#include <chrono>
#include <cmath>
#include <filesystem>
#include <iostream>

namespace ddfcam::planning {
namespace {

const std::filesystem::path kPair =
    std::filesystem::path(DDFCAM_SHARED_DATA_DIR) / "meshes" / "springback-deepdrawn";

// Raster resolution 4, unit pseudo-normal directions and heights 0 (the target is the support).
ddf::ConversionParams conversionParams() {
  ddf::ConversionParams params;
  params.resolution = 4;
  params.chooseLengths = false;
  return params;
}

// Target DDF on the target mesh at raster resolution 4 with heights 0 (the target is the
// support) and vectors of 10 mm, longer than the largest measured deviation (7.8 mm).
ddf::DisplacementField targetDdf(const ddf::TriangleMesh& mesh) {
  ddf::DisplacementField ddf = ddf::convertMeshToDdf(mesh, conversionParams()).ddf;
  std::vector<ddf::Vec3> vectors = ddf.vectors();
  for (ddf::Vec3& v : vectors) v = 10.0 * v.normalized();
  ddf.setVectors(std::move(vectors));
  return ddf;
}

TEST(SpringbackCompensationShared, ModelIterationsFollowTheAlphaLaw) {
  const auto targetPath = kPair / "target_AF_bs.stl", formedPath = kPair / "mesh_ausgerichtet1.stl";
  if (!std::filesystem::exists(targetPath) || !std::filesystem::exists(formedPath))
    GTEST_SKIP() << "shared pair not found at " << kPair;
  const auto start = std::chrono::steady_clock::now();
  CompensationHistory history = startCompensation(targetDdf(io::readMesh(targetPath)));
  std::vector<float> measured = formedHeightsFromMesh(history.target, io::readMesh(formedPath));
  const auto afterCompare = std::chrono::steady_clock::now();
  // alpha = 0.3: a typical springback share of deep-drawn steel sheet, the oracle's example.
  const double alpha = 0.3;
  const LinearSpringbackModel model = calibrateSpringback(history.target, measured, alpha);
  recordFormedResponse(history, std::move(measured), "mesh_ausgerichtet1.stl");
  for (int j = 1; j <= 3; ++j) {
    compensationStep(history, 1.0);
    recordFormedResponse(
        history, linearSpringback(model, history.target, history.iterations[j].mouldHeights),
        "linear model alpha=0.3");
  }
  const auto end = std::chrono::steady_clock::now();
  const CompensationIteration& first = history.iterations[0];
  EXPECT_GT(first.maxDeviationMm, 5.0);  // the lead's point distances reach 7.77 mm
  EXPECT_LT(first.maxDeviationMm, 10.0);
  for (int j = 0; j <= 3; ++j) {
    const CompensationIteration& it = history.iterations[j];
    std::cout << "[ shared pair ] iteration " << j << ": max " << it.maxDeviationMm << " mm, RMS "
              << it.rmsDeviationMm << " mm, mould points outside the crust "
              << it.pointsOutsideCrust << "\n";
    const double law = std::pow(alpha, j);
    EXPECT_NEAR(it.maxDeviationMm, law * first.maxDeviationMm, 1e-4 * first.maxDeviationMm) << j;
    EXPECT_NEAR(it.rmsDeviationMm, law * first.rmsDeviationMm, 1e-4 * first.rmsDeviationMm) << j;
  }
  std::cout << "[ shared pair ] compare "
            << std::chrono::duration<double>(afterCompare - start).count()
            << " s (with reading), 3 model iterations "
            << std::chrono::duration<double>(end - afterCompare).count() << " s\n";
}

}  // namespace
}  // namespace ddfcam::planning
