// SPDX-License-Identifier: MIT
// Tests of the APT/CLDATA writer: hand-written expected text, refusals, cutters, round trips.
#include <ddfcam/error.h>
#include <ddfcam/io/programs/apt_reader.h>
#include <ddfcam/io/programs/apt_writer.h>
#include <ddfcam/planning/placement/cl_program_builder.h>
#include <ddfcam/planning/placement/cutter_tool.h>

#include <gmock/gmock.h>
#include <gtest/gtest.h>

#include <cmath>
#include <fstream>
#include <optional>
#include <random>
#include <sstream>
#include <string>
#include <vector>

#include "../io_test_support.h"

namespace ddfcam::io {
namespace {

using planning::MoveKind;
using ::testing::HasSubstr;

std::vector<std::string> linesOf(const std::string& text) {
  std::vector<std::string> lines;
  std::istringstream in(text);
  for (std::string line; std::getline(in, line);) lines.push_back(line);
  return lines;
}

planning::ClPoint point(const ddf::Vec3& p, MoveKind move, double feed,
                        std::optional<ddf::Vec3> axis = std::nullopt) {
  planning::ClPoint c;
  c.positionMm = p;
  c.move = move;
  c.feedMmPerMin = feed;
  c.axis = axis;
  return c;
}

planning::ClProgram tinyProgram() {
  planning::ClProgram program;
  program.partName = "DEMO";
  program.toolNumber = 3;
  program.cutter = planning::ClCutter{10.0, 5.0, 0.0, 5.0, 0.0, 0.0, 20.0};
  program.spindleRpm = 12000.0;
  program.coolant = true;
  program.comments = {"hello"};
  program.points = {
      point({0, 0, 50}, MoveKind::Rapid, 0.0),
      point({0, -0.00001, 0}, MoveKind::Cut, 500.0, ddf::Vec3::UnitZ()),
      point({10, -2.5, 0.12346}, MoveKind::Cut, 500.0, ddf::Vec3(0.6, 0.0, 0.8)),
      point({20, 0, 0}, MoveKind::Link, 800.0),
  };
  return program;
}

TEST(AptWriter, WritesTheExpectedTextForATinyProgram) {
  const std::vector<std::string> expected = {
      "PARTNO DEMO",
      "UNITS/MM",
      "$$ hello",
      "CUTTER/10.0000,5.0000,0.0000,5.0000,0.0000,0.0000,20.0000",
      "LOADTL/3",
      "SPINDL/12000.0000,CLW",
      "COOLNT/ON",
      "MULTAX/ON",
      "RAPID",
      "GOTO/0.0000,0.0000,50.0000",
      "FEDRAT/500.0000,MMPM",
      "GOTO/0.0000,0.0000,0.0000,0.0000000,0.0000000,1.0000000",
      "GOTO/10.0000,-2.5000,0.1235,0.6000000,0.0000000,0.8000000",
      "FEDRAT/800.0000,MMPM",
      "GOTO/20.0000,0.0000,0.0000",
      "COOLNT/OFF",
      "SPINDL/OFF",
      "END",
      "FINI",
  };
  EXPECT_EQ(linesOf(encodeApt(tinyProgram())), expected);
}

TEST(AptWriter, ALinkedPassStartsWithoutARepeatedGoto) {
  // Two passes of a ball end along x, 2 mm above z = 0, joined by retract, rapid and approach:
  // the first cut point of the second pass repeats the approach's end (see clProgramFromPath).
  planning::ToolPath path;
  path.name = "two";
  path.feedMmPerMin = 900;
  for (const ddf::Vec3 c : {ddf::Vec3(0, 0, 2), ddf::Vec3(5, 0, 2), ddf::Vec3(5, 4, 2),
                            ddf::Vec3(0, 4, 2)}) {
    planning::PathPose pose;
    pose.pose.translation() = c;
    pose.contact = c - ddf::Vec3(0, 0, 2);
    path.poses.push_back(pose);
  }
  path.passStarts = {0, 2};
  planning::Tool ball;
  ball.kind = planning::ToolKind::BallEnd;
  ball.radiusMm = 2.0;
  ball.widthMm = 10.0;
  const planning::ClProgram program = planning::clProgramFromPath(
      path, ball, planning::ClPointKind::ToolReference, {}, {.clearanceMm = 3});
  ASSERT_EQ(program.points.size(), 7u);  // 4 cut points, retract, rapid, approach
  const std::vector<std::string> lines = linesOf(encodeApt(program));
  std::vector<std::string> gotos;
  for (const std::string& line : lines)
    if (line.rfind("GOTO/", 0) == 0) gotos.push_back(line);
  for (std::size_t g = 1; g < gotos.size(); ++g) EXPECT_NE(gotos[g], gotos[g - 1]) << g;
  ASSERT_EQ(gotos.size(), 6u);
  // Read back: the program's positions without the zero-length move, in order.
  const planning::ClProgram back = decodeApt(encodeApt(program), "two.apt");
  std::vector<ddf::Vec3> expected;
  for (const planning::ClPoint& p : program.points)
    if (expected.empty() || (p.positionMm - expected.back()).norm() > 1e-9)
      expected.push_back(p.positionMm);
  ASSERT_EQ(back.points.size(), expected.size());
  for (std::size_t i = 0; i < expected.size(); ++i)
    EXPECT_LT((back.points[i].positionMm - expected[i]).norm(), 1e-4) << i;
}

TEST(AptWriter, WritesInchesAndTheNxFeedOrder) {
  planning::ClProgram program;
  program.partName = "P";
  program.spindleRpm = 0.0;
  program.spindleClockwise = false;
  program.points = {point({25.4, 50.8, -12.7}, MoveKind::Cut, 254.0)};
  const std::string text = encodeApt(
      program, {.coordinateDecimals = 5, .unit = LengthUnit::Inch, .feedUnitFirst = true});
  const std::vector<std::string> expected = {"PARTNO P",
                                             "UNITS/INCHES",
                                             "LOADTL/1",
                                             "FEDRAT/IPM,10.00000",
                                             "GOTO/1.00000,2.00000,-0.50000",
                                             "END",
                                             "FINI"};
  EXPECT_EQ(linesOf(text), expected);
}

TEST(AptWriter, RefusesWhatAptCannotSay) {
  planning::ClProgram contact = tinyProgram();
  contact.pointKind = planning::ClPointKind::Contact;
  EXPECT_THROW(encodeApt(contact), InvalidInput);
  EXPECT_THROW(encodeApt(tinyProgram(), {.coordinateDecimals = 3}), InvalidInput);
  EXPECT_THROW(encodeApt(tinyProgram(), {.coordinateDecimals = 7}), InvalidInput);
  EXPECT_THROW(encodeApt(tinyProgram(), {.vectorDecimals = 5}), InvalidInput);
  EXPECT_THROW(encodeApt(tinyProgram(), {.vectorDecimals = 10}), InvalidInput);
  EXPECT_THROW(encodeApt(tinyProgram(), {.unit = LengthUnit::Metre}), InvalidInput);
  planning::ClProgram badAxis = tinyProgram();
  badAxis.points[1].axis = ddf::Vec3(0, 0, 2);
  EXPECT_THROW(encodeApt(badAxis), InvalidInput);
  badAxis.points[1].axis = ddf::Vec3(0, 0, std::nan(""));
  EXPECT_THROW(encodeApt(badAxis), InvalidInput);
  planning::ClProgram badPoint = tinyProgram();
  badPoint.points[0].positionMm.x() = INFINITY;
  EXPECT_THROW(encodeApt(badPoint), InvalidInput);
}

TEST(AptWriter, GivesTheSevenParameterCutterOfEveryToolKind) {
  using planning::Tool;
  using planning::ToolKind;
  const auto cutterOf = [](ToolKind kind, double edge) {
    return planning::aptCutter(
        Tool{.kind = kind, .radiusMm = 4.0, .widthMm = 12.0, .edgeRadiusMm = edge});
  };
  EXPECT_EQ(cutterOf(ToolKind::BallEnd, 0.0),
            (planning::ClCutter{8.0, 4.0, 0.0, 4.0, 0.0, 0.0, 12.0}));
  EXPECT_EQ(cutterOf(ToolKind::FlatEnd, 0.0),
            (planning::ClCutter{8.0, 0.0, 4.0, 0.0, 0.0, 0.0, 12.0}));
  EXPECT_EQ(cutterOf(ToolKind::TorusCutter, 1.0),
            (planning::ClCutter{8.0, 1.0, 3.0, 1.0, 0.0, 0.0, 12.0}));
  EXPECT_EQ(cutterOf(ToolKind::Sphere, 0.0),
            (planning::ClCutter{8.0, 4.0, 0.0, 4.0, 0.0, 0.0, 8.0}));
  EXPECT_EQ(cutterOf(ToolKind::CylinderRoll, 0.5),
            (planning::ClCutter{8.0, 0.5, 3.5, 0.5, 0.0, 0.0, 12.0}));
  EXPECT_EQ(cutterOf(ToolKind::BeltContactWheel, 0.0),
            (planning::ClCutter{8.0, 0.0, 4.0, 0.0, 0.0, 0.0, 12.0}));
  EXPECT_THROW(planning::aptCutter(Tool{.kind = ToolKind::BallEnd, .radiusMm = -1.0}),
               InvalidInput);
}

TEST(AptWriter, BreaksLongRecordsAfterACommaWithinTheColumnLimit) {
  planning::ClProgram program;
  program.partName = std::string(200, 'N');
  program.comments = {std::string(150, 'c') + "\nsecond line"};
  program.points = {point({-99999.123456, 88888.5, -77777.25}, MoveKind::Cut, 1e5,
                          ddf::Vec3(-0.48, -0.6, -0.64))};
  for (const int columns : {32, 40, 72}) {
    const std::string text =
        encodeApt(program, {.coordinateDecimals = 6, .vectorDecimals = 9, .maxColumns = columns});
    int continued = 0;
    for (const std::string& line : linesOf(text)) {
      EXPECT_LE(line.size(), static_cast<std::size_t>(columns)) << line;
      if (line.back() == '$' && line.rfind("$$", 0) != 0) {
        ++continued;
        EXPECT_EQ(line[line.size() - 2], ',') << line;
      }
    }
    EXPECT_GT(continued, 0) << columns;
    const planning::ClProgram back = decodeApt(text, "long.apt");
    ASSERT_EQ(back.points.size(), 1u);
    EXPECT_NEAR((back.points[0].positionMm - program.points[0].positionMm).norm(), 0.0, 1e-6);
  }
}

/// Random programs: paths of rapid approaches and cut runs, 3- or 5-axis or mixed.
planning::ClProgram randomProgram(std::mt19937& rng, bool fiveAxis, bool mixed) {
  std::uniform_real_distribution<double> coord(-500.0, 500.0);
  std::uniform_real_distribution<double> unit(-1.0, 1.0);
  std::uniform_int_distribution<int> count(1, 6);
  planning::ClProgram program;
  program.partName = "RANDOM_" + std::to_string(rng() % 1000);
  program.toolNumber = static_cast<int>(rng() % 40);
  program.cutter = planning::ClCutter{6.0, 3.0, 0.0, 3.0, 0.0, 0.0, 25.0};
  program.spindleRpm = 1000.0 + rng() % 20000;
  program.spindleClockwise = rng() % 2 == 0;
  program.coolant = rng() % 2 == 0;
  program.comments = {"random program", "second comment"};
  const int paths = count(rng);
  for (int p = 0; p < paths; ++p) {
    const double feed = 100.0 + rng() % 5000;
    const int rapids = count(rng) % 3 + 1;
    const int cuts = count(rng) + 1;
    for (int k = 0; k < rapids + cuts; ++k) {
      const bool rapid = k < rapids;
      planning::ClPoint c = point({coord(rng), coord(rng), coord(rng)},
                                  rapid ? MoveKind::Rapid : MoveKind::Cut, rapid ? 0.0 : feed);
      if (fiveAxis && (!mixed || rng() % 2 == 0)) {
        ddf::Vec3 a(unit(rng), unit(rng), unit(rng));
        if (a.norm() < 0.1) a = ddf::Vec3::UnitZ();
        c.axis = a.normalized();
      }
      c.path = p;
      program.points.push_back(c);
    }
  }
  return program;
}

void expectSameToPrecision(const planning::ClProgram& in, const planning::ClProgram& out,
                           const AptWriteParams& w) {
  const std::vector<std::optional<ddf::Vec3>> axes = test::axesInForce(in);
  const double per = millimetresPer(w.unit);
  const double posTol = 0.5 * std::pow(10.0, -w.coordinateDecimals) * per * (1 + 1e-9) + 1e-9;
  const double axisTol = 2.0 * std::pow(10.0, -w.vectorDecimals);
  EXPECT_EQ(out.partName, in.partName);
  EXPECT_EQ(out.sourceUnit, w.unit);
  EXPECT_EQ(out.toolNumber, in.toolNumber);
  EXPECT_EQ(out.spindleClockwise, in.spindleClockwise);
  EXPECT_NEAR(out.spindleRpm, in.spindleRpm, 1e-9);
  EXPECT_EQ(out.coolant, in.coolant);
  EXPECT_EQ(out.comments, in.comments);
  EXPECT_TRUE(out.warnings.empty());
  ASSERT_TRUE(out.cutter.has_value());
  EXPECT_NEAR(out.cutter->diameterMm, in.cutter->diameterMm, posTol);
  EXPECT_NEAR(out.cutter->heightMm, in.cutter->heightMm, posTol);
  ASSERT_EQ(out.points.size(), in.points.size());
  for (std::size_t k = 0; k < in.points.size(); ++k) {
    const planning::ClPoint& a = in.points[k];
    const planning::ClPoint& b = out.points[k];
    for (int d = 0; d < 3; ++d) EXPECT_NEAR(b.positionMm[d], a.positionMm[d], posTol) << k;
    EXPECT_EQ(b.move, a.move) << k;
    EXPECT_NEAR(b.feedMmPerMin, a.feedMmPerMin, posTol) << k;
    const std::optional<ddf::Vec3>& inForce = axes[k];
    ASSERT_EQ(b.axis.has_value(), inForce.has_value()) << k;
    if (inForce) {
      EXPECT_LE((*b.axis - *inForce).norm(), axisTol) << k;
    }
    if (a.move == MoveKind::Cut) {
      EXPECT_EQ(b.path, a.path) << k;
    }
    EXPECT_GT(b.sourceLine, 0);
  }
  EXPECT_EQ(out.pathCount(), in.pathCount());
}

TEST(AptWriter, RoundTripsRandomProgramsToTheWrittenPrecision) {
  std::mt19937 rng(20261122);
  int trial = 0;
  for (const LengthUnit unit : {LengthUnit::Millimetre, LengthUnit::Inch}) {
    for (const bool unitFirst : {false, true}) {
      for (const int cd : {4, 5, 6}) {
        for (const int vd : {6, 7, 9}) {
          const bool fiveAxis = trial % 3 != 0;
          const bool mixed = trial % 3 == 2;
          ++trial;
          const planning::ClProgram in = randomProgram(rng, fiveAxis, mixed);
          const AptWriteParams w{.coordinateDecimals = cd,
                                 .vectorDecimals = vd,
                                 .unit = unit,
                                 .feedUnitFirst = unitFirst};
          const std::string text = encodeApt(in, w);
          for (const std::string& line : linesOf(text)) ASSERT_LE(line.size(), 72u) << line;
          SCOPED_TRACE(text);
          expectSameToPrecision(in, decodeApt(text, "round.apt"), w);
        }
      }
    }
  }
}

TEST(AptWriter, WritesAtomicallyToAFileThatReadsBack) {
  test::ScratchDir dir;
  const auto path = dir.path() / "tiny.apt";
  writeApt(tinyProgram(), path);
  const planning::ClProgram back = readApt(path);
  EXPECT_EQ(back.partName, "DEMO");
  ASSERT_EQ(back.points.size(), 4u);
  EXPECT_EQ(back.points[3].move, MoveKind::Cut);  // APT has no link moves: a feed move
  EXPECT_THROW(writeApt(tinyProgram(), dir.path() / "missing" / "x.apt"), IoError);
}

}  // namespace
}  // namespace ddfcam::io
