// SPDX-License-Identifier: MIT
// ddfcam-cli convert and info with --units and the conversion options: a part in metres read
// with --units m gives the DDF of the same part in mm, the size warning names --units, and
// info reports the raster spacing, the crust reach, the source unit and the CAD faces; a reduced
// .ddf keeps its input mesh, from which curvature takes the part's curvature.
#include <ddfcam/io/mesh/ddf_file.h>
#include <ddfcam/io/mesh/mesh_io.h>

#include <gmock/gmock.h>
#include <gtest/gtest.h>
#include <nlohmann/json.hpp>

#include "../support/test_meshes.h"
#include "cli_convert_support.h"

#include <algorithm>
#include <cmath>
#include <sstream>
#include <string>
#include <vector>

namespace ddfcam::io {
namespace {

using test::runCli;
using ::testing::HasSubstr;
using ::testing::Not;

/// A shallow bowl 0.24 x 0.18 (file units; 0.3 across) as 8 x 6 cells.
ddf::TriangleMesh bowlInMetres() {
  return test::heightFieldMesh(0.0, 0.24, 0.0, 0.18, 8, 6, [](double x, double y) {
    return 0.2 * ((x - 0.12) * (x - 0.12) + (y - 0.09) * (y - 0.09));
  });
}

ddf::TriangleMesh timesThousand(ddf::TriangleMesh mesh) {
  for (Eigen::Vector3d& v : mesh.vertices) v *= 1000.0;
  return mesh;
}

TEST(CliUnits, MetreFileWithUnitsMGivesTheDdfOfTheMillimetreFile) {
  test::ScratchDir dir;
  // OBJ keeps every double exactly, so the oracle is the scaled mesh converted in mm.
  writeMesh(bowlInMetres(), dir / "bowl_m.obj");
  writeMesh(timesThousand(bowlInMetres()), dir / "bowl_mm.obj");
  const auto inMetres = runCli(dir, {"convert", (dir / "bowl_m.obj").string(), "-o",
                                     (dir / "m.ddf").string(), "--units", "m"});
  ASSERT_EQ(inMetres.exitCode, 0) << inMetres.err;
  EXPECT_THAT(inMetres.out, HasSubstr("unit: m, 0.300034 units across"));
  EXPECT_THAT(inMetres.out, HasSubstr("to [240, 180, 4.5] mm"));
  const auto inMm =
      runCli(dir, {"convert", (dir / "bowl_mm.obj").string(), "-o", (dir / "mm.ddf").string()});
  ASSERT_EQ(inMm.exitCode, 0) << inMm.err;
  DdfMetadata metres, mm;
  const ddf::DisplacementField a = readDdf(dir / "m.ddf", &metres);
  test::expectBitwiseEqual(a, readDdf(dir / "mm.ddf", &mm));
  EXPECT_EQ(metres.sourceUnit, ddfcam::LengthUnit::Metre);
  EXPECT_EQ(mm.sourceUnit, ddfcam::LengthUnit::Millimetre);
  EXPECT_TRUE(metres.stored && mm.stored);
  EXPECT_GT(a.faceCount(), 0);
}

TEST(CliUnits, PlanAndCurvatureOnAMetreFileWithUnitsMMatchTheMillimetreFile) {
  test::ScratchDir dir;
  writeMesh(bowlInMetres(), dir / "bowl_m.obj");
  writeMesh(timesThousand(bowlInMetres()), dir / "bowl_mm.obj");
  for (const char* stem : {"bowl_m", "bowl_mm"}) {
    const std::string in = (dir / (std::string(stem) + ".obj")).string();
    const std::string units = stem == std::string("bowl_m") ? "m" : "mm";
    const auto plan = runCli(dir, {"plan", in, "-o", (dir / (std::string(stem) + ".csv")).string(),
                                   "--units", units, "--spacing", "20"});
    ASSERT_EQ(plan.exitCode, 0) << plan.err;
    const auto curvature =
        runCli(dir, {"curvature", in, "-o", (dir / (std::string(stem) + ".vtp")).string(), "--csv",
                     (dir / (std::string(stem) + "_k.csv")).string(), "--units", units});
    ASSERT_EQ(curvature.exitCode, 0) << curvature.err;
  }
  EXPECT_EQ(test::readBytes(dir / "bowl_m.csv"), test::readBytes(dir / "bowl_mm.csv"));
  EXPECT_EQ(test::readBytes(dir / "bowl_m_k.csv"), test::readBytes(dir / "bowl_mm_k.csv"));
  EXPECT_FALSE(test::readBytes(dir / "bowl_m.csv").empty());
}

TEST(CliUnits, SizeWarningAppearsOnlyWithoutUnits) {
  test::ScratchDir dir;
  writeMesh(bowlInMetres(), dir / "blade.stl");
  const std::string input = (dir / "blade.stl").string();
  const auto without = runCli(dir, {"convert", input, "-o", (dir / "a.ddf").string()});
  ASSERT_EQ(without.exitCode, 0) << without.err;
  EXPECT_THAT(without.err, HasSubstr("warning: " + input +
                                     " is 0.3 units across; if it is not in mm, pass --units "
                                     "(as m it would be 300 mm)"));
  for (const char* unit : {"mm", "m"}) {
    const auto with =
        runCli(dir, {"convert", input, "-o", (dir / "b.ddf").string(), "--units", unit});
    ASSERT_EQ(with.exitCode, 0) << with.err;
    EXPECT_THAT(with.err, Not(HasSubstr("units across"))) << unit;
  }
}

TEST(CliUnits, BadUnitsAndConflictingOptionsAreUsageErrors) {
  test::ScratchDir dir;
  const std::string off = DDFCAM_TEST_DATA_DIR "/bowl_patch.off";
  const auto unit = runCli(dir, {"convert", off, "-o", "x.ddf", "--units", "ft"});
  EXPECT_EQ(unit.exitCode, 2);
  EXPECT_THAT(unit.err, HasSubstr("--units expects mm, cm, m or in, got 'ft'"));
  const std::vector<std::vector<std::string>> commands = {
      {"info", off},         {"plan", off, "-o", "x.csv"},
      {"curvature", off},    {"simulate", off, "--paths", "p.csv", "-o", "y.ddf"},
      {"compare", off, off}, {"compensate", off, "--formed", off}};
  for (std::vector<std::string> words : commands) {
    words.insert(words.end(), {"--units", "yards"});
    const auto other = runCli(dir, words);
    EXPECT_EQ(other.exitCode, 2) << words[0] << other.err;
    EXPECT_THAT(other.err, HasSubstr("--units expects mm, cm, m or in, got 'yards'")) << words[0];
  }
  const auto both = runCli(
      dir, {"convert", off, "-o", "x.ddf", "--tolerance", "0.01", "--raster-spacing", "0.5"});
  EXPECT_EQ(both.exitCode, 2);
  EXPECT_THAT(both.err, HasSubstr("--tolerance and --raster-spacing exclude each other"));
  const auto support = runCli(dir, {"convert", off, "-o", "x.ddf", "--support", "coarse"});
  EXPECT_EQ(support.exitCode, 2);
  EXPECT_THAT(support.err, HasSubstr("--support expects reduced or input"));
  EXPECT_FALSE(std::filesystem::exists(dir / "x.ddf"));
}

TEST(CliUnits, InfoReportsSpacingReachUnitAndCadFaces) {
  test::ScratchDir dir;
  // Flat grid of 2 x 2 cells of 4 mm, vectors (0, 0, 0.5), heights 0.2: the crust reaches
  // (1 - 0.2) 0.5 = 0.4 mm above and (1 + 0.2) 0.5 = 0.6 mm below; the longest support edge
  // is a cell diagonal, 4 sqrt(2) mm, so at m = 5 the spacing is sqrt(2) mm.
  const auto grid = test::gridMesh(2, 2, 4.0, 4.0);
  ddf::DisplacementField field(grid, test::constantVectors(grid, {0, 0, 0.5}), 5, 0.2f);
  DdfMetadata metadata;
  metadata.sourceUnit = ddfcam::LengthUnit::Inch;
  metadata.cadFaceNames = {"face 0 (plane)", "face 1 (B-spline)"};
  metadata.cadFaceOfSupportFace = {0, 0, 0, 1, 1, 1, 1, 1};
  writeDdf(field, dir / "grid.ddf", metadata);
  const auto text = runCli(dir, {"info", (dir / "grid.ddf").string()});
  ASSERT_EQ(text.exitCode, 0) << text.err;
  EXPECT_THAT(text.out, HasSubstr(".ddf format version 2"));
  EXPECT_THAT(text.out, HasSubstr("raster spacing: 1.414 mm (longest support edge 5.657 mm"));
  EXPECT_THAT(text.out, HasSubstr("crust reach above the surface: min 0.4 mm, median 0.4 mm"));
  EXPECT_THAT(text.out, HasSubstr("crust reach below the surface: min 0.6 mm, median 0.6 mm"));
  EXPECT_THAT(text.out, HasSubstr("source unit: in"));
  EXPECT_THAT(text.out, HasSubstr("CAD faces: 2"));
  EXPECT_THAT(text.out, HasSubstr("face 1 (B-spline): 5 support faces"));
  const auto json = runCli(dir, {"info", (dir / "grid.ddf").string(), "--json"});
  ASSERT_EQ(json.exitCode, 0) << json.err;
  EXPECT_THAT(json.out, HasSubstr("\"sourceUnit\": \"in\""));
  EXPECT_EQ(nlohmann::json::parse(json.out)["cadFaceNames"],
            (std::vector<std::string>{"face 0 (plane)", "face 1 (B-spline)"}));
  EXPECT_EQ(test::jsonInteger(json.out, "formatVersion"), 2);
  EXPECT_EQ(test::jsonInteger(json.out, "cadFaces"), 2);
}

TEST(CliUnits, InfoJsonGivesTheGridNumbersBoundsAndCheckOfAKnownField) {
  test::ScratchDir dir;
  // The grid above, with one cell of it as design mesh: 9 vertices, 8 faces; at m = 5, 15
  // points per face, 120 stored, (2 (m - 1) + 1)^2 = 81 distinct; the surface lies at
  // z = 0.2 x 0.5 = 0.1 over the support's 8 x 8 mm square.
  const auto grid = test::gridMesh(2, 2, 4.0, 4.0);
  ddf::DisplacementField field(grid, test::constantVectors(grid, {0, 0, 0.5}), 5, 0.2f);
  DdfMetadata metadata;
  metadata.designMesh = ddf::TriangleMesh{
      {{0.0, 0.0, 0.0}, {4.0, 0.0, 0.0}, {4.0, 4.0, 0.0}, {0.0, 4.0, 0.0}}, {{0, 1, 2}, {0, 2, 3}}};
  writeDdf(field, dir / "grid.ddf", metadata);
  const auto run = runCli(dir, {"info", (dir / "grid.ddf").string(), "--json"});
  ASSERT_EQ(run.exitCode, 0) << run.err;
  const nlohmann::json info = nlohmann::json::parse(run.out);
  EXPECT_EQ(info["file"], (dir / "grid.ddf").string());
  EXPECT_EQ(info["fileBytes"], std::filesystem::file_size(dir / "grid.ddf"));
  EXPECT_EQ(info["formatVersion"], 2);
  EXPECT_EQ(info["designMeshTriangles"], 2);
  EXPECT_EQ(info["vertices"], 9);
  EXPECT_EQ(info["faces"], 8);
  EXPECT_EQ(info["pointsPerFace"], 15);
  EXPECT_EQ(info["storedHeights"], 120);
  EXPECT_EQ(info["rasterPoints"], 81);
  EXPECT_NEAR(info["heightMin"].get<double>(), 0.2, 1e-7);
  EXPECT_NEAR(info["heightMax"].get<double>(), 0.2, 1e-7);
  EXPECT_EQ(info["heightsAtCrustBottom"], 0);
  EXPECT_EQ(info["nonFiniteHeights"], 0);
  const auto expectBox = [&](const char* key, double z) {
    const nlohmann::json& box = info[key];
    ASSERT_EQ(box.size(), 2u) << key;
    for (int c = 0; c < 3; ++c) {
      EXPECT_NEAR(box["min"][c].get<double>(), c == 2 ? z : 0.0, 1e-6) << key;
      EXPECT_NEAR(box["max"][c].get<double>(), c == 2 ? z : 8.0, 1e-6) << key;
    }
  };
  expectBox("supportBounds", 0.0);
  expectBox("surfaceBounds", 0.1);
  EXPECT_NEAR(info["longestSupportEdgeMm"].get<double>(), 4.0 * std::sqrt(2.0), 1e-9);
  EXPECT_NEAR(info["rasterSpacingMm"].get<double>(), std::sqrt(2.0), 1e-9);
  for (const char* side : {"minAboveMm", "medianAboveMm"})
    EXPECT_NEAR(info["crustReach"][side].get<double>(), 0.4, 1e-6) << side;
  for (const char* side : {"minBelowMm", "medianBelowMm"})
    EXPECT_NEAR(info["crustReach"][side].get<double>(), 0.6, 1e-6) << side;
  EXPECT_EQ(info["sourceUnit"], "mm");
  EXPECT_EQ(info["cadFaces"], 0);
  EXPECT_EQ(info["cadFaceNames"], nlohmann::json::array());
  // A flat support with parallel vectors and heights inside the crust breaks no constraint;
  // parallel stubbles never cross, so the smallest crust height is infinite, which JSON has
  // no number for: null.
  const nlohmann::json& check = info["validation"];
  EXPECT_EQ(check["ok"], true) << run.out;
  for (const char* key : {"constraint1", "constraint2", "constraint3", "suppressed"})
    EXPECT_EQ(check[key], 0) << key;
  EXPECT_TRUE(check["minCrustHeight"].is_null()) << run.out;
}

TEST(CliUnits, InfoOnAnOldFileSaysTheUnitIsNotRecorded) {
  test::ScratchDir dir;
  const auto run = runCli(dir, {"info", DDFCAM_TEST_DATA_DIR "/octahedron_m4_v1.ddf"});
  ASSERT_EQ(run.exitCode, 0) << run.err;
  EXPECT_THAT(run.out, HasSubstr(".ddf format version 1"));
  EXPECT_THAT(run.out, HasSubstr("source unit: not recorded (mm assumed)"));
  EXPECT_THAT(run.out, Not(HasSubstr("CAD faces")));
}

TEST(CliUnits, InfoOnAMeshConvertsItInItsUnit) {
  test::ScratchDir dir;
  writeMesh(bowlInMetres(), dir / "bowl.obj");
  const auto run = runCli(dir, {"info", (dir / "bowl.obj").string(), "--units", "m", "--json"});
  ASSERT_EQ(run.exitCode, 0) << run.err;
  EXPECT_THAT(run.out, HasSubstr("\"sourceUnit\": \"m\""));
  EXPECT_THAT(run.out, HasSubstr("\"converted\": true"));
  EXPECT_TRUE(nlohmann::json::parse(run.out)["crustReach"]["minAboveMm"].is_number()) << run.out;
  EXPECT_TRUE(test::infoSaysValid(run.out)) << run.out;
}

TEST(CliUnits, AStockTheCrustCannotHoldIsRefusedWithTheLargestAllowance) {
  test::ScratchDir dir;
  const std::string off = DDFCAM_TEST_DATA_DIR "/bowl_patch.off";
  const auto output = (dir / "stock.ddf").string();
  const auto held = runCli(dir, {"convert", off, "-o", output, "--stock", "0.1"});
  ASSERT_EQ(held.exitCode, 0) << held.err;
  EXPECT_THAT(held.out, HasSubstr("stock allowance 0.1 mm: the crust holds it"));
  std::filesystem::remove(output);
  // The bowl (10 mm across, concave) cannot carry 50 mm of stock anywhere near its rim.
  const auto refused = runCli(dir, {"convert", off, "-o", output, "--stock", "50"});
  EXPECT_EQ(refused.exitCode, 3) << refused.err;
  EXPECT_THAT(refused.err, HasSubstr("cannot hold the stock of 50 mm"));
  EXPECT_THAT(refused.err, HasSubstr("largest allowance it holds: "));
  EXPECT_FALSE(std::filesystem::exists(output));
  const auto allowed =
      runCli(dir, {"convert", off, "-o", output, "--stock", "50", "--allow-invalid"});
  EXPECT_EQ(allowed.exitCode, 0) << allowed.err;
  EXPECT_TRUE(std::filesystem::exists(output));
}

TEST(CliUnits, ConvertHelpNamesTheUnitAndConversionOptions) {
  test::ScratchDir dir;
  const auto help = runCli(dir, {"convert", "--help"});
  EXPECT_EQ(help.exitCode, 0);
  EXPECT_THAT(help.out, Not(HasSubstr("Coordinates are taken as mm")));
  for (const char* option :
       {"--units", "--support reduced|input", "--tolerance", "--raster-spacing", "--stock"})
    EXPECT_THAT(help.out, HasSubstr(option));
}

}  // namespace
}  // namespace ddfcam::io

