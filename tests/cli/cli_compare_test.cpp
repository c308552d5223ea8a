// SPDX-License-Identifier: MIT
// Runs ddfcam-cli compare on analytic sheets (a plane mould against a sinusoid: the area within
// +-tol is (2/pi) asin(tol/A)) and once on the shared forming pair.
#include <ddfcam/io/mesh/mesh_io.h>

#include <gmock/gmock.h>
#include <gtest/gtest.h>
#include <nlohmann/json.hpp>

#include <chrono>
#include <cmath>
#include <cstdio>
#include <filesystem>
#include <iostream>
#include <numbers>
#include <sstream>

#include "cli_mould_support.h"
#include "cli_simulate_support.h"

namespace ddfcam::io {
namespace {

using test::CliRun;
using ::testing::HasSubstr;

struct SheetPair {
  test::ScratchDir dir;
  std::filesystem::path mould = dir / "mould.stl", formed = dir / "formed.stl";
  explicit SheetPair(double amplitude) {
    writeMesh(test::flatSheet(), mould);
    writeMesh(test::sinusoidSheet(amplitude), formed);
  }
};

nlohmann::json readJson(const std::filesystem::path& path) {
  return nlohmann::json::parse(test::readBytes(path));
}

TEST(CliCompare, SinusoidAreaWithinToleranceMatchesTheArcsineLaw) {
  const SheetPair pair(1.0);
  const CliRun run =
      test::cli(pair.dir, "compare",
                {pair.mould.string(), pair.formed.string(), "--resolution", "9", "--tolerance",
                 "0.5", "-o", (pair.dir / "d.vtp").string(), "--csv", (pair.dir / "d.csv").string(),
                 "--json", (pair.dir / "s.json").string()});
  ASSERT_EQ(run.exitCode, 0) << run.err;
  EXPECT_THAT(run.out, HasSubstr("within [-0.5, 0.5] mm"));
  EXPECT_THAT(run.out, HasSubstr("stages:"));
  const nlohmann::json json = readJson(pair.dir / "s.json");
  const nlohmann::json& s = json["statistics"];
  const double expected = 100.0 * (2.0 / std::numbers::pi) * std::asin(0.5 / 1.0);  // 33.33 %
  EXPECT_NEAR(s["within_band_percent"].get<double>(), expected, 1.5);
  // Half of the rest lies above the band (short of the mould), half below.
  EXPECT_NEAR(s["short_percent"].get<double>(), (100.0 - expected) / 2.0, 1.5);
  EXPECT_NEAR(s["max_mm"].get<double>(), 1.0, 0.01);
  EXPECT_NEAR(s["min_mm"].get<double>(), -1.0, 0.01);
  EXPECT_NEAR(s["mean_mm"].get<double>(), 0.0, 0.02);
  EXPECT_NEAR(s["sigma_mm"].get<double>(), 1.0 / std::sqrt(2.0), 0.02);  // RMS of a sine
  EXPECT_NEAR(s["area_mm2"].get<double>(), test::kSheetWidth * test::kSheetDepth, 1e-6);
  EXPECT_GE(json["stages"].size(), 1u);
  EXPECT_EQ(json["unresolved_faces"].get<int>(), 0);
  // The histogram's bins and tails hold the whole area.
  double area =
      json["histogram"]["below_mm2"].get<double>() + json["histogram"]["above_mm2"].get<double>();
  for (const auto& bin : json["histogram"]["area_mm2"]) area += bin.get<double>();
  EXPECT_NEAR(area, s["area_mm2"].get<double>(), 1e-6 * area);
  // Every CSV row: the deviation vector is (0, 0, d) with d = sin(2 pi x / 20) (mould z = 0).
  std::istringstream csv(test::readBytes(pair.dir / "d.csv"));
  std::string line;
  std::getline(csv, line);
  EXPECT_EQ(line, "x_mm,y_mm,z_mm,dx_mm,dy_mm,dz_mm,deviation_mm");
  int rows = 0;
  while (std::getline(csv, line)) {
    double v[7];
    ASSERT_EQ(std::sscanf(line.c_str(), "%lf,%lf,%lf,%lf,%lf,%lf,%lf", v, v + 1, v + 2, v + 3,
                          v + 4, v + 5, v + 6),
              7)
        << line;
    const double d = std::sin(2.0 * std::numbers::pi * v[0] / test::kWavelength);
    EXPECT_NEAR(v[6], d, 2e-3) << line;
    EXPECT_NEAR(v[5], d, 2e-3) << line;
    ++rows;
  }
  // Distinct raster points of the 21 x 6-vertex mould (325 edges, 200 faces) at m = 9: 126
  // vertices, 7 per edge, 21 per face.
  EXPECT_EQ(rows, 126 + 7 * 325 + 21 * 200);
  EXPECT_THAT(test::readBytes(pair.dir / "d.vtp"), HasSubstr("Name=\"tolerance_class\""));
}

TEST(CliCompare, FlippedNormalAndBandMirrorTheStatistics) {
  const SheetPair pair(1.0);
  const CliRun run =
      test::cli(pair.dir, "compare",
                {pair.mould.string(), pair.formed.string(), "--resolution", "5", "--band",
                 "-0.25,0.5", "--flip-normal", "--json", (pair.dir / "s.json").string(), "--csv",
                 (pair.dir / "d.csv").string()});
  ASSERT_EQ(run.exitCode, 0) << run.err;
  const nlohmann::json json = readJson(pair.dir / "s.json");
  EXPECT_NEAR(json["statistics"]["max_mm"].get<double>(), 1.0, 0.01);
  EXPECT_NEAR(json["statistics"]["min_mm"].get<double>(), -1.0, 0.01);
  EXPECT_EQ(json["band"]["lower_mm"].get<double>(), -0.25);
  // Band [-0.25, 0.5] of a sine: (asin(0.25) + asin(0.5)) / pi of the area.
  const double expected = 100.0 * (std::asin(0.25) + std::asin(0.5)) / std::numbers::pi;
  EXPECT_NEAR(json["statistics"]["within_band_percent"].get<double>(), expected, 2.0);
  // The vectors still point to the formed surface; the deviation is measured along -z.
  std::istringstream csv(test::readBytes(pair.dir / "d.csv"));
  std::string line;
  std::getline(csv, line);
  int checked = 0;
  while (std::getline(csv, line)) {
    double v[7];
    ASSERT_EQ(std::sscanf(line.c_str(), "%lf,%lf,%lf,%lf,%lf,%lf,%lf", v, v + 1, v + 2, v + 3,
                          v + 4, v + 5, v + 6),
              7);
    EXPECT_NEAR(v[6], -v[5], 1e-6) << line;
    checked += std::abs(v[5]) > 0.1;
  }
  EXPECT_GT(checked, 100);
}

TEST(CliCompare, SheetsInMetresWithUnitsMGiveTheStatisticsInMm) {
  // The sinusoid pair of the arcsine test written in metres (40 x 10 mm is 0.04 x 0.01 m, so
  // without --units it draws the size warning); read with --units m it is the same pair.
  test::ScratchDir dir;
  const auto inMetres = [](ddf::TriangleMesh mesh) {
    for (Eigen::Vector3d& v : mesh.vertices) v /= 1000.0;
    return mesh;
  };
  writeMesh(inMetres(test::flatSheet()), dir / "mould.obj");
  writeMesh(inMetres(test::sinusoidSheet(1.0)), dir / "formed.obj");
  const std::vector<std::string> args = {(dir / "mould.obj").string(),
                                         (dir / "formed.obj").string(),
                                         "--resolution",
                                         "9",
                                         "--tolerance",
                                         "0.5",
                                         "--json",
                                         (dir / "s.json").string()};
  std::vector<std::string> withUnits = args;
  withUnits.insert(withUnits.end(), {"--units", "m"});
  const CliRun run = test::cli(dir, "compare", withUnits);
  ASSERT_EQ(run.exitCode, 0) << run.err;
  EXPECT_THAT(run.err, ::testing::Not(HasSubstr("units across")));
  const nlohmann::json json = readJson(dir / "s.json");
  const nlohmann::json& s = json["statistics"];
  const double expected = 100.0 * (2.0 / std::numbers::pi) * std::asin(0.5 / 1.0);
  EXPECT_NEAR(s["within_band_percent"].get<double>(), expected, 1.5);
  EXPECT_NEAR(s["max_mm"].get<double>(), 1.0, 0.01);
  EXPECT_NEAR(s["area_mm2"].get<double>(), test::kSheetWidth * test::kSheetDepth, 1e-6);
  const CliRun warned = test::cli(dir, "compare", args);
  EXPECT_THAT(warned.err, HasSubstr("mould.obj is 0.04123 units across; if it is not in mm, "
                                    "pass --units (as m it would be 41.23 mm)"));
}

TEST(CliCompare, BadUsageAndMissingFilesFailWithAMessage) {
  const SheetPair pair(1.0);
  CliRun run =
      test::cli(pair.dir, "compare",
                {pair.mould.string(), pair.formed.string(), "--tolerance", "1", "--band", "-1,1"});
  EXPECT_NE(run.exitCode, 0);
  EXPECT_THAT(run.err, HasSubstr("either --tolerance or --band"));
  run = test::cli(pair.dir, "compare", {pair.mould.string(), (pair.dir / "none.stl").string()});
  EXPECT_NE(run.exitCode, 0);
  EXPECT_THAT(run.err, HasSubstr("none.stl"));
  run = test::cli(pair.dir, "compare", {pair.mould.string(), pair.formed.string(), "--align", "x"});
  EXPECT_NE(run.exitCode, 0);
  EXPECT_THAT(run.err, HasSubstr("none or best-fit"));
}

TEST(CliCompare, SharedFormingPair) {
  const std::filesystem::path dir =
      std::filesystem::path(DDFCAM_SHARED_DATA_DIR) / "meshes" / "springback-deepdrawn";
  if (!std::filesystem::exists(dir / "target_AF_bs.stl")) GTEST_SKIP() << "shared pair absent";
  test::ScratchDir scratch;
  const auto start = std::chrono::steady_clock::now();
  const CliRun run =
      test::cli(scratch, "compare",
                {(dir / "target_AF_bs.stl").string(), (dir / "mesh_ausgerichtet1.stl").string(),
                 "--resolution", "2", "--json", (scratch / "s.json").string()});
  const double seconds =
      std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
  ASSERT_EQ(run.exitCode, 0) << run.err;
  const nlohmann::json json = readJson(scratch / "s.json");
  std::cout << run.out << "  (" << seconds << " s)\n";
  // Signed distances of the formed vertices to the target span -7.77 .. 6.42 mm (1 % and 99 %
  // quantiles -6.78 and 1.15): from the mould side the extremes lie near -7.8 and above 1.
  EXPECT_GT(json["statistics"]["max_mm"].get<double>(), 1.0);
  EXPECT_LT(json["statistics"]["min_mm"].get<double>(), -6.5);
  EXPECT_GT(json["statistics"]["min_mm"].get<double>(), -8.5);
  EXPECT_GT(json["statistics"]["area_mm2"].get<double>(), 1e4);
}

}  // namespace
}  // namespace ddfcam::io
