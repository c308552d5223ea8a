// SPDX-License-Identifier: MIT
// ddfcam: written G-code run through LinuxCNC's stand-alone RS274NGC interpreter as oracle.
#include <ddfcam/io/programs/gcode_writer.h>

#include <gtest/gtest.h>

#include <array>
#include <cmath>
#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <numbers>
#include <sstream>

#include "rs274_run.h"

namespace ddfcam::io {
namespace {

namespace fs = std::filesystem;
constexpr double kPi = std::numbers::pi;
using test::kRs274Path;
using test::Rs274Run;
using test::runRs274;

using Axes = std::array<double, 6>;  ///< X Y Z A B C

/// End points of STRAIGHT_TRAVERSE / STRAIGHT_FEED canonical calls, in order.
std::vector<Axes> canonicalMoves(const std::string& out) {
  std::vector<Axes> moves;
  std::istringstream in(out);
  for (std::string line; std::getline(in, line);) {
    const std::size_t call = line.find("STRAIGHT_");
    if (call == std::string::npos) continue;
    std::string args = line.substr(line.find('(', call) + 1);
    for (char& c : args) c = c == ',' || c == ')' ? ' ' : c;
    std::istringstream values(args);
    Axes a{};
    for (double& v : a) values >> v;
    EXPECT_FALSE(values.fail()) << line;
    moves.push_back(a);
  }
  return moves;
}

/// End points of the written motion blocks (modal X Y Z A B C), by a word reader of its own.
std::vector<Axes> writtenMoves(const std::string& text) {
  std::vector<Axes> moves;
  Axes state{};
  std::istringstream in(text);
  for (std::string line; std::getline(in, line);) {
    if (line.empty() || line[0] == '%' || line.find('(') != std::string::npos) continue;
    std::istringstream words(line);
    bool motion = false;
    for (std::string w; words >> w;) {
      const std::size_t axis = std::string("XYZABC").find(w[0]);
      if (axis == std::string::npos) continue;
      state[axis] = std::stod(w.substr(1));
      motion = true;
    }
    if (motion) moves.push_back(state);
  }
  return moves;
}

void expectSameMoves(const std::vector<Axes>& canonical, const std::vector<Axes>& written) {
  ASSERT_EQ(canonical.size(), written.size());
  for (std::size_t i = 0; i < canonical.size(); ++i) {
    for (int k = 0; k < 6; ++k) {
      // rs274 prints 4 decimals; the program is written with 4 too.
      EXPECT_NEAR(canonical[i][k], written[i][k], 1.01e-4) << "move " << i << " axis " << k;
    }
  }
}

planning::ClProgram sphereProgram(int count, bool withAxes) {
  planning::ClProgram program;
  program.partName = "rs274 check (sphere)";
  program.pointKind =
      withAxes ? planning::ClPointKind::ToolReference : planning::ClPointKind::Contact;
  program.coolant = true;
  for (int i = 0; i < count; ++i) {
    const double s = static_cast<double>(i) / (count - 1);
    const double tilt = (withAxes ? 100.0 : 75.0) * kPi / 180.0 * s;
    const ddf::Vec3 n(std::sin(tilt) * std::cos(8 * kPi * s),
                      std::sin(tilt) * std::sin(8 * kPi * s), std::cos(tilt));
    planning::ClPoint p;
    p.point = i;
    p.positionMm = ddf::Vec3(4.0, -7.0, -25.0) + 30.0 * n;
    p.normal = n;
    if (withAxes) p.axis = n;
    p.feedMmPerMin = i % 50 < 45 ? 1200.0 : 0.0;
    p.move = i % 100 == 60 ? planning::MoveKind::Rapid : planning::MoveKind::Cut;
    program.points.push_back(p);
  }
  return program;
}

const planning::Tool kBall{
    .name = "ball 6", .kind = planning::ToolKind::BallEnd, .radiusMm = 3.0, .widthMm = 12.0};

#define DDFCAM_REQUIRE_RS274()                                                          \
  if (!fs::exists(kRs274Path)) {                                                        \
    GTEST_SKIP() << "rs274 (Debian package linuxcnc-uspace) not installed: the G-code " \
                    "is not checked by an independent interpreter";                     \
  }

TEST(GCodeRs274, ThreeAxisProgramIsAcceptedAndMovesAsWritten) {
  DDFCAM_REQUIRE_RS274();
  const planning::ClProgram program = sphereProgram(300, false);
  const std::string text = encodeGCode(program, kBall, {});
  const Rs274Run run = runRs274(text);
  EXPECT_EQ(run.exitCode, 0);
  EXPECT_EQ(run.errors, "");
  const std::vector<Axes> canonical = canonicalMoves(run.out);
  expectSameMoves(canonical, writtenMoves(text));
  // And against the geometry: the ball's centre is 33 mm from the sphere's centre.
  ASSERT_EQ(canonical.size(), program.points.size() + 3);
  for (std::size_t i = 0; i < program.points.size(); ++i) {
    const Axes& a = canonical[i + 2];
    const ddf::Vec3 centre(a[0], a[1], a[2] + 3.0);
    EXPECT_NEAR((centre - ddf::Vec3(4.0, -7.0, -25.0)).norm(), 33.0, 2e-4) << i;
  }
}

class GCodeRs274FiveAxis : public ::testing::TestWithParam<planning::RotaryPair> {};

TEST_P(GCodeRs274FiveAxis, ProgramIsAcceptedAndMovesAsWritten) {
  DDFCAM_REQUIRE_RS274();
  GCodeWriteParams params;
  params.mode = GCodeWriteParams::Mode::FiveAxis;
  params.kinematics.pair = GetParam();
  params.kinematics.pivotMm = {10.0, 0.0, -80.0};
  params.kinematics.rotaryOffsetMm = {0.0, 4.0, 0.0};
  params.lineNumbers = true;
  const std::string text = encodeGCode(sphereProgram(300, true), kBall, params);
  const Rs274Run run = runRs274(text);
  EXPECT_EQ(run.exitCode, 0);
  EXPECT_EQ(run.errors, "");
  const std::vector<Axes> canonical = canonicalMoves(run.out);
  expectSameMoves(canonical, writtenMoves(text));
  // The tilt appears on A or B only, as the pair says, and reaches 100 degrees.
  const int tilt = GetParam() == planning::RotaryPair::AC ? 3 : 4;
  double largest = 0.0;
  for (const Axes& a : canonical) {
    EXPECT_EQ(a[7 - tilt], 0.0);  // the other of A / B
    largest = std::max(largest, std::abs(a[tilt]));
  }
  EXPECT_NEAR(largest, 100.0, 1e-3);
}

TEST_P(GCodeRs274FiveAxis, InverseTimeProgramIsAccepted) {
  DDFCAM_REQUIRE_RS274();
  GCodeWriteParams params;
  params.mode = GCodeWriteParams::Mode::FiveAxis;
  params.kinematics.pair = GetParam();
  params.inverseTimeFeed = true;
  const std::string text = encodeGCode(sphereProgram(300, true), kBall, params);
  const Rs274Run run = runRs274(text);
  EXPECT_EQ(run.exitCode, 0);
  EXPECT_EQ(run.errors, "");
  EXPECT_NE(run.out.find("feed mode set to inverse time"), std::string::npos);
  expectSameMoves(canonicalMoves(run.out), writtenMoves(text));
}

INSTANTIATE_TEST_SUITE_P(Pairs, GCodeRs274FiveAxis,
                         ::testing::Values(planning::RotaryPair::AC, planning::RotaryPair::BC),
                         [](const auto& info) {
                           return std::string(info.param == planning::RotaryPair::AC ? "AC" : "BC");
                         });

TEST(GCodeRs274, InterpreterRejectsABadLine) {
  DDFCAM_REQUIRE_RS274();
  // Proves the check above can fail: a Q word without a canned cycle is an error in RS274NGC.
  std::string text = encodeGCode(sphereProgram(20, false), kBall, {});
  text.insert(text.find("M5 M9"), "G1 X0 Y0 Z40 Q5\n");
  const Rs274Run run = runRs274(text);
  EXPECT_TRUE(run.exitCode != 0 || !run.errors.empty());
  EXPECT_NE(run.errors.find("Q word"), std::string::npos) << run.errors;
}

}  // namespace
}  // namespace ddfcam::io
