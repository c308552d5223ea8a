// SPDX-License-Identifier: MIT
// Runs ddfcam-cli simulate: a straight roll pass over a flat plate checked against the analytic
// groove, plan + simulate on the demo part, the JSON text of reports, and bad arguments.
#include <ddfcam/ddf/analytic_generators.h>
#include <ddfcam/ddf/displacement_field.h>
#include <ddfcam/io/mesh/ddf_file.h>
#include <ddfcam/io/programs/tool_path_csv.h>

#include <gmock/gmock.h>
#include <gtest/gtest.h>

#include <cmath>
#include <limits>
#include <map>
#include <optional>
#include <regex>
#include <string>
#include <vector>

#include "cli_simulate_support.h"
#include "json_output.h"

namespace ddfcam::io {
namespace {

using ::testing::HasSubstr;

using test::cli;
using test::CliRun;
using test::jsonNumber;
using test::kPlate;
using test::kSpacing;
using test::plate;
using test::straightPass;

TEST(CliSimulate, StraightRollPassOnAPlateCutsTheAnalyticGroove) {
  test::ScratchDir dir;
  writeDdf(plate(), dir / "plate.ddf");
  writeToolPathCsv(straightPass(), dir / "pass.csv");
  const double radius = 5.0, width = 4.1, allowance = 0.1, tolerance = 0.01;
  const CliRun run = cli(dir, "simulate",
                         {(dir / "plate.ddf").string(), "--paths", (dir / "pass.csv").string(),
                          "--radius", "5", "--width", "4.1", "--allowance", "0.1", "--tolerance",
                          "0.01", "-o", (dir / "out.ddf").string(), "--report",
                          (dir / "r.json").string(), "--error-map", (dir / "e.vtp").string()});
  ASSERT_EQ(run.exitCode, 0) << run.err;
  const ddf::DisplacementField out = readDdf(dir / "out.ddf");
  ASSERT_EQ(out.faceCount(), 32);
  // Independent truth from the read-back heights (z = h on this plate): inside the groove
  // (|y - 10| < W/2, the contact span) the roll bottom at z = 0; outside the stock at 0.1.
  double inTolArea = 0, area = 0, removed = 0;
  const auto grid = test::heightGrid(out);
  ASSERT_EQ(grid.size(), 81u * 81u);
  for (const auto& [at, z] : grid) {
    const double x = at.first * kSpacing, y = at.second * kSpacing;
    const bool inGroove = std::abs(y - 10.0) < 0.5 * width && x >= 2.0 && x <= 18.0;
    const bool outside = std::abs(y - 10.0) > 0.5 * width || x < 2.0 - 1.5 || x > 18.0 + 1.5;
    if (inGroove) {
      EXPECT_NEAR(z, 0.0, 2e-3) << x << ", " << y;
    }
    if (outside) {
      EXPECT_NEAR(z, allowance, 1e-5) << x << ", " << y;
    }
    // Trapezoid weights of the regular grid.
    const double w = (at.first % 80 == 0 ? 0.5 : 1.0) * (at.second % 80 == 0 ? 0.5 : 1.0);
    area += w;
    if (std::abs(z) <= tolerance) inTolArea += w;
    removed += w * (allowance - z) * kSpacing * kSpacing;
  }
  const std::string json = test::readBytes(dir / "r.json");
  EXPECT_NEAR(jsonNumber(json, "max_mm"), allowance, 1e-5) << json;
  EXPECT_NEAR(jsonNumber(json, "min_mm"), 0.0, 2e-3) << json;
  EXPECT_EQ(jsonNumber(json, "poses"), 161.0);
  EXPECT_EQ(jsonNumber(json, "passes"), 1.0);
  EXPECT_NEAR(jsonNumber(json, "in_tolerance_percent"), 100.0 * inTolArea / area, 1.0) << json;
  EXPECT_NEAR(jsonNumber(json, "area_mm2"), kPlate * kPlate, 1e-6);
  // Removed volume: per unit width the 16 mm contact span times 0.1 plus one circular segment
  // of height 0.1 (half at each end); the piecewise linear raster widens the 4.1 mm groove
  // (cut rows y = 8 .. 12) to 4 + 0.25 mm.
  const double h = allowance, segment = radius * radius * std::acos((radius - h) / radius) -
                                        (radius - h) * std::sqrt(2 * radius * h - h * h);
  const double analytic = (16.0 * h + segment) * (4.0 + kSpacing);
  EXPECT_NEAR(jsonNumber(json, "removed_volume_mm3"), analytic, 0.03 * analytic) << json;
  EXPECT_NEAR(jsonNumber(json, "removed_volume_mm3"), removed, 0.01 * removed) << json;
  const std::string vtp = test::readBytes(dir / "e.vtp");
  EXPECT_THAT(vtp, HasSubstr("NumberOfPoints=\"6561\""));
  EXPECT_THAT(vtp, HasSubstr("Name=\"deviation_mm\""));
}

TEST(CliSimulate, PlanThenSimulateOnTheDemoPart) {
  test::ScratchDir dir;
  const CliRun plan =
      cli(dir, "plan",
          {"demo", "-o", (dir / "p.csv").string(), "--field", "fixed", "--no-smooth", "--seeding",
           "transverse", "--spacing", "8", "--tool", "ball"});
  ASSERT_EQ(plan.exitCode, 0) << plan.err;
  std::size_t cutRows = 0;
  for (const auto& row : readToolPathCsv(dir / "p.csv").points)
    cutRows += row.move == planning::MoveKind::Cut ? 1 : 0;
  const CliRun run = cli(dir, "simulate",
                         {"demo", "--paths", (dir / "p.csv").string(), "--tool", "ball",
                          "--no-vconvexity-check", "--allowance", "0.05", "--tolerance", "0.2",
                          "-o", (dir / "out.ddf").string(), "--report", (dir / "r.json").string()});
  ASSERT_EQ(run.exitCode, 0) << run.err;
  EXPECT_THAT(run.out, HasSubstr("deviation (mm)"));
  const ddf::DisplacementField demo = ddf::demoPart().ddf;
  const ddf::DisplacementField out = readDdf(dir / "out.ddf");
  ASSERT_EQ(out.faceCount(), demo.faceCount());
  ASSERT_EQ(out.allHeights().size(), demo.allHeights().size());
  // The workpiece is raised by 0.05 mm along the normal (|v| = 1 mm, so < 0.05 / 0.5 in h) and
  // only ever lowered; some points are cut.
  std::size_t cut = 0;
  for (std::size_t i = 0; i < out.allHeights().size(); ++i) {
    EXPECT_LE(out.allHeights()[i], demo.allHeights()[i] + 0.1f);
    cut += out.allHeights()[i] < demo.allHeights()[i] + 0.049f ? 1 : 0;
  }
  EXPECT_GT(cut, out.allHeights().size() / 50);  // three ball grooves 8 mm apart
  const std::string json = test::readBytes(dir / "r.json");
  EXPECT_EQ(jsonNumber(json, "poses"), static_cast<double>(cutRows));
  EXPECT_LE(jsonNumber(json, "max_mm"), 0.05 + 1e-4) << json;
  EXPECT_LE(jsonNumber(json, "min_mm"), jsonNumber(json, "max_mm"));
  EXPECT_NEAR(jsonNumber(json, "in_tolerance_percent") + jsonNumber(json, "material_left_percent") +
                  jsonNumber(json, "overcut_percent"),
              100.0, 1e-6);
  EXPECT_GT(jsonNumber(json, "removed_volume_mm3"), 0.0);
}

TEST(CliSimulate, APathOfManyPosesIsAnnouncedWithItsEstimate) {
  test::ScratchDir dir;
  writeDdf(plate(), dir / "plate.ddf");
  // 16 mm every 3 um: 5,334 poses, above the 5,000 that are announced.
  writeToolPathCsv(straightPass(0.003), dir / "long.csv");
  writeToolPathCsv(straightPass(), dir / "short.csv");
  const auto run = [&](const char* csv) {
    return cli(dir, "simulate",
               {(dir / "plate.ddf").string(), "--paths", (dir / csv).string(), "--radius", "5",
                "--width", "4.1", "--allowance", "0.1", "-o", (dir / "out.ddf").string()});
  };
  const CliRun longRun = run("long.csv");
  ASSERT_EQ(longRun.exitCode, 0) << longRun.err;
  const std::regex announced(R"(simulating 5334 poses: about (\d+) s \(([0-9.e-]+) ms per pose, timed on 16 of them\))");
  std::smatch m;
  ASSERT_TRUE(std::regex_search(longRun.err, m, announced)) << longRun.err;
  // The estimate is the pose count times the timed mean, rounded up (the mean is printed to
  // six digits, so the product may land on the other side of a whole second).
  EXPECT_NEAR(std::stod(m[1]), std::ceil(5334 * std::stod(m[2]) * 1e-3), 1.0);
  const CliRun shortRun = run("short.csv");
  ASSERT_EQ(shortRun.exitCode, 0) << shortRun.err;
  EXPECT_THAT(shortRun.err, ::testing::Not(HasSubstr("poses: about")));
}

TEST(CliSimulate, BadArgumentsGiveClearErrorsAndExitCodes) {
  test::ScratchDir dir;
  writeDdf(plate(), dir / "plate.ddf");
  writeToolPathCsv(straightPass(), dir / "pass.csv");
  const std::string part = (dir / "plate.ddf").string(), csv = (dir / "pass.csv").string();
  const std::string out = (dir / "o.ddf").string();
  struct Case {
    std::vector<std::string> args;
    int code;
    std::string message;
  };
  const std::vector<Case> cases = {
      {{part, "-o", out}, 2, "--paths"},
      {{part, "--paths", csv}, 2, "--output"},
      {{part, "--paths", csv, "-o", out, "--tool", "cone"}, 2, "expected roll|ball"},
      {{part, "--paths", csv, "-o", out, "--tool", "ball", "--width", "3"}, 2, "--width"},
      {{part, "--paths", csv, "-o", out, "--allowance", "lots"}, 2, "--allowance lots"},
      {{part, "--paths", csv, "-o", out, "--tolerance", "-1"}, 2, "--tolerance"},
      {{part, "--paths", (dir / "missing.csv").string(), "-o", out}, 1, "missing.csv"},
      {{(dir / "nope.ddf").string(), "--paths", csv, "-o", out}, 1, "nope.ddf"},
      {{part, "--paths", csv, "-o", out, "--tool", "torus_cutter"}, 2, "--corner-radius"},
      {{part, "--paths", csv, "-o", out, "--tool", "ball_end", "--corner-radius", "1"},
       2,
       "--corner-radius"},
      {{part, "--paths", csv, "-o", out, "--tool-name", "x"}, 2, "--tool-file"},
      {{part, "--paths", csv, "-o", out, "--tool-file", csv, "--tool-name", "x", "--radius", "2"},
       2,
       "--radius"},
      {{part, "--paths", csv, "-o", out, "--correct-every", "3"}, 2, "--correct"},
      {{part, "--paths", csv, "-o", out, "--correct", "--correct-grid", "1"}, 2, "--correct-grid"},
      {{part, "--paths", csv, "-o", out, "--force", "10"}, 2, "--preston"},
      {{part, "--paths", csv, "-o", out, "--preston", "--swept"}, 2, "--swept"},
      {{part, "--paths", csv, "-o", out, "--lead", "95"}, 2, "--lead"},
      {{part, "--paths", csv, "-o", out, "--step", "0"}, 2, "--step"},
      {{part, "--paths", csv, "-o", out, "--stock-mesh", csv, "--allowance", "0.1"},
       2,
       "--stock-mesh"},
      // 5 mm of stock do not fit into the plate's 1 mm crust.
      {{part, "--paths", csv, "-o", out, "--allowance", "5"}, 1, "allowance"},
  };
  for (const Case& c : cases) {
    const CliRun run = cli(dir, "simulate", c.args);
    EXPECT_EQ(run.exitCode, c.code) << c.args.back() << ": " << run.err;
    EXPECT_THAT(run.err, HasSubstr(c.message)) << c.args.back();
  }
  EXPECT_FALSE(std::filesystem::exists(out));
  planning::ClProgram links = straightPass();
  for (auto& row : links.points) row.move = planning::MoveKind::Link;
  writeToolPathCsv(links, dir / "links.csv");
  const CliRun run =
      cli(dir, "simulate", {part, "--paths", (dir / "links.csv").string(), "-o", out});
  EXPECT_EQ(run.exitCode, 1);
  EXPECT_THAT(run.err, HasSubstr("no cut rows"));
}

TEST(CliSimulate, JsonTextEscapesAndNestsValues) {
  cli::JsonReport json;
  json["text"] = "a\"b\\c\n\x01";
  json["list"] = {1.5, std::nan(""), true};
  json["empty"] = cli::JsonReport::object();
  EXPECT_EQ(cli::jsonText(json),
            "{\n  \"text\": \"a\\\"b\\\\c\\n\\u0001\",\n  \"list\": [\n    1.5,\n    null,\n"
            "    true\n  ],\n  \"empty\": {}\n}\n");
}

TEST(CliSimulate, JsonTextKeepsTheOrderOfMembersAndPrintsBadBytesAsReplacements) {
  cli::JsonReport json;
  json["z"] = std::numeric_limits<double>::infinity();
  json["a"] = std::string("caf\xc3\xa9 \xff.csv");  // UTF-8, then a Latin-1 byte
  json["m"] = cli::jsonOrNull(std::optional<int>());
  json["n"] = cli::jsonOrNull(std::optional<int>(7));
  const std::string text = cli::jsonText(json);
  // Oracle: the text as a reader sees it, parsed back, keys in the order set.
  const nlohmann::ordered_json back = nlohmann::ordered_json::parse(text);
  std::vector<std::string> keys;
  for (const auto& [key, value] : back.items()) keys.push_back(key);
  EXPECT_EQ(keys, (std::vector<std::string>{"z", "a", "m", "n"}));
  EXPECT_TRUE(back["z"].is_null());
  EXPECT_EQ(back["a"], "caf\xc3\xa9 \xef\xbf\xbd.csv");  // U+FFFD for the stray byte
  EXPECT_TRUE(back["m"].is_null());
  EXPECT_EQ(back["n"], 7);
}

}  // namespace
}  // namespace ddfcam::io