namespace ddfcam::io {
namespace {

using test::runCli;
using ::testing::HasSubstr;

TEST(CliCurvature, ReducedDdfKeepsItsMeshAndShowsItsCurvature) {
  // convert keeps the input mesh in the .ddf file, so curvature of the reduced part fits the
  // mesh's vertices (the raster differences of its flat-triangle heights spike at the edges).
  test::ScratchDir dir;
  constexpr double kR = 20.0, kTube = 6.0;
  writeMesh(test::torusMesh(kR, kTube, 120, 48), dir / "torus.off");
  const auto convert = runCli(dir, {"convert", (dir / "torus.off").string(), "-o",
                                    (dir / "torus.ddf").string(), "--support", "reduced"});
  ASSERT_EQ(convert.exitCode, 0) << convert.err;
  DdfMetadata metadata;
  const ddf::DisplacementField part = readDdf(dir / "torus.ddf", &metadata);
  ASSERT_TRUE(metadata.designMesh.has_value());
  EXPECT_EQ(metadata.designMesh->triangles.size(), 11520u);
  EXPECT_LT(part.faceCount(), 11520 / 4);
  const auto info = runCli(dir, {"info", (dir / "torus.ddf").string()});
  ASSERT_EQ(info.exitCode, 0) << info.err;
  EXPECT_THAT(info.out, HasSubstr(", design mesh of 11520 triangles\n"));
  const auto curvature = runCli(dir, {"curvature", (dir / "torus.ddf").string(), "-o",
                                      (dir / "k.vtp").string(), "--csv", (dir / "k.csv").string()});
  ASSERT_EQ(curvature.exitCode, 0) << curvature.err;
  EXPECT_THAT(curvature.out, HasSubstr("vertex quadric fits of the mesh the part came from"));
  // Oracle: the torus' curvature at every CSV row (x, y, z, k_max, k_min in columns 4..8).
  std::istringstream rows(test::readBytes(dir / "k.csv"));
  std::string line;
  std::getline(rows, line);  // header
  double worst = 0.0;
  std::size_t count = 0;
  for (; std::getline(rows, line); ++count) {
    std::vector<double> v;
    std::istringstream cells(line);
    for (std::string cell; std::getline(cells, cell, ',');) v.push_back(std::stod(cell));
    ASSERT_GE(v.size(), 9u) << line;
    const auto [k1, k2] = test::torusCurvature(kR, kTube, ddf::Vec3(v[4], v[5], v[6]));
    worst = std::max({worst, std::abs(v[7] - k1), std::abs(v[8] - k2)});
  }
  ASSERT_GT(count, 10000u);
  EXPECT_LT(worst, 0.02 / kTube);
}

}  // namespace
}  // namespace ddfcam::io
