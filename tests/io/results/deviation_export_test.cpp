// SPDX-License-Identifier: MIT
// Tests of the deviation exports: CSV parsed back, VTP read back through the VTK XML reader.
#include <ddfcam/ddf/analytic_generators.h>
#include <ddfcam/ddf/raster_mesh.h>
#include <ddfcam/error.h>
#include <ddfcam/io/mesh/vtk_xml_mesh.h>
#include <ddfcam/io/results/deviation_export.h>

#include <gtest/gtest.h>

#include <cmath>
#include <filesystem>
#include <sstream>
#include <string>

#include "../io_test_support.h"

namespace ddfcam::io {
namespace {

/// Deviation of the analytic "formed" surface z = 0.1 x - 0.05 y over the plane z = 0, mm.
double analyticDeviation(const ddf::Vec3& p) {
  return 0.1 * p.x() - 0.05 * p.y();
}

/// A one-stage comparison of that surface with a 3 x 2-cell plane mould (12 faces, m = 4),
/// built by hand: per copy the deviation vector (0, 0, d) and the deviation d; copy 5 missing.
planning::SurfaceComparison planeComparison() {
  planning::SurfaceComparison c;
  ddf::DisplacementField mould =
      ddf::planePatch({.size = {6.0, 4.0}, .cellsX = 3, .cellsY = 2, .m = 4, .planeZMm = 0.0}).ddf;
  const std::size_t perFace = mould.pointsPerFace();
  const std::size_t n = mould.allHeights().size();
  c.deviation = {"deviation", "mm", true, std::vector<float>(n)};
  c.deviationVectors.resize(n);
  for (int f = 0; f < mould.faceCount(); ++f)
    for (int i = 0; i < mould.resolution(); ++i)
      for (int k = 0; i + k < mould.resolution(); ++k) {
        const std::size_t copy = f * perFace + mould.raster().index(i, k);
        const float d = static_cast<float>(analyticDeviation(mould.surfacePoint(f, i, k)));
        c.deviation.values[copy] = d;
        c.deviationVectors[copy] = ddf::Vec3(0.0, 0.0, d);
      }
  c.sequence.deformedPoints.assign(n, ddf::Vec3::Zero());
  c.sequence.stages = {ddf::DeformationStage{mould, 1.0, {}}};
  c.band = {-0.1, 0.2};
  return c;
}

std::vector<double> parseRow(const std::string& line) {
  std::vector<double> values;
  std::stringstream in(line);
  std::string cell;
  while (std::getline(in, cell, ',')) values.push_back(cell == "nan" ? NAN : std::stod(cell));
  return values;
}

TEST(DeviationExport, ToleranceClassFollowsTheBand) {
  const planning::ToleranceBand band{-0.1, 0.2};
  EXPECT_EQ(toleranceClassOf(-0.2, band), -1.0f);
  EXPECT_EQ(toleranceClassOf(-0.1, band), 0.0f);
  EXPECT_EQ(toleranceClassOf(0.2, band), 0.0f);
  EXPECT_EQ(toleranceClassOf(0.25, band), 1.0f);
  EXPECT_TRUE(std::isnan(toleranceClassOf(NAN, band)));
}

TEST(DeviationExport, CsvHasOneRowPerRasterPointWithTheAnalyticDeviation) {
  const planning::SurfaceComparison c = planeComparison();
  const auto path = std::filesystem::temp_directory_path() / "ddfcam_prj_deviation.csv";
  writeDeviationCsv(c, path);
  std::stringstream text(test::readBytes(path));
  std::filesystem::remove(path);
  std::string line;
  std::getline(text, line);
  EXPECT_EQ(line, "x_mm,y_mm,z_mm,dx_mm,dy_mm,dz_mm,deviation_mm");
  std::size_t rows = 0;
  while (std::getline(text, line)) {
    const std::vector<double> row = parseRow(line);
    ASSERT_EQ(row.size(), 7u) << line;
    const double d = analyticDeviation({row[0], row[1], row[2]});
    EXPECT_EQ(row[2], 0.0);
    EXPECT_EQ(row[3], 0.0);
    EXPECT_EQ(row[4], 0.0);
    EXPECT_NEAR(row[5], d, 1e-6);
    EXPECT_NEAR(row[6], d, 1e-6);
    ++rows;
  }
  // Distinct raster points of a 4 x 3-vertex grid (23 edges, 12 faces) at m = 4: 12 vertices,
  // 2 per edge, 1 per face.
  EXPECT_EQ(rows, 12u + 2u * 23u + 12u);
  EXPECT_EQ(rows, c.sequence.stages[0].ddf.topology().pointCount());
}

TEST(DeviationExport, VtpReadsBackWithDeviationClassAndVectors) {
  const planning::SurfaceComparison c = planeComparison();
  const auto path = std::filesystem::temp_directory_path() / "ddfcam_prj_deviation.vtp";
  writeDeviationVtp(c, path);
  const VtkXmlMesh back = readVtkXmlMesh(path);
  std::filesystem::remove(path);
  const std::size_t points = c.sequence.stages[0].ddf.topology().pointCount();
  ASSERT_EQ(back.mesh.vertices.size(), points);
  EXPECT_EQ(back.mesh.triangles.size(), 12u * 9u);
  const planning::MeshField* deviation = nullptr;
  const planning::MeshField* cls = nullptr;
  const planning::MeshField* vector = nullptr;
  for (const planning::MeshField& field : back.fields) {
    if (field.name == "deviation") deviation = &field;
    if (field.name == "tolerance_class") cls = &field;
    if (field.name.find("deviation_vector") != std::string::npos) vector = &field;
  }
  ASSERT_TRUE(deviation && cls && vector);
  int classes[3] = {0, 0, 0};
  for (std::size_t v = 0; v < points; ++v) {
    const ddf::Vec3& p = back.mesh.vertices[v];
    EXPECT_EQ(p.z(), 0.0);  // on the mould, not on the formed surface
    const double d = analyticDeviation(p);
    EXPECT_NEAR(deviation->values[v], d, 1e-6);
    EXPECT_NEAR(vector->values[v], std::abs(d), 1e-6);
    // The class of the stored (float) deviation: -1 below -0.1, +1 above 0.2, else 0.
    const float stored = static_cast<float>(d);
    EXPECT_EQ(cls->values[v], stored < -0.1 ? -1.0f : (stored > 0.2 ? 1.0f : 0.0f));
    ++classes[static_cast<int>(cls->values[v]) + 1];
  }
  // The plane spans d in [-0.2, 0.6]: all three classes occur.
  EXPECT_GT(classes[0], 0);
  EXPECT_GT(classes[1], 0);
  EXPECT_GT(classes[2], 0);
}

TEST(DeviationExport, WrongSizesAreRejected) {
  planning::SurfaceComparison c = planeComparison();
  c.deviationVectors.pop_back();
  EXPECT_THROW(formatDeviationCsv(c), InvalidInput);
  EXPECT_THROW(formatDeviationVtp(c), InvalidInput);
}

}  // namespace
}  // namespace ddfcam::io
