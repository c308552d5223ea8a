// SPDX-License-Identifier: MIT
// Runs ddfcam-cli compensate on a plane target with sinusoidal springback: the linear model's
// alpha^j law and one-step convergence for lambda = 1/(1-alpha), and an imported history.
#include <ddfcam/io/mesh/mesh_io.h>

#include <gmock/gmock.h>
#include <gtest/gtest.h>
#include <nlohmann/json.hpp>

#include <cmath>
#include <filesystem>
#include <numbers>

#include "cli_mould_support.h"
#include "cli_simulate_support.h"

namespace ddfcam::io {
namespace {

using test::CliRun;
using ::testing::HasSubstr;

constexpr double kAmplitude = 0.8;  // mm, springback of the first forming in the flat target

struct Sheets {
  test::ScratchDir dir;
  std::filesystem::path target = dir / "target.stl";
  Sheets() { writeMesh(test::flatSheet(), target); }
  std::filesystem::path formed(double amplitude, const std::string& name) const {
    const std::filesystem::path path = dir / name;
    writeMesh(test::sinusoidSheet(amplitude), path);
    return path;
  }
};

nlohmann::json convergence(const Sheets& s) {
  return nlohmann::json::parse(test::readBytes(s.dir / "c.json"))["iterations"];
}

TEST(CliCompensate, LinearModelFollowsTheAlphaLaw) {
  const Sheets s;
  const double alpha = 0.4;
  const CliRun run =
      test::cli(s.dir, "compensate",
                {s.target.string(), "--model-alpha", "0.4", "--calibrate-from",
                 s.formed(kAmplitude, "f0.stl").string(), "--iterations", "3", "--resolution", "5",
                 "--out-dir", (s.dir / "moulds").string(), "--json", (s.dir / "c.json").string()});
  ASSERT_EQ(run.exitCode, 0) << run.err;
  const nlohmann::json it = convergence(s);
  ASSERT_EQ(it.size(), 4u);
  const double max0 = it[0]["max_mm"].get<double>();
  EXPECT_NEAR(max0, kAmplitude, 0.01);
  // With lambda = 1 every step leaves alpha of the deviation (alpha^(j+1) |T - P|, and the
  // first forming is alpha |T - P|).
  for (int j = 1; j < 4; ++j) {
    EXPECT_NEAR(it[j]["max_mm"].get<double>() / max0, std::pow(alpha, j), 1e-3) << j;
    EXPECT_NEAR(it[j]["rms_mm"].get<double>() / it[0]["rms_mm"].get<double>(), std::pow(alpha, j),
                1e-3)
        << j;
  }
  for (int j = 0; j < 4; ++j)
    EXPECT_TRUE(
        std::filesystem::exists(s.dir / "moulds" / ("mould_" + std::to_string(j) + ".stl")));
  // The first corrected mould bends the other way: z = -A sin at its vertices.
  const ddf::TriangleMesh mould1 = readMesh(s.dir / "moulds" / "mould_1.stl");
  for (const Eigen::Vector3d& v : mould1.vertices)
    EXPECT_NEAR(v.z(), -kAmplitude * std::sin(2.0 * std::numbers::pi * v.x() / test::kWavelength),
                0.01);
}

// Oracle: on the flat target the stubbles and every deviation are vertical, so of the per-axis
// shares only the z share acts, and the model must follow that share's alpha law (up to the
// resampling of the formed points onto the stubbles).
TEST(CliCompensate, PerAxisModelActsThroughTheShareAlongTheDeviation) {
  const Sheets s;
  const CliRun run = test::cli(
      s.dir, "compensate",
      {s.target.string(), "--model-alpha", "0.3", "--model-axes", "0.1,0.2,0.5", "--calibrate-from",
       s.formed(kAmplitude, "f0.stl").string(), "--iterations", "2", "--resolution", "5",
       "--out-dir", (s.dir / "m").string(), "--json", (s.dir / "c.json").string()});
  ASSERT_EQ(run.exitCode, 0) << run.err;
  const nlohmann::json it = convergence(s);
  ASSERT_EQ(it.size(), 3u);
  // P is calibrated with alpha = 0.3 (P - T = s_0 / 0.3); the model then forms every mould,
  // the target included, with the z share 0.5: s_0' = 0.5 (P - T), and each step halves it.
  const double rms0 = it[0]["rms_mm"].get<double>();
  EXPECT_NEAR(rms0, 0.5 / 0.3 * kAmplitude / std::sqrt(2.0), 0.02 * rms0);
  EXPECT_NEAR(it[1]["rms_mm"].get<double>() / rms0, 0.5, 0.01);
  EXPECT_NEAR(it[2]["rms_mm"].get<double>() / it[1]["rms_mm"].get<double>(), 0.5, 0.01);
}

TEST(CliCompensate, LambdaOneOverOneMinusAlphaConvergesInOneStep) {
  const Sheets s;
  const CliRun run = test::cli(s.dir, "compensate",
                               {s.target.string(), "--model-alpha", "0.5", "--calibrate-from",
                                s.formed(kAmplitude, "f0.stl").string(), "--iterations", "1",
                                "--lambda", "2", "--resolution", "5", "--out-dir",
                                (s.dir / "m").string(), "--json", (s.dir / "c.json").string()});
  ASSERT_EQ(run.exitCode, 0) << run.err;
  const nlohmann::json it = convergence(s);
  ASSERT_EQ(it.size(), 2u);
  EXPECT_EQ(it[1]["lambda"].get<double>(), 2.0);
  EXPECT_LT(it[1]["max_mm"].get<double>(), 1e-4 * it[0]["max_mm"].get<double>());
}

TEST(CliCompensate, ImportedFormingsMakeTheHistory) {
  const Sheets s;
  const CliRun run =
      test::cli(s.dir, "compensate",
                {s.target.string(), "--formed", s.formed(kAmplitude, "f0.stl").string(),
                 s.formed(0.5 * kAmplitude, "f1.stl").string(), "--lambda", "0.5", "--resolution",
                 "5", "--out-dir", (s.dir / "m").string(), "--json", (s.dir / "c.json").string()});
  ASSERT_EQ(run.exitCode, 0) << run.err;
  const nlohmann::json it = convergence(s);
  ASSERT_EQ(it.size(), 3u);  // two formings, the mould planned from the second
  EXPECT_NEAR(it[0]["max_mm"].get<double>(), kAmplitude, 0.01);
  EXPECT_NEAR(it[1]["max_mm"].get<double>(), 0.5 * kAmplitude, 0.01);
  EXPECT_TRUE(it[2]["max_mm"].is_null());  // not formed yet
  EXPECT_EQ(it[0]["formed"].get<std::string>(), "f0.stl");
  // mould_2 = -0.5 A sin - 0.5 (0.5 A sin) = -0.75 A sin.
  const ddf::TriangleMesh mould2 = readMesh(s.dir / "m" / "mould_2.stl");
  for (const Eigen::Vector3d& v : mould2.vertices)
    EXPECT_NEAR(v.z(),
                -0.75 * kAmplitude * std::sin(2.0 * std::numbers::pi * v.x() / test::kWavelength),
                0.01);
}

TEST(CliCompensate, UsageErrors) {
  const Sheets s;
  CliRun run = test::cli(s.dir, "compensate", {s.target.string()});
  EXPECT_NE(run.exitCode, 0);
  EXPECT_THAT(run.err, HasSubstr("either --formed files or --model-alpha"));
  run = test::cli(s.dir, "compensate", {s.target.string(), "--model-alpha", "0.3"});
  EXPECT_NE(run.exitCode, 0);
  EXPECT_THAT(run.err, HasSubstr("--calibrate-from"));
}

}  // namespace
}  // namespace ddfcam::io
