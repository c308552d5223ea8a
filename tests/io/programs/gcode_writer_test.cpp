// SPDX-License-Identifier: MIT
// ddfcam: G-code writer checked by a small independent parser against analytic tool placement.
#include <ddfcam/error.h>
#include <ddfcam/io/programs/gcode_writer.h>

#include <gmock/gmock.h>
#include <gtest/gtest.h>

#include <cmath>
#include <filesystem>
#include <fstream>
#include <map>
#include <numbers>
#include <optional>
#include <sstream>
#include <vector>

namespace ddfcam::io {
namespace {

constexpr double kPi = std::numbers::pi;
using Mode = GCodeWriteParams::Mode;

/// One motion block as an independent reader sees it: G word and modal axis values.
struct Motion {
  int g = -1;
  std::map<char, double> axes;  ///< X Y Z A B C after the block (modal)
  bool hasFeed = false;
  double feed = 0.0;
};

/// Parses RS274 text: comments and N words dropped, words letter + number. Motion blocks are
/// those with an axis word; every one must carry G0 or G1 (checked here).
std::vector<Motion> parseMotions(const std::string& text) {
  std::vector<Motion> motions;
  std::map<char, double> state{{'X', 0}, {'Y', 0}, {'Z', 0}, {'A', 0}, {'B', 0}, {'C', 0}};
  std::istringstream in(text);
  std::string line;
  while (std::getline(in, line)) {
    std::string clean;
    bool inComment = false;
    for (char c : line) {
      if (c == '(') inComment = true;
      if (!inComment && c != ' ') clean += c;
      if (c == ')') inComment = false;
    }
    if (clean == "%") continue;
    Motion m;
    bool motion = false;
    for (std::size_t i = 0; i < clean.size();) {
      const char letter = clean[i];
      // The number runs to the next letter (std::stod alone would read "0X1" as hex).
      const std::size_t end = clean.find_first_not_of("0123456789.+-", i + 1);
      const std::string number = clean.substr(i + 1, end == std::string::npos ? end : end - i - 1);
      const double value = std::stod(number);
      i = end == std::string::npos ? clean.size() : end;
      if (letter == 'G' && (value == 0.0 || value == 1.0)) m.g = static_cast<int>(value);
      if (std::string("XYZABC").find(letter) != std::string::npos) {
        state[letter] = value;
        motion = true;
      }
      if (letter == 'F') m.hasFeed = true, m.feed = value;
    }
    if (!motion) continue;
    EXPECT_NE(m.g, -1) << "motion line without G0/G1: " << line;
    m.axes = state;
    motions.push_back(m);
  }
  return motions;
}

ddf::Vec3 unitFromAngles(double tiltRad, double azimuthRad) {
  return {std::sin(tiltRad) * std::cos(azimuthRad), std::sin(tiltRad) * std::sin(azimuthRad),
          std::cos(tiltRad)};
}

/// Contact points on the upper part of a sphere (centre @p centre, radius @p radius), normals
/// outwards, as a one-path program.
planning::ClProgram sphereContacts(const ddf::Vec3& centre, double radius, int count) {
  planning::ClProgram program;
  program.pointKind = planning::ClPointKind::Contact;
  for (int i = 0; i < count; ++i) {
    const ddf::Vec3 n = unitFromAngles(1.3 * i / count, 0.37 * i);
    planning::ClPoint p;
    p.point = i;
    p.positionMm = centre + radius * n;
    p.normal = n;
    p.feedMmPerMin = 800.0;
    program.points.push_back(p);
  }
  return program;
}

planning::Tool cutter(planning::ToolKind kind, double radius, double edge = 0.0) {
  return planning::Tool{.name = "test cutter",
                        .kind = kind,
                        .radiusMm = radius,
                        .widthMm = 20.0,
                        .edgeRadiusMm = edge};
}

ddf::Vec3 xyz(const Motion& m) {
  return {m.axes.at('X'), m.axes.at('Y'), m.axes.at('Z')};
}

/// The program's lines, excluding the two safe-plane rapids at the start and the retract.
std::vector<Motion> pointMotions(const std::string& text, std::size_t count) {
  std::vector<Motion> all = parseMotions(text);
  EXPECT_EQ(all.size(), count + 3);
  return {all.begin() + 2, all.end() - 1};
}

TEST(GCodeWriter, ThreeAxisBallTipIsSphereOffsetMinusRadius) {
  const ddf::Vec3 centre(10.0, -5.0, -20.0);
  const double sphere = 30.0, ball = 3.0;
  const planning::ClProgram program = sphereContacts(centre, sphere, 200);
  const std::string text = encodeGCode(program, cutter(planning::ToolKind::BallEnd, ball), {});
  const std::vector<Motion> motions = pointMotions(text, 200);
  for (std::size_t i = 0; i < motions.size(); ++i) {
    // The ball's centre lies on the normal at sphere + ball from the sphere's centre.
    const ddf::Vec3 expected =
        centre + (sphere + ball) * *program.points[i].normal - ball * ddf::Vec3::UnitZ();
    EXPECT_LT((xyz(motions[i]) - expected).cwiseAbs().maxCoeff(), 0.51e-4) << i;
    EXPECT_EQ(motions[i].g, 1);
  }
  EXPECT_TRUE(motions.front().hasFeed);
  EXPECT_DOUBLE_EQ(motions.front().feed, 800.0);
  EXPECT_THAT(text, ::testing::HasSubstr("G17 G21 G40 G49 G80 G90 G94\n"));
  EXPECT_THAT(text, ::testing::HasSubstr("T1 M6\n"));
  EXPECT_THAT(text, ::testing::HasSubstr("S6000.0 M3\n"));
  EXPECT_THAT(text, ::testing::EndsWith("M5 M9\nM30\n%\n"));
}

TEST(GCodeWriter, ThreeAxisFlatAndTorusTouchTheSurface) {
  const ddf::Vec3 centre(0.0, 0.0, -40.0);
  const double sphere = 40.0;
  const planning::ClProgram program = sphereContacts(centre, sphere, 60);
  for (const planning::Tool& tool : {cutter(planning::ToolKind::FlatEnd, 5.0),
                                     cutter(planning::ToolKind::TorusCutter, 6.0, 2.0)}) {
    const std::vector<Motion> motions = pointMotions(encodeGCode(program, tool, {}), 60);
    const double r = tool.edgeRadiusMm, ring = tool.radiusMm - r;
    for (std::size_t i = 0; i < motions.size(); ++i) {
      // Oracle: the set of corner-circle centres is the filled disc of radius ring at height
      // r above the tip (for a flat end, the bottom face); its nearest point to the sphere's
      // centre must lie at sphere + r (touching, not gouging).
      const ddf::Vec3 disc = xyz(motions[i]) + ddf::Vec3(0.0, 0.0, r);
      const ddf::Vec3 d(centre.x() - disc.x(), centre.y() - disc.y(), 0.0);
      const ddf::Vec3 closest =
          d.norm() <= ring ? ddf::Vec3(disc + d) : ddf::Vec3(disc + ring * d.normalized());
      const double nearest = (closest - centre).norm();
      EXPECT_NEAR(nearest, sphere + r, 1e-4) << tool.name << " " << i;
    }
  }
}

TEST(GCodeWriter, EveryMotionLineHasItsGWordAndRapidsHaveNoFeed) {
  planning::ClProgram program = sphereContacts({0, 0, 0}, 20.0, 30);
  program.pointKind = planning::ClPointKind::ToolReference;
  for (int i = 10; i < 15; ++i) program.points[i].move = planning::MoveKind::Rapid;
  program.points[20].move = planning::MoveKind::Link;
  program.points[20].feedMmPerMin = 0.0;  // falls back to defaultFeedMmPerMin
  GCodeWriteParams params;
  params.lineNumbers = true;
  const std::string text = encodeGCode(program, cutter(planning::ToolKind::BallEnd, 2.0), params);
  const std::vector<Motion> motions = pointMotions(text, 30);
  for (std::size_t i = 0; i < motions.size(); ++i) {
    const bool rapid = i >= 10 && i < 15;
    EXPECT_EQ(motions[i].g, rapid ? 0 : 1) << i;
    if (rapid) {
      EXPECT_FALSE(motions[i].hasFeed);
    }
    EXPECT_LT((xyz(motions[i]) - program.points[i].positionMm).norm(), 1e-4);
  }
  EXPECT_TRUE(motions[20].hasFeed);
  EXPECT_DOUBLE_EQ(motions[20].feed, 1000.0);
  EXPECT_TRUE(motions[21].hasFeed);  // back to 800
  EXPECT_THAT(text, ::testing::HasSubstr("\nN10 (ddfcam G-code, 3-axis)\n"));
}

TEST(GCodeWriter, InchProgramScalesPositionsAndFeeds) {
  planning::ClProgram program = sphereContacts({0, 0, 0}, 25.4, 5);
  program.pointKind = planning::ClPointKind::ToolReference;
  GCodeWriteParams params;
  params.unit = LengthUnit::Inch;
  params.decimals = 6;
  const std::string text = encodeGCode(program, cutter(planning::ToolKind::BallEnd, 2.0), params);
  EXPECT_THAT(text, ::testing::HasSubstr("G17 G20 G40"));
  const std::vector<Motion> motions = pointMotions(text, 5);
  for (std::size_t i = 0; i < motions.size(); ++i) {
    EXPECT_LT((xyz(motions[i]) - *program.points[i].normal).norm(), 2e-6);
  }
  EXPECT_NEAR(motions.front().feed, 800.0 / 25.4, 1e-6);
}

/// Oracle forward kinematics written out with explicit rotations (see machine_kinematics.h).
std::pair<ddf::Vec3, ddf::Vec3> partPose(const planning::TableKinematics& k, const Motion& m) {
  const bool ac = k.pair == planning::RotaryPair::AC;
  const double t = (ac ? m.axes.at('A') : m.axes.at('B')) * kPi / 180.0;
  const double c = m.axes.at('C') * kPi / 180.0;
  Eigen::Matrix3d rz, tilt;
  rz << std::cos(c), -std::sin(c), 0, std::sin(c), std::cos(c), 0, 0, 0, 1;
  if (ac) {
    tilt << 1, 0, 0, 0, std::cos(t), -std::sin(t), 0, std::sin(t), std::cos(t);
  } else {
    tilt << std::cos(t), 0, std::sin(t), 0, 1, 0, -std::sin(t), 0, std::cos(t);
  }
  const ddf::Vec3 q = k.pivotMm + k.rotaryOffsetMm;
  const ddf::Vec3 untilted = tilt.transpose() * (xyz(m) - k.pivotMm) + k.pivotMm;
  return {rz.transpose() * (untilted - q) + q,
          rz.transpose() * tilt.transpose() * ddf::Vec3::UnitZ()};
}

/// Tool-reference program: a spiral of tips on a dome with axes tilting from 0 to 80 degrees
/// while turning three times around Z.
planning::ClProgram spiralProgram(int count) {
  planning::ClProgram program;
  for (int i = 0; i < count; ++i) {
    const double s = static_cast<double>(i) / (count - 1);
    planning::ClPoint p;
    p.point = i;
    p.axis = unitFromAngles(80.0 * kPi / 180.0 * s, 6.0 * kPi * s);
    p.positionMm = ddf::Vec3(3.0, -2.0, 15.0) + 35.0 * *p.axis;
    p.feedMmPerMin = 1500.0;
    program.points.push_back(p);
  }
  return program;
}

TEST(GCodeWriter, FiveAxisLinesMapBackToTipAndAxis) {
  for (planning::RotaryPair pair : {planning::RotaryPair::AC, planning::RotaryPair::BC}) {
    GCodeWriteParams params;
    params.mode = Mode::FiveAxis;
    params.kinematics.pair = pair;
    params.kinematics.pivotMm = {0.0, 0.0, -100.0};
    params.kinematics.rotaryOffsetMm = {5.0, -3.0, 0.0};
    params.decimals = 6;
    params.angleDecimals = 6;
    const planning::ClProgram program = spiralProgram(400);
    const std::string text = encodeGCode(program, cutter(planning::ToolKind::BallEnd, 4.0), params);
    EXPECT_THAT(text, ::testing::HasSubstr(pair == planning::RotaryPair::AC ? " A" : " B"));
    const std::vector<Motion> motions = pointMotions(text, 400);
    for (std::size_t i = 0; i < motions.size(); ++i) {
      const auto [tip, axis] = partPose(params.kinematics, motions[i]);
      EXPECT_LT((tip - program.points[i].positionMm).norm(), 1e-5) << i;
      EXPECT_LT((axis - *program.points[i].axis).norm(), 1e-7) << i;
      if (i > 0) {
        EXPECT_LT(std::abs(motions[i].axes.at('C') - motions[i - 1].axes.at('C')), 180);
      }
    }
  }
}

TEST(GCodeWriter, InverseTimeFeedIsFeedOverTipDistance) {
  GCodeWriteParams params;
  params.mode = Mode::FiveAxis;
  params.inverseTimeFeed = true;
  params.decimals = 6;
  params.angleDecimals = 6;
  const planning::ClProgram program = spiralProgram(200);
  const std::string text = encodeGCode(program, cutter(planning::ToolKind::BallEnd, 4.0), params);
  EXPECT_THAT(text, ::testing::HasSubstr(" G90 G93\n"));
  const std::vector<Motion> motions = pointMotions(text, 200);
  for (std::size_t i = 1; i < motions.size(); ++i) {
    ASSERT_TRUE(motions[i].hasFeed) << i;  // G93 needs F on every G1
    const double distance =
        (program.points[i].positionMm - program.points[i - 1].positionMm).norm();
    EXPECT_NEAR(motions[i].feed, 1500.0 / distance, 1e-6 * motions[i].feed + 1e-6) << i;
  }
}

TEST(GCodeWriter, FiveAxisContactBallWithAxisAlongNormalTipsAtTheContact) {
  planning::ClProgram program = sphereContacts({0, 0, 0}, 30.0, 50);
  for (planning::ClPoint& p : program.points) p.axis = p.normal;
  GCodeWriteParams params;
  params.mode = Mode::FiveAxis;
  const std::string text = encodeGCode(program, cutter(planning::ToolKind::BallEnd, 3.0), params);
  const std::vector<Motion> motions = pointMotions(text, 50);
  for (std::size_t i = 0; i < motions.size(); ++i) {
    EXPECT_LT((partPose(params.kinematics, motions[i]).first - program.points[i].positionMm).norm(),
              5e-4);
  }
}

TEST(GCodeWriter, FiveAxisTiltedFlatAndTorusTouchAPlane) {
  // A plane n . x = n . c, cut with the axis leaning 10 degrees from the normal. Support
  // function of the cutter along -n: the tip's height minus R |n across a| (flat end), or
  // n . tip + r n . a - (R - r) |n across a| - r (torus); it must equal the plane's offset.
  const ddf::Vec3 n = unitFromAngles(0.5, 1.0);
  planning::ClProgram program;
  program.pointKind = planning::ClPointKind::Contact;
  for (int i = 0; i < 40; ++i) {
    planning::ClPoint p;
    p.point = i;
    p.positionMm = ddf::Vec3(i - 20.0, 0.5 * i, 0.0);
    p.positionMm.z() = -(n.x() * p.positionMm.x() + n.y() * p.positionMm.y()) / n.z();
    p.normal = n;
    p.axis = (n + std::tan(10.0 * kPi / 180.0) * unitFromAngles(0.5 + kPi / 2, 1.0 + 0.05 * i))
                 .normalized();
    program.points.push_back(p);
  }
  GCodeWriteParams params;
  params.mode = Mode::FiveAxis;
  params.decimals = 6;
  params.angleDecimals = 6;
  for (const planning::Tool& tool : {cutter(planning::ToolKind::FlatEnd, 5.0),
                                     cutter(planning::ToolKind::TorusCutter, 6.0, 2.0)}) {
    const std::vector<Motion> motions = pointMotions(encodeGCode(program, tool, params), 40);
    const double r = tool.edgeRadiusMm, ring = tool.radiusMm - r;
    for (std::size_t i = 0; i < motions.size(); ++i) {
      const auto [tip, axis] = partPose(params.kinematics, motions[i]);
      const double across = (n - n.dot(axis) * axis).norm();
      const double lowest = n.dot(tip) + r * n.dot(axis) - ring * across - r;
      EXPECT_NEAR(lowest, 0.0, 1e-5) << tool.name << " " << i;
      EXPECT_GT(across, 0.1);  // the lean is real
    }
  }
}

TEST(GCodeWriter, RefusesWhatItCannotWrite) {
  const planning::Tool ball = cutter(planning::ToolKind::BallEnd, 3.0);
  planning::ClProgram program = sphereContacts({0, 0, 0}, 30.0, 10);
  program.points[4].sourceLine = 77;
  planning::ClProgram tilted = program;
  tilted.points[4].axis = ddf::Vec3(0.0, std::sin(0.1), std::cos(0.1));
  EXPECT_THAT([&] { encodeGCode(tilted, ball, {}); },
              ::testing::ThrowsMessage<InvalidInput>(::testing::HasSubstr("point 4")));
  EXPECT_THAT([&] { encodeGCode(tilted, ball, {}); },
              ::testing::ThrowsMessage<InvalidInput>(::testing::HasSubstr("line 77")));
  planning::ClProgram noNormal = program;
  noNormal.points[3].normal.reset();
  EXPECT_THROW(encodeGCode(noNormal, ball, {}), InvalidInput);
  planning::ClProgram nan = program;
  nan.points[2].positionMm.x() = NAN;
  EXPECT_THROW(encodeGCode(nan, ball, {}), InvalidInput);
  planning::ClProgram infFeed = program;
  infFeed.points[2].feedMmPerMin = INFINITY;
  EXPECT_THROW(encodeGCode(infFeed, ball, {}), InvalidInput);
  EXPECT_THROW(encodeGCode(program, planning::Tool{}, {}), InvalidInput);  // a roll
  GCodeWriteParams metre;
  metre.unit = LengthUnit::Metre;
  EXPECT_THROW(encodeGCode(program, ball, metre), InvalidInput);
  GCodeWriteParams limited;
  limited.mode = Mode::FiveAxis;
  limited.kinematics.tiltMaxDeg = 10.0;
  limited.kinematics.tiltMinDeg = -10.0;
  planning::ClProgram steep = program;
  for (planning::ClPoint& p : steep.points) p.axis = p.normal;
  EXPECT_THAT([&] { encodeGCode(steep, ball, limited); },
              ::testing::ThrowsMessage<InvalidInput>(::testing::HasSubstr("outside the machine")));
}

/// A tool reference program along x with the given axes (empty: no axis given).
planning::ClProgram referencePoints(const std::vector<std::optional<ddf::Vec3>>& axes) {
  planning::ClProgram program;
  program.pointKind = planning::ClPointKind::ToolReference;
  for (std::size_t i = 0; i < axes.size(); ++i) {
    planning::ClPoint p;
    p.point = static_cast<int>(i);
    p.positionMm = {10.0 * static_cast<double>(i), 5.0, 2.0};
    p.axis = axes[i];
    p.feedMmPerMin = 600.0;
    program.points.push_back(p);
  }
  return program;
}

TEST(GCodeWriter, PointWithoutAnAxisKeepsTheAxisInForce) {
  const ddf::Vec3 tilted = unitFromAngles(0.4, 2.0);
  const planning::ClProgram program =
      referencePoints({std::nullopt, tilted, std::nullopt, std::nullopt});
  GCodeWriteParams params;
  params.mode = Mode::FiveAxis;
  params.kinematics.pair = planning::RotaryPair::BC;
  const std::vector<Motion> moves =
      pointMotions(encodeGCode(program, cutter(planning::ToolKind::BallEnd, 3.0), params), 4);
  ASSERT_EQ(moves.size(), 4u);
  const auto axisOf = [&](const Motion& m) {
    return planning::forwardKinematics(params.kinematics, {xyz(m), m.axes.at('B'), m.axes.at('C')})
        .axis;
  };
  EXPECT_LT((axisOf(moves[0]) - ddf::Vec3::UnitZ()).norm(), 1e-6);  // before any axis: +Z
  for (int i = 1; i < 4; ++i) EXPECT_LT((axisOf(moves[i]) - tilted).norm(), 1e-5) << i;
  // 3-axis output refuses the tilted points that carry no axis of their own too.
  EXPECT_THAT([&] { encodeGCode(program, cutter(planning::ToolKind::BallEnd, 3.0), {}); },
              ::testing::ThrowsMessage<InvalidInput>(::testing::HasSubstr("point 1")));
}

TEST(GCodeWriter, AdviceForAnAxisItCannotWriteIsAdviceThatWorks) {
  const planning::Tool ball = cutter(planning::ToolKind::BallEnd, 3.0);
  GCodeWriteParams five;
  five.mode = Mode::FiveAxis;
  // Tilted by 30 deg: 3-axis says 5-axis, and 5-axis writes it.
  const planning::ClProgram tilted = referencePoints({unitFromAngles(kPi / 6, 0.3)});
  EXPECT_THAT([&] { encodeGCode(tilted, ball, {}); },
              ::testing::ThrowsMessage<InvalidInput>(::testing::HasSubstr("5-axis machine")));
  EXPECT_NO_THROW(encodeGCode(tilted, ball, five));
  // Pointing up from below: neither machine reaches it, and neither message says 5-axis.
  const planning::ClProgram upward = referencePoints({ddf::Vec3(0, 0, -1)});
  for (const GCodeWriteParams& params : {GCodeWriteParams{}, five}) {
    try {
      encodeGCode(upward, ball, params);
      ADD_FAILURE() << "an upward axis was written";
    } catch (const InvalidInput& e) {
      EXPECT_THAT(e.what(), ::testing::HasSubstr("turn the part over"));
      EXPECT_THAT(e.what(), ::testing::Not(::testing::HasSubstr("write it as 5-axis")));
    }
  }
  // Turned over (the part rotated 180 deg about x), the same point is written.
  EXPECT_NO_THROW(encodeGCode(referencePoints({ddf::Vec3(0, 0, 1)}), ball, {}));
}

TEST(GCodeWriter, ToolChangesGiveTheirToolAndStartTheSpindleAgain) {
  planning::ClProgram program =
      referencePoints({std::nullopt, std::nullopt, std::nullopt, std::nullopt});
  program.toolNumber = 1;
  program.spindleRpm = 3000.0;
  program.toolChanges = {{.firstPoint = 2, .toolNumber = 4, .toolName = "flat 6"},
                         {.firstPoint = 3, .toolNumber = 9, .toolName = "ball 2"}};
  const std::string text = encodeGCode(program, cutter(planning::ToolKind::BallEnd, 3.0), {});
  const auto count = [&](const std::string& word) {
    std::size_t n = 0;
    for (std::size_t at = text.find(word); at != std::string::npos; at = text.find(word, at + 1))
      ++n;
    return n;
  };
  EXPECT_EQ(count("T1 M6"), 1u);
  EXPECT_EQ(count("T4 M6"), 1u);
  EXPECT_EQ(count("T9 M6"), 1u);
  EXPECT_EQ(count("G43 H4"), 1u);
  EXPECT_EQ(count("S3000.0 M3"), 3u);
  // Each change comes after point 1 (resp. 2) and before the next point, at the safe plane.
  const std::size_t change = text.find("T4 M6");
  EXPECT_LT(text.find("X10.0000"), change);
  EXPECT_GT(text.find("G1 X20.0000"), change);
  const std::vector<Motion> all = parseMotions(text);
  // 2 safe rapids, 4 points, 2 x (retract + over the next point), the final retract.
  ASSERT_EQ(all.size(), 11u);
  EXPECT_EQ(all[4].g, 0);
  EXPECT_NEAR(all[4].axes.at('Z'), all[0].axes.at('Z'), 1e-12);
}

TEST(GCodeWriter, ToolCentrePointPositionsAreTheTipInThePartFrame) {
  const ddf::Vec3 tilted = unitFromAngles(0.5, 1.0);
  const planning::ClProgram program = referencePoints({tilted, tilted, tilted});
  GCodeWriteParams params;
  params.mode = Mode::FiveAxis;
  params.kinematics.pair = planning::RotaryPair::BC;
  params.kinematics.pivotMm = {0.0, 0.0, -120.0};  // would move machine X Y Z a lot
  params.tcpPositions = true;
  params.tcpOnBlock = "G234 H{tool}";
  params.tcpOffBlock = "G49";
  const std::string text = encodeGCode(program, cutter(planning::ToolKind::BallEnd, 3.0), params);
  EXPECT_THAT(text, ::testing::HasSubstr("\nG234 H1\n"));
  EXPECT_THAT(text, ::testing::Not(::testing::HasSubstr("G43 H1")));
  EXPECT_THAT(text, ::testing::HasSubstr("\nG49\nM5 M9"));
  const std::vector<Motion> moves = pointMotions(text, 3);
  for (std::size_t i = 0; i < 3; ++i)
    EXPECT_LT((xyz(moves[i]) - program.points[i].positionMm).norm(), 1e-4) << i;
}

TEST(GCodeWriter, WriteGCodeWritesTheEncodedText) {
  const planning::ClProgram program = sphereContacts({0, 0, 0}, 30.0, 10);
  const planning::Tool ball = cutter(planning::ToolKind::BallEnd, 3.0);
  const std::filesystem::path path =
      std::filesystem::temp_directory_path() / "ddfcam_gcode_writer_test.ngc";
  writeGCode(path, program, ball, {});
  std::ifstream in(path, std::ios::binary);
  const std::string read((std::istreambuf_iterator<char>(in)), std::istreambuf_iterator<char>());
  EXPECT_EQ(read, encodeGCode(program, ball, {}));
  std::filesystem::remove(path);
}

}  // namespace
}  // namespace ddfcam::io
