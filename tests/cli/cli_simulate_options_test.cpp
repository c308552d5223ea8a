// SPDX-License-Identifier: MIT
// ddfcam-cli simulate options against analytic truth: swept groove, sampling step from the
// tolerance, penetration correction in a trough, Preston conservation, tool library and stock.
#include <ddfcam/ddf/displacement_field.h>
#include <ddfcam/ddf/triangle_mesh.h>
#include <ddfcam/io/mesh/ddf_file.h>
#include <ddfcam/io/mesh/mesh_io.h>
#include <ddfcam/io/programs/tool_path_csv.h>

#include <gmock/gmock.h>
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>

#include "cli_simulate_support.h"

namespace ddfcam::io {
namespace {

using test::cli;
using test::CliRun;
using test::jsonNumber;
using test::kSpacing;
using ::testing::HasSubstr;

// Common arguments: the plate, a CSV, an output and a report in @p dir.
std::vector<std::string> baseArgs(const test::ScratchDir& dir, const std::string& csv) {
  return {(dir / "part.ddf").string(), "--paths",  (dir / csv).string(),     "-o",
          (dir / "out.ddf").string(),  "--report", (dir / "r.json").string()};
}

std::vector<std::string> operator+(std::vector<std::string> a, const std::vector<std::string>& b) {
  a.insert(a.end(), b.begin(), b.end());
  return a;
}

TEST(CliSimulate, SweptCoarsePathCutsAContinuousGroove) {
  test::ScratchDir dir;
  writeDdf(test::plate(), dir / "part.ddf");
  writeToolPathCsv(test::straightPass(4.0), dir / "coarse.csv");  // x = 2, 6, 10, 14, 18
  const std::vector<std::string> roll = {"--radius", "5", "--width", "4.1", "--allowance", "0.1"};
  const double radius = 5.0, h = 0.1;
  // Discrete: halfway between poses 4 mm apart the roll bottom is R - sqrt(R^2 - 2^2) above
  // the contact line, above the stock, so the groove is interrupted there.
  CliRun run = cli(dir, "simulate", baseArgs(dir, "coarse.csv") + roll);
  ASSERT_EQ(run.exitCode, 0) << run.err;
  ASSERT_GT(radius - std::sqrt(radius * radius - 4.0), h);
  auto grid = test::heightGrid(readDdf(dir / "out.ddf"));
  for (const double x : {4.0, 8.0, 12.0, 16.0})
    EXPECT_NEAR((grid[{std::lround(x / kSpacing), 40}]), h, 1e-5) << x;
  // Swept: the hull of consecutive roll instances has its bottom on the contact line.
  run = cli(dir, "simulate",
            baseArgs(dir, "coarse.csv") + roll + std::vector<std::string>{"--swept"});
  ASSERT_EQ(run.exitCode, 0) << run.err;
  grid = test::heightGrid(readDdf(dir / "out.ddf"));
  for (const auto& [at, z] : grid) {
    const double x = at.first * kSpacing, y = at.second * kSpacing;
    if (x >= 2.0 && x <= 18.0 && std::abs(y - 10.0) <= 2.0) {
      EXPECT_NEAR(z, 0.0, 2e-3) << x << ", " << y;
    }
  }
  const std::string json = test::readBytes(dir / "r.json");
  EXPECT_THAT(json, HasSubstr("\"mode\": \"swept\""));
  const double segment = radius * radius * std::acos((radius - h) / radius) -
                         (radius - h) * std::sqrt(2 * radius * h - h * h);
  const double analytic = (16.0 * h + segment) * (4.0 + kSpacing);
  EXPECT_NEAR(jsonNumber(json, "removed_volume_mm3"), analytic, 0.03 * analytic) << json;
}

TEST(CliSimulate, SampleToleranceChoosesTheToolProfileStep) {
  test::ScratchDir dir;
  writeDdf(test::plate(), dir / "part.ddf");
  writeToolPathCsv(test::straightPass(4.0), dir / "coarse.csv");
  const std::vector<std::string> roll = {"--radius", "5", "--width", "4.1", "--allowance", "0.1"};
  // Straight pass on a plane: only the cusp between two roll instances binds, its step is the
  // chord of the R = 5 circle at height T (004 eq. 5.7): 2 sqrt(2 R T - T^2) = 0.19999 mm,
  // below the 0.25 mm raster spacing.
  const double T = 0.001, step = 2.0 * std::sqrt(2.0 * 5.0 * T - T * T);
  CliRun run =
      cli(dir, "simulate",
          baseArgs(dir, "coarse.csv") + roll +
              std::vector<std::string>{"--sample-tolerance", "0.001", "--tolerance", "0.001"});
  ASSERT_EQ(run.exitCode, 0) << run.err;
  std::string json = test::readBytes(dir / "r.json");
  EXPECT_NEAR(jsonNumber(json, "sample_step_mm"), step, 1e-5) << json;
  EXPECT_THAT(json, HasSubstr("\"sample_rule\": \"tool profile\""));
  EXPECT_EQ(jsonNumber(json, "poses"), std::ceil(16.0 / step) + 1.0) << json;
  for (const auto& [at, z] : test::heightGrid(readDdf(dir / "out.ddf"))) {
    const double x = at.first * kSpacing, y = at.second * kSpacing;
    if (x >= 2.0 && x <= 18.0 && std::abs(y - 10.0) <= 2.0) {
      EXPECT_NEAR(z, 0.0, T + 0.25 * T + 1e-4) << x;  // cusp + facets (chord T / 4)
    }
  }
  run = cli(dir, "simulate",
            baseArgs(dir, "coarse.csv") + roll + std::vector<std::string>{"--step", "0.5"});
  ASSERT_EQ(run.exitCode, 0) << run.err;
  json = test::readBytes(dir / "r.json");
  EXPECT_NEAR(jsonNumber(json, "sample_step_mm"), 0.5, 1e-12) << json;
  EXPECT_THAT(json, HasSubstr("\"sample_rule\": \"override\""));
  EXPECT_EQ(jsonNumber(json, "poses"), 33.0) << json;
}

// A trough along x across the plate: z = -D exp(-(y - 10)^2 / 2), bottom radius 1 / D.
constexpr double kTroughDepth = 0.8;
double trough(double y) {
  return -kTroughDepth * std::exp(-0.5 * (y - 10.0) * (y - 10.0));
}
double troughSlope(double y) {
  return -(y - 10.0) * trough(y);
}

TEST(CliSimulate, CorrectLiftsARollOutOfAConcaveTrough) {
  test::ScratchDir dir;
  ddf::DisplacementField part = test::plate();
  const int n = part.raster().m - 1;
  for (int f = 0; f < part.faceCount(); ++f)
    for (int k = 0; k <= n; ++k)
      for (int i = 0; i + k <= n; ++i)
        part.heights(f)[part.raster().index(i, k)] =
            static_cast<float>(trough(part.surfacePoint(f, i, k).y()));
  writeDdf(part, dir / "part.ddf");
  // A roll (axis x, R 5 > bottom radius 1.25) fed across the trough along y.
  planning::ClProgram table;
  table.pointKind = planning::ClPointKind::Contact;
  for (int p = 0; p <= 48; ++p) {
    planning::ClPoint row;
    row.point = p;
    const double y = 4.0 + 0.25 * p;
    row.positionMm = {10.0, y, trough(y)};
    row.axis = ddf::Vec3(1, 0, 0);
    row.normal = ddf::Vec3(0, -troughSlope(y), 1).normalized();
    table.points.push_back(row);
  }
  writeToolPathCsv(table, dir / "across.csv");
  const std::vector<std::string> roll = {"--radius", "5", "--width", "4", "--no-vconvexity-check"};
  CliRun run = cli(dir, "simulate", baseArgs(dir, "across.csv") + roll);
  ASSERT_EQ(run.exitCode, 0) << run.err;
  EXPECT_LT(jsonNumber(test::readBytes(dir / "r.json"), "min_mm"), -0.1);  // gouged
  run = cli(dir, "simulate",
            baseArgs(dir, "across.csv") + roll +
                std::vector<std::string>{"--correct", "--correct-grid", "100"});
  ASSERT_EQ(run.exitCode, 0) << run.err;
  const std::string json = test::readBytes(dir / "r.json");
  // At the bottom pose the roll must rest on the flanks: centre height max over y of
  // z(y) + sqrt(R^2 - (y - 10)^2), brute force on the true profile.
  double centre = -1e9;
  for (double y = 5.0; y <= 15.0; y += 1e-4)
    centre = std::max(centre, trough(y) + std::sqrt(std::max(0.0, 25.0 - (y - 10) * (y - 10))));
  const double bottomLift = centre - 5.0 + kTroughDepth;
  EXPECT_GT(jsonNumber(json, "poses_lifted"), 0.0) << json;
  EXPECT_GE(jsonNumber(json, "max_lift_mm"), bottomLift - 0.01) << json;
  EXPECT_GE(jsonNumber(json, "ms"), 0.0) << json;
  EXPECT_GE(jsonNumber(json, "min_mm"), -0.01) << json;  // no gouge beyond a small tolerance
}

TEST(CliSimulate, PrestonRemovesTheConservedCrossSection) {
  test::ScratchDir dir;
  writeDdf(test::plate(), dir / "part.ddf");
  writeToolPathCsv(test::straightPass(0.1), dir / "pass.csv");
  const CliRun run =
      cli(dir, "simulate",
          baseArgs(dir, "pass.csv") +
              std::vector<std::string>{"--radius", "5", "--width", "4", "--preston", "--kp", "1e-7",
                                       "--force", "100", "--wheel-speed", "30", "--feed", "1000"});
  ASSERT_EQ(run.exitCode, 0) << run.err;
  // Oracle: cross-section K_p F v_s / v_f = 1e-7 * 100 * 30000 / (1000 / 60) mm^2; the pass
  // feeds 16 mm (half time steps at both ends), so the volume is 16 times that.
  const double section = 1e-7 * 100.0 * 30000.0 / (1000.0 / 60.0), volume = 16.0 * section;
  const std::string json = test::readBytes(dir / "r.json");
  EXPECT_THAT(json, HasSubstr("\"mode\": \"preston\""));
  EXPECT_NEAR(jsonNumber(json, "removed_volume_mm3"), volume, 0.02 * volume) << json;
  double measured = 0.0, midSection = 0.0;
  for (const auto& [at, z] : test::heightGrid(readDdf(dir / "out.ddf"))) {
    EXPECT_LE(z, 1e-6);
    const double w = (at.first % 80 == 0 ? 0.5 : 1.0) * (at.second % 80 == 0 ? 0.5 : 1.0);
    measured -= w * z * kSpacing * kSpacing;
    if (at.first == 40) midSection -= z * kSpacing;  // x = 10, far from the pass ends
  }
  EXPECT_NEAR(measured, volume, 0.02 * volume);
  EXPECT_NEAR(midSection, section, 0.03 * section);
}

TEST(CliSimulate, ToolFromALibraryFileOnAStockMesh) {
  test::ScratchDir dir;
  writeDdf(test::plate(), dir / "part.ddf");
  writeToolPathCsv(test::straightPass(0.1), dir / "pass.csv");
  test::writeBytes(dir / "tools.txt",
                   "# two tools\n"
                   "tool \"roll R5\" kind=cylinder_roll radius_mm=5 width_mm=4\n"
                   "tool \"ball D4\" kind=ball_end radius_mm=2 width_mm=4 segments=0 "
                   "chord_tolerance_mm=0.001\n");
  // Stock: the plane z = 0.1 over the whole plate, as an allowance of 0.1 would give.
  ddf::TriangleMesh stock;
  stock.vertices = {{-1, -1, 0.1}, {21, -1, 0.1}, {21, 21, 0.1}, {-1, 21, 0.1}};
  stock.triangles = {{0, 1, 2}, {0, 2, 3}};
  writeMesh(stock, dir / "stock.obj");
  const std::vector<std::string> library = {"--tool-file", (dir / "tools.txt").string(),
                                            "--stock-mesh", (dir / "stock.obj").string()};
  CliRun run =
      cli(dir, "simulate",
          baseArgs(dir, "pass.csv") + library + std::vector<std::string>{"--tool-name", "ball D4"});
  ASSERT_EQ(run.exitCode, 0) << run.err;
  // Ball-end R = 2 with its tip on the contact line: cross-section z = R - sqrt(R^2 - dy^2),
  // capped by the stock.
  for (const auto& [at, z] : test::heightGrid(readDdf(dir / "out.ddf"))) {
    const double x = at.first * kSpacing, dy = std::abs(at.second * kSpacing - 10.0);
    if (x < 3.0 || x > 17.0) continue;
    const double ball = dy < 2.0 ? 2.0 - std::sqrt(4.0 - dy * dy) : 1.0;
    EXPECT_NEAR(z, std::min(0.1, ball), 2e-3) << x << ", " << dy;
  }
  EXPECT_THAT(test::readBytes(dir / "r.json"), HasSubstr("\"kind\": \"ball_end\""));
  run = cli(dir, "simulate",
            baseArgs(dir, "pass.csv") + library + std::vector<std::string>{"--tool-name", "nope"});
  EXPECT_EQ(run.exitCode, 1);
  EXPECT_THAT(run.err, HasSubstr("\"nope\""));
  EXPECT_THAT(run.err, HasSubstr("ball D4"));
}

TEST(CliSimulate, LeadTurnsAFlatEndIntoAnEllipticGroove) {
  test::ScratchDir dir;
  writeDdf(test::plate(), dir / "part.ddf");
  const double step = 0.02;
  writeToolPathCsv(test::straightPass(step), dir / "pass.csv");
  const CliRun run =
      cli(dir, "simulate",
          baseArgs(dir, "pass.csv") + std::vector<std::string>{"--tool", "flat_end", "--radius",
                                                               "3", "--lead", "15", "--allowance",
                                                               "0.1", "--tolerance", "0.004",
                                                               "--no-vconvexity-check"});
  ASSERT_EQ(run.exitCode, 0) << run.err;
  // The bottom disc leans 15 deg towards the feed with its leading rim on the contact line:
  // across the feed its lowest point at offset dy lies (R - sqrt(R^2 - dy^2)) sin(lead) up;
  // the tilted disc leaves a feed sawtooth of up to step tan(lead), the facets T / 4.
  const double slack = step * std::tan(M_PI / 12.0) + 0.25 * 0.004 + 1e-4;
  for (const auto& [at, z] : test::heightGrid(readDdf(dir / "out.ddf"))) {
    const double x = at.first * kSpacing, dy = std::abs(at.second * kSpacing - 10.0);
    if (x < 3.0 || x > 17.0) continue;
    const double disc = dy < 3.0 ? std::sin(M_PI / 12.0) * (3.0 - std::sqrt(9.0 - dy * dy)) : 1.0;
    EXPECT_NEAR(z, std::min(0.1, disc), slack) << x << ", " << dy;
  }
  EXPECT_THAT(test::readBytes(dir / "r.json"), HasSubstr("\"lead_deg\": 15"));
}

}  // namespace
}  // namespace ddfcam::io
