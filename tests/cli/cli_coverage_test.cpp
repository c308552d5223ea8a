// SPDX-License-Identifier: MIT
// Runs ddfcam-cli simulate and compare on results that used to "succeed" silently: a path
// translated off the part, a tool plunged through the crust, a patch over a fraction of a mould.
// Checks the coverage and clamping figures against analytic values, the warnings and --strict.
#include <ddfcam/io/mesh/ddf_file.h>
#include <ddfcam/io/mesh/mesh_io.h>
#include <ddfcam/io/programs/tool_path_csv.h>

#include <gmock/gmock.h>
#include <gtest/gtest.h>
#include <nlohmann/json.hpp>

#include <cmath>
#include <filesystem>
#include <string>
#include <vector>

#include "cli_mould_support.h"
#include "cli_simulate_support.h"

namespace ddfcam::io {
namespace {

using test::CliRun;
using ::testing::HasSubstr;

nlohmann::json readJson(const std::filesystem::path& path) {
  return nlohmann::json::parse(test::readBytes(path));
}

/// The plate (20 x 20 mm, z = 0, vectors +z of length 1) and the straight pass along x.
struct PlateRun {
  test::ScratchDir dir;
  std::filesystem::path part = dir / "plate.ddf", paths = dir / "pass.csv";
  PlateRun() {
    writeDdf(test::plate(), part);
    writeToolPathCsv(test::straightPass(), paths);
  }
  CliRun simulate(std::vector<std::string> extra) const {
    std::vector<std::string> args = {part.string(),
                                     "--paths",
                                     paths.string(),
                                     "-o",
                                     (dir / "out.ddf").string(),
                                     "--report",
                                     (dir / "r.json").string()};
    args.insert(args.end(), extra.begin(), extra.end());
    return test::cli(dir, "simulate", args);
  }
  nlohmann::json report() const { return readJson(dir / "r.json"); }
};

TEST(CliCoverage, StraightPassCoversItsAnalyticStrip) {
  const PlateRun run;
  const CliRun r = run.simulate({"--radius", "5", "--width", "4.1", "--strict"});
  ASSERT_EQ(r.exitCode, 0) << r.out << r.err;
  const nlohmann::json report = run.report();
  const nlohmann::json& d = report["deviation"];
  // The roll comes within 0.1 mm of the plate where |y - 10| <= W / 2 and x is within
  // a = sqrt(2 R r - r^2) of the contacts 2 .. 18; the 0.25 mm raster misplaces up to half a
  // spacing along the 44 mm border.
  const double a = std::sqrt(2.0 * 5.0 * 0.1 - 0.01), strip = (16.0 + 2.0 * a) * 4.1;
  EXPECT_NEAR(d["touched_area_mm2"].get<double>(), strip, 0.125 * 44.0);
  EXPECT_NEAR(d["part_area_mm2"].get<double>(), 400.0, 1e-6);
  EXPECT_NEAR(d["coverage_percent"].get<double>(), 100.0 * strip / 400.0, 100.0 * 5.5 / 400.0);
  EXPECT_EQ(d["clamped_points"].get<int>(), 0);
  EXPECT_EQ(report["run_warnings"].get<int>(), 0);
  EXPECT_THAT(r.out, HasSubstr("coverage: the tool touched"));
}

TEST(CliCoverage, PathTranslatedOffThePartWarnsAndFailsWithStrict) {
  const PlateRun run;
  const CliRun loose = run.simulate({"--translate", "5000,0,0"});
  ASSERT_EQ(loose.exitCode, 0) << loose.err;
  const nlohmann::json report = run.report();
  // Nothing is cut, so every deviation is 0 and "in tolerance", but the tool touched nothing.
  EXPECT_NEAR(report["deviation"]["in_tolerance_percent"].get<double>(), 100.0, 1e-9);
  EXPECT_EQ(report["deviation"]["coverage_percent"].get<double>(), 0.0);
  EXPECT_EQ(report["deviation"]["touched_area_mm2"].get<double>(), 0.0);
  EXPECT_GE(report["run_warnings"].get<int>(), 2);  // off the part, and the coverage
  EXPECT_THAT(loose.err, HasSubstr("warning: the tool touches only 0 % of the part"));
  const CliRun strict = run.simulate({"--translate", "5000,0,0", "--strict"});
  EXPECT_EQ(strict.exitCode, 3) << strict.err;
  EXPECT_THAT(strict.err, HasSubstr("with --strict"));
  EXPECT_TRUE(std::filesystem::exists(run.dir / "out.ddf"));  // outputs are still written
  // A threshold of 0 % accepts the coverage; the placement warning still fails --strict.
  const CliRun zero = run.simulate({"--translate", "5000,0,0", "--strict", "--min-coverage", "0"});
  EXPECT_EQ(zero.exitCode, 3);
  EXPECT_THAT(zero.err, ::testing::Not(HasSubstr("the tool touches only")));
  EXPECT_EQ(run.simulate({"--min-coverage", "120"}).exitCode, 2);
}

TEST(CliCoverage, PlungesThroughTheCrustReportClampedPoints) {
  // Contacts 1.5 mm below the plate, whose crust ends 1 mm below it: a 5 mm and a 0.5 mm roll
  // both show the crust bottom as their minimum; the clamped points say the cut is deeper.
  std::vector<int> clamped;
  for (const char* radius : {"5", "0.5"}) {
    const PlateRun run;
    const CliRun r = run.simulate({"--radius", radius, "--translate", "0,0,-1.5"});
    ASSERT_EQ(r.exitCode, 0) << r.err;
    const nlohmann::json report = run.report();
    const nlohmann::json& d = report["deviation"];
    EXPECT_NEAR(d["min_mm"].get<double>(), -1.0, 1e-5) << radius;
    EXPECT_GT(d["clamped_points"].get<int>(), 0) << radius;
    EXPECT_GT(d["clamped_area_mm2"].get<double>(), 0.0) << radius;
    EXPECT_TRUE(d["min_is_bound"].get<bool>());
    EXPECT_GT(report["heights_clamped"].get<int>(), 0);
    EXPECT_THAT(r.err, HasSubstr("clamped to it: the true overcut there is deeper"));
    EXPECT_EQ(run.simulate({"--radius", radius, "--translate", "0,0,-1.5", "--strict"}).exitCode,
              3);
    clamped.push_back(d["clamped_points"].get<int>());
  }
  EXPECT_GT(clamped[0], clamped[1]);  // the wider roll clamps more points
}

TEST(CliCoverage, ComparePatchCoversAQuarterOfTheMould) {
  test::ScratchDir dir;
  writeMesh(test::flatSheet(), dir / "mould.stl");  // 40 x 10 mm
  writeMesh(
      test::heightFieldMesh(10.0, 20.0, 0.0, 10.0, 20, 20, [](double, double) { return 0.1; }),
      dir / "patch.stl");
  const std::vector<std::string> args = {
      (dir / "mould.stl").string(), (dir / "patch.stl").string(), "--reach", "1", "--json",
      (dir / "c.json").string()};
  const CliRun loose = test::cli(dir, "compare", args);
  ASSERT_EQ(loose.exitCode, 0) << loose.err;
  const nlohmann::json json = readJson(dir / "c.json");
  EXPECT_NEAR(json["statistics"]["within_band_percent"].get<double>(), 100.0, 1e-9);
  // The border at x = 10 and 20 runs along raster points (2 mm cells, m = 4): half a spacing
  // on either side.
  EXPECT_NEAR(json["coverage"]["coverage_percent"].get<double>(), 25.0,
              100.0 * 2.0 * 10.0 * (2.0 / 6.0) / 400.0);
  EXPECT_NEAR(json["coverage"]["mould_area_mm2"].get<double>(), 400.0, 1e-6);
  EXPECT_EQ(json["run_warnings"].get<int>(), 1);
  EXPECT_THAT(loose.err, HasSubstr("warning: the statistics cover only"));
  EXPECT_THAT(loose.out, HasSubstr("coverage:"));
  std::vector<std::string> strict = args;
  strict.push_back("--strict");
  EXPECT_EQ(test::cli(dir, "compare", strict).exitCode, 3);
  strict.insert(strict.end(), {"--min-coverage", "20"});
  EXPECT_EQ(test::cli(dir, "compare", strict).exitCode, 0);
}

}  // namespace
}  // namespace ddfcam::io
