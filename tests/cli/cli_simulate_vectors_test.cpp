// SPDX-License-Identifier: MIT
// Runs ddfcam-cli simulate on a robot path (x,y,z,i,j,k, vectors into the part): --vectors
// and --points, what auto detects, the gouge warning, and report figures that agree.
#include <ddfcam/io/mesh/ddf_file.h>

#include <gmock/gmock.h>
#include <gtest/gtest.h>

#include <cmath>
#include <fstream>
#include <string>

#include "cli_simulate_support.h"

namespace ddfcam::io {
namespace {

using test::cli;
using test::CliRun;
using test::jsonNumber;
using ::testing::HasSubstr;

/// A robot pass on the plate (z = 0) along x at y = 10: contacts, approach vectors (0, 0, -1).
void writeRobotPass(const std::filesystem::path& file) {
  std::ofstream out(file);
  for (int i = 0; i <= 20; ++i) out << 4.0 + 0.6 * i << ",10,0,0,0,-1\n";
}

/// The string value after "key": in @p json; empty if absent.
std::string jsonText(const std::string& json, const std::string& key) {
  const std::size_t at = json.find("\"" + key + "\": \"");
  if (at == std::string::npos) return {};
  const std::size_t start = at + key.size() + 5;
  return json.substr(start, json.find('"', start) - start);
}

struct Simulated {
  CliRun run;
  std::string json;
};

Simulated simulate(const test::ScratchDir& dir, const std::vector<std::string>& extra) {
  std::vector<std::string> args = {(dir / "plate.ddf").string(),
                                   "--paths",
                                   (dir / "robot.csv").string(),
                                   "--tool",
                                   "ball_end",
                                   "--radius",
                                   "2",
                                   "--allowance",
                                   "0.1",
                                   "--no-vconvexity-check",
                                   "-o",
                                   (dir / "out.ddf").string(),
                                   "--report",
                                   (dir / "r.json").string()};
  args.insert(args.end(), extra.begin(), extra.end());
  Simulated s{cli(dir, "simulate", args), {}};
  s.json = test::readBytes(dir / "r.json");
  return s;
}

TEST(CliSimulateVectors, RobotApproachVectorsAreDetectedAndTheReportAgrees) {
  test::ScratchDir dir;
  writeDdf(test::plate(), dir / "plate.ddf");
  writeRobotPass(dir / "robot.csv");
  const Simulated detected = simulate(dir, {});
  ASSERT_EQ(detected.run.exitCode, 0) << detected.run.err;
  const std::string& a = detected.json;
  EXPECT_EQ(jsonText(a, "vectors"), "approach") << a;
  EXPECT_EQ(jsonText(a, "points"), "tip") << a;
  EXPECT_THAT(jsonText(a, "convention"), HasSubstr("into the part at 21 of 21")) << a;
  EXPECT_EQ(jsonNumber(a, "gouging_poses"), 0.0) << a;
  EXPECT_EQ(jsonNumber(a, "points_off_part"), 0.0) << a;
  EXPECT_EQ(jsonNumber(a, "points_on_part"), 21.0) << a;
  EXPECT_LT(jsonNumber(a, "max_contact_distance_mm"), 1e-6) << a;
  EXPECT_EQ(jsonNumber(a, "max_contact_distance_on_part_mm"),
            jsonNumber(a, "max_contact_distance_mm"))
      << a;
  EXPECT_THAT(detected.run.out, HasSubstr("approach directions (detected"));
  EXPECT_EQ(detected.run.err.find("gouge"), std::string::npos) << detected.run.err;

  // Read as tool axes (the behaviour of the issue): the ball 2 R deep, warned as gouging, and
  // the off-part count and the largest distance tell the same story.
  const Simulated axes = simulate(dir, {"--vectors", "axis"});
  ASSERT_EQ(axes.run.exitCode, 0) << axes.run.err;
  const std::string& b = axes.json;
  EXPECT_EQ(jsonText(b, "vectors"), "axis") << b;
  EXPECT_EQ(jsonNumber(b, "gouging_poses"), 21.0) << b;
  EXPECT_NEAR(jsonNumber(b, "max_gouge_depth_mm"), 4.0, 1e-6) << b;
  EXPECT_EQ(jsonNumber(b, "points_off_part"), 21.0) << b;
  EXPECT_NEAR(jsonNumber(b, "max_contact_distance_mm"), 4.0, 1e-6) << b;
  EXPECT_NE(b.find("\"max_contact_distance_on_part_mm\": null"), std::string::npos) << b;
  EXPECT_THAT(axes.run.err, HasSubstr("21 of 21 poses gouge the part"));
  EXPECT_THAT(axes.run.err, HasSubstr("as approach directions do"));

  // --points contact: a contact program, the ball touching at each point.
  const Simulated contacts = simulate(dir, {"--vectors", "approach", "--points", "contact"});
  ASSERT_EQ(contacts.run.exitCode, 0) << contacts.run.err;
  EXPECT_EQ(jsonText(contacts.json, "points"), "contact") << contacts.json;
  EXPECT_LT(jsonNumber(contacts.json, "max_contact_distance_mm"), 1e-6) << contacts.json;
}

TEST(CliSimulateVectors, BadMeaningsAndHelp) {
  test::ScratchDir dir;
  writeDdf(test::plate(), dir / "plate.ddf");
  writeRobotPass(dir / "robot.csv");
  const Simulated bad = simulate(dir, {"--vectors", "inwards"});
  EXPECT_EQ(bad.run.exitCode, 2);
  EXPECT_THAT(bad.run.err, HasSubstr("axis|approach|normal|auto"));
  EXPECT_EQ(simulate(dir, {"--points", "centre"}).run.exitCode, 2);
  const CliRun help = cli(dir, "simulate", {"--help"});
  EXPECT_EQ(help.exitCode, 0);
  EXPECT_THAT(help.out, HasSubstr("--vectors axis|approach|normal|auto"));
  EXPECT_THAT(help.out, HasSubstr("--points contact|tip|file|auto"));
}

}  // namespace
}  // namespace ddfcam::io
