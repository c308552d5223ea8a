// SPDX-License-Identifier: MIT
// Conversion of shared third-party parts with a reduced support and a tolerance: both
// distances checked by brute force on a sample (label data; skips without the shared data).
#include <ddfcam/ddf/mesh_conversion.h>
#include <ddfcam/log.h>

#include <gtest/gtest.h>
#include <OpenMesh/Core/IO/MeshIO.hh>

#include <chrono>
#include <filesystem>

#include "../support/ddf_surface_distance.h"
#include "../support/support_triangles.h"

namespace ddfcam::ddf {
namespace {

/// The shared mesh @p name scaled by @p scale to mm, or nullopt when the data is absent.
std::optional<TriangleMesh> sharedMesh(const std::string& name, double scale) {
  const auto path = std::filesystem::path(DDFCAM_SHARED_DATA_DIR) / "meshes" / name;
  if (!std::filesystem::exists(path)) return std::nullopt;
  SupportMesh mesh;
  if (!OpenMesh::IO::read_mesh(mesh, path.string())) return std::nullopt;
  return test::supportTriangles(mesh, scale);
}

/// Converts @p input with a reduced support and @p toleranceMm; the reported both-way distances
/// must bound the brute-force ones, and the tolerance must hold both ways.
void expectReducedWithin(const TriangleMesh& input, double toleranceMm) {
  ConversionParams params;
  params.support = SupportChoice::Reduced;
  params.toleranceMm = toleranceMm;
  // The tries (support faces, m, both distances, the worst input point) go to the test log.
  const LogSink previous =
      setLogSink([](LogLevel, const std::string& message) { std::cout << message << "\n"; });
  const auto start = std::chrono::steady_clock::now();
  const auto result = convertMeshToDdf(input, params);
  setLogSink(previous);
  const double seconds =
      std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
  for (const auto& line : conversionSummaryLines(result.report)) std::cout << line << "\n";
  std::cout << conversionVerdict(result.report) << " (" << seconds << " s)\n";
  EXPECT_LT(result.ddf.faceCount(), static_cast<int>(input.triangles.size()));
  ASSERT_TRUE(result.accuracy.measured);
  EXPECT_TRUE(result.accuracy.toleranceMet) << result.accuracy.note;
  // Brute force over the whole lattice surface for a sample of input points, and over the
  // whole input for a sample of raster points.
  const TriangleMesh surface = test::latticeSurface(result.ddf);
  const auto inputPoints = test::triangleSamples(input, 97);
  const auto rasterPoints = test::rasterSurfacePoints(result.ddf, 211);
  const double in = test::largestDistance(inputPoints, surface);
  const double out = test::largestDistance(rasterPoints, input);
  EXPECT_LE(in, toleranceMm) << inputPoints.size() << " input samples";
  EXPECT_LE(out, toleranceMm) << rasterPoints.size() << " raster samples";
  EXPECT_GE(result.accuracy.inputToDdfMm, in - 1e-9);
  EXPECT_GE(result.accuracy.ddfToInputMm, out - 1e-9);
  testing::Test::RecordProperty("faces", std::to_string(result.ddf.faceCount()));
  testing::Test::RecordProperty("m", std::to_string(result.ddf.resolution()));
  testing::Test::RecordProperty("seconds", std::to_string(seconds));
}

// A thin, twisted free-form part with sharp leading and trailing edges, which a coarse reduced
// support cannot follow at any raster spacing: a shorter support edge bound meets 0.05 mm.
TEST(MeshConversionShared, TurbineBladeReducedWithinTolerance) {
  const auto blade = sharedMesh("turbine-blade-jigsaw.stl", 1000.0);  // metres
  if (!blade) GTEST_SKIP() << "shared mesh data not present";
  expectReducedWithin(*blade, 0.05);
}

TEST(MeshConversionShared, FandiskReducedWithinTolerance) {
  const auto fandisk = sharedMesh("fandisk.obj", 1.0);
  if (!fandisk) GTEST_SKIP() << "shared mesh data not present";
  expectReducedWithin(*fandisk, 0.05);
}

}  // namespace
}  // namespace ddfcam::ddf
