// SPDX-License-Identifier: MIT
// Conversion with a resolution from a spacing or a tolerance, labels through welding and
// dropping, a reduced support, and the measured distances against brute-force oracles.
#include <ddfcam/ddf/analytic_generators.h>
#include <ddfcam/ddf/mesh_conversion.h>
#include <ddfcam/ddf/raster_mesh.h>
#include <ddfcam/error.h>

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>

#include "../support/ddf_surface_distance.h"
#include "../support/test_meshes.h"

namespace ddfcam::ddf {
namespace {

/// A fine closed sphere mesh of radius 10 mm (5,120 triangles): the raster mesh of a generated
/// sphere DDF, every vertex on the sphere.
TriangleMesh sphereInput() {
  return extractRasterMesh(spherePart({.radiusMm = 10.0, .subdivisions = 2, .m = 5}).ddf).mesh;
}

/// An open cylinder mesh, r = 10 mm, 30 mm long (48 x 12 quads: 1,152 triangles).
TriangleMesh cylinderInput() {
  return extractSupportMesh(cylinderPart({}).ddf);
}

/// A B-spline bump patch, 40 x 30 mm on a 32 x 24 grid (1,536 triangles).
TriangleMesh bsplineInput() {
  return extractSupportMesh(demoPart({}).ddf);
}

/// Brute-force both-way distances of @p result to @p input on a sample (strides keep it short).
std::pair<double, double> bruteForceDistances(const ConversionResult& result,
                                              const TriangleMesh& input, int inputStride,
                                              int rasterStride) {
  const TriangleMesh surface = test::latticeSurface(result.ddf);
  const double in = test::largestDistance(test::triangleSamples(input, inputStride), surface);
  const double out =
      test::largestDistance(test::rasterSurfacePoints(result.ddf, rasterStride), input);
  return {in, out};
}

TEST(MeshConversionAccuracy, SpacingRuleGivesTheSmallestSufficientResolution) {
  TriangleMesh triangle;  // legs 3 and 4 mm: the longest edge is 5 mm
  triangle.vertices = {{0, 0, 0}, {3, 0, 0}, {0, 4, 0}};
  triangle.triangles = {{0, 1, 2}};
  ConversionParams params;
  params.rasterSpacingMm = 0.5;  // 5 / 0.5 = 10 steps exactly
  auto result = convertMeshToDdf(triangle, params);
  EXPECT_EQ(result.ddf.resolution(), 11);
  EXPECT_DOUBLE_EQ(result.accuracy.rasterSpacingMm, 0.5);
  EXPECT_TRUE(result.accuracy.measured);
  params.rasterSpacingMm = 0.49;  // 10.2 steps: 11
  EXPECT_EQ(convertMeshToDdf(triangle, params).ddf.resolution(), 12);
  params.rasterSpacingMm = 10.0;  // coarser than the edge: the smallest raster
  EXPECT_EQ(convertMeshToDdf(triangle, params).ddf.resolution(), 2);
  params.rasterSpacingMm = 0.001;  // 5,000 steps
  try {
    convertMeshToDdf(triangle, params);
    FAIL() << "expected InvalidInput";
  } catch (const InvalidInput& e) {
    EXPECT_NE(std::string(e.what()).find("raster points"), std::string::npos) << e.what();
    EXPECT_NE(std::string(e.what()).find("m = 5001"), std::string::npos) << e.what();
  }
  params.rasterSpacingMm = -1.0;
  EXPECT_THROW(convertMeshToDdf(triangle, params), InvalidInput);
}

TEST(MeshConversionAccuracy, SpacingRuleHonoursThePointBudget) {
  const TriangleMesh input = cylinderInput();  // longest edge: the quad diagonal
  ConversionParams params;
  params.rasterSpacingMm = 0.05;
  params.maxRasterPoints = 100'000;  // 1,152 faces need ~ 1e6 at this spacing
  EXPECT_THROW(convertMeshToDdf(input, params), InvalidInput);
}

TEST(MeshConversionAccuracy, LabelsSurviveWeldingAndDropping) {
  TriangleMesh input = test::heightFieldMesh(0, 3, 0, 3, 3, 3, [](double, double) { return 0; });
  std::vector<int> labels;
  for (std::size_t t = 0; t < input.triangles.size(); ++t) labels.push_back(100 + int(t) % 3);
  // A duplicate of triangle 4 (label 900), a degenerate one (901), a fin on the interior
  // edge (5, 10) (902), and every triangle unwelded.
  input.triangles.push_back(input.triangles[4]);
  input.triangles.push_back({1, 1, 2});
  input.vertices.push_back({1.5, 1.5, 1.0});
  input.triangles.push_back({5, 10, static_cast<int>(input.vertices.size()) - 1});
  labels.insert(labels.end(), {900, 901, 902});
  TriangleMesh split;
  for (const auto& t : input.triangles) {
    const int base = static_cast<int>(split.vertices.size());
    for (int v : t) split.vertices.push_back(input.vertices[v]);
    split.triangles.push_back({base, base + 1, base + 2});
  }
  ConversionParams params;
  params.inputLabels = labels;
  const auto result = convertMeshToDdf(split, params);
  ASSERT_EQ(result.ddf.faceCount(), 18);
  ASSERT_EQ(result.supportLabels.size(), 18u);
  ASSERT_EQ(result.sourceTriangle.size(), 18u);
  for (int f = 0; f < 18; ++f) {
    EXPECT_EQ(result.supportLabels[f], labels[result.sourceTriangle[f]]);
    EXPECT_LT(result.supportLabels[f], 900) << "a dropped triangle's label on face " << f;
    // The face is the input triangle it names (same corners after welding, any rotation).
    const auto& t = split.triangles[result.sourceTriangle[f]];
    for (int c = 0; c < 3; ++c) {
      double nearest = 1e300;
      for (int v : result.ddf.faceVertices(f))
        nearest = std::min(nearest, (result.ddf.position(v) - split.vertices[t[c]]).norm());
      EXPECT_LT(nearest, 1e-12) << "face " << f << " corner " << c;
    }
  }
  params.inputLabels.pop_back();
  EXPECT_THROW(convertMeshToDdf(split, params), InvalidInput);
}

TEST(MeshConversionAccuracy, InputSupportMeetsAnyToleranceAtTheFirstTry) {
  const TriangleMesh input = bsplineInput();
  ConversionParams params;
  params.resolution = 4;
  params.toleranceMm = 1e-4;
  const auto result = convertMeshToDdf(input, params);
  EXPECT_TRUE(result.accuracy.measured);
  EXPECT_TRUE(result.accuracy.toleranceMet) << result.accuracy.note;
  EXPECT_EQ(result.accuracy.resolutionTries, 1);
  EXPECT_EQ(result.ddf.resolution(), 4);
  const auto [in, out] = bruteForceDistances(result, input, 5, 7);
  EXPECT_LT(in, 1e-4);
  EXPECT_LT(out, 1e-4);
  EXPECT_LE(result.accuracy.inputToDdfMm, 1e-4);
  EXPECT_FALSE(conversionSummaryLines(result.report).empty());
}

TEST(MeshConversionAccuracy, CancelStopsTheMeasurement) {
  ConversionParams params;
  params.toleranceMm = 0.01;
  double last = 0.0;
  params.progress = [&](double x) {
    last = x;
    return x < 0.7;  // the measurement runs after the fill
  };
  EXPECT_THROW(convertMeshToDdf(bsplineInput(), params), Cancelled);
  EXPECT_GE(last, 0.7);
  EXPECT_LT(last, 1.0);
}

// With a reduced support the faces span many input triangles, so the first raster may cut the
// chords; the tolerance tries must bring both distances within 0.02 mm (brute force).
ConversionResult expectReducedWithinTolerance(const TriangleMesh& input, double toleranceMm) {
  ConversionParams params;
  params.support = SupportChoice::Reduced;
  params.resolution = 4;
  params.toleranceMm = toleranceMm;
  const auto result = convertMeshToDdf(input, params);
  EXPECT_LT(result.ddf.faceCount(), static_cast<int>(input.triangles.size()));
  EXPECT_EQ(result.reduction.supportFaces, result.ddf.faceCount());
  EXPECT_TRUE(result.sourceTriangle.empty());
  EXPECT_TRUE(result.accuracy.measured);
  EXPECT_TRUE(result.accuracy.toleranceMet) << result.accuracy.note;
  const auto [in, out] = bruteForceDistances(result, input, 3, 11);
  EXPECT_LE(in, toleranceMm * (1 + 1e-9));
  EXPECT_LE(out, toleranceMm * (1 + 1e-9));
  // The library's distances are maxima over supersets of these samples.
  EXPECT_GE(result.accuracy.inputToDdfMm, in - 1e-9);
  EXPECT_GE(result.accuracy.ddfToInputMm, out - 1e-9);
  testing::Test::RecordProperty("faces", std::to_string(result.ddf.faceCount()));
  testing::Test::RecordProperty("m", std::to_string(result.ddf.resolution()));
  testing::Test::RecordProperty("tries", std::to_string(result.accuracy.resolutionTries));
  return result;
}

TEST(MeshConversionAccuracy, ReducedSphereStaysWithinTolerance) {
  expectReducedWithinTolerance(sphereInput(), 0.02);
}

TEST(MeshConversionAccuracy, ReducedCylinderStaysWithinTolerance) {
  const auto result = expectReducedWithinTolerance(cylinderInput(), 0.02);
  // The first raster (m = 4) cuts the chords of the reduced faces by more than 0.02 mm.
  EXPECT_GT(result.accuracy.resolutionTries, 1);
  EXPECT_GT(result.ddf.resolution(), 4);
}

TEST(MeshConversionAccuracy, ToleranceNotMetIsReportedWithTheLimit) {
  // Shorter support edges end at the input itself (1,152 faces), which meets any tolerance:
  // the point budget (800 faces at m = 4) must rule it out.
  ConversionParams params;
  params.support = SupportChoice::Reduced;
  params.resolution = 4;
  params.toleranceMm = 1e-5;
  params.maxRasterPoints = 8'000;
  const auto result = convertMeshToDdf(cylinderInput(), params);
  EXPECT_TRUE(result.accuracy.measured);
  EXPECT_FALSE(result.accuracy.toleranceMet);
  EXPECT_NE(result.accuracy.note.find("not met"), std::string::npos) << result.accuracy.note;
  EXPECT_NE(result.accuracy.note.find("limit"), std::string::npos) << result.accuracy.note;
  EXPECT_LE(
      result.report.supportFaces * result.ddf.resolution() * (result.ddf.resolution() + 1) / 2,
      8'000);
  bool listed = false;
  for (const auto& line : conversionSummaryLines(result.report))
    listed = listed || line.find("NOT within the tolerance") != std::string::npos;
  EXPECT_TRUE(listed);
}

TEST(MeshConversionAccuracy, StockFitKeepsTheSurfaceWithinTolerance) {
  const TriangleMesh input = bsplineInput();
  ConversionParams params;
  params.toleranceMm = 0.01;
  params.stockMm = 0.2;
  const auto result = convertMeshToDdf(input, params);
  ASSERT_TRUE(result.stock.has_value());
  ASSERT_TRUE(result.report.stock.has_value());
  EXPECT_DOUBLE_EQ(result.stock->requestedMm, 0.2);
  EXPECT_TRUE(result.accuracy.toleranceMet) << result.accuracy.note;
  const auto [in, out] = bruteForceDistances(result, input, 5, 7);
  EXPECT_LE(in, 0.01);
  EXPECT_LE(out, 0.01);
  bool listed = false;
  for (const auto& line : conversionSummaryLines(result.report))
    listed = listed || line.find("stock allowance") != std::string::npos;
  EXPECT_TRUE(listed);
}

TEST(MeshConversionAccuracy, ReducedBsplinePatchStaysWithinTolerance) {
  expectReducedWithinTolerance(bsplineInput(), 0.02);
}

TEST(MeshConversionAccuracy, ReducedSupportKeepsLabelBorders) {
  TriangleMesh input =
      test::heightFieldMesh(0, 20, 0, 10, 20, 10, [](double x, double) { return 0.02 * x * x; });
  std::vector<int> labels;
  for (const auto& t : input.triangles) {
    const double x =
        (input.vertices[t[0]].x() + input.vertices[t[1]].x() + input.vertices[t[2]].x()) / 3.0;
    labels.push_back(x < 10.0 ? 1 : 2);
  }
  ConversionParams params;
  params.support = SupportChoice::Reduced;
  params.inputLabels = labels;
  const auto result = convertMeshToDdf(input, params);
  ASSERT_EQ(result.supportLabels.size(), static_cast<std::size_t>(result.ddf.faceCount()));
  EXPECT_LT(result.ddf.faceCount(), static_cast<int>(input.triangles.size()));
  for (int f = 0; f < result.ddf.faceCount(); ++f) {
    Vec3 centroid = Vec3::Zero();
    for (int v : result.ddf.faceVertices(f)) centroid += result.ddf.position(v) / 3.0;
    EXPECT_EQ(result.supportLabels[f], centroid.x() < 10.0 ? 1 : 2) << "face " << f;
  }
}

}  // namespace
}  // namespace ddfcam::ddf
