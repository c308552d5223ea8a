// SPDX-License-Identifier: MIT
// Tests of the APT/CLDATA reader on hand-written snippets of every feature, and bad input.
#include <ddfcam/error.h>
#include <ddfcam/io/programs/apt_reader.h>

#include <gmock/gmock.h>
#include <gtest/gtest.h>

#include <cmath>
#include <numbers>
#include <random>
#include <string>

namespace ddfcam::io {
namespace {

using planning::MoveKind;
using ::testing::HasSubstr;

planning::ClProgram read(const std::string& text, const AptReadParams& params = {}) {
  return decodeApt(text, "snippet.apt", params);
}

std::string errorOf(const std::string& text) {
  try {
    read(text);
  } catch (const IoError& e) {
    return e.what();
  }
  return "no error";
}

bool hasWarning(const planning::ClProgram& p, const std::string& part) {
  for (const planning::ClMessage& m : p.warnings) {
    if (m.text.find(part) != std::string::npos) return true;
  }
  return false;
}

TEST(AptReader, ReadsCommentsContinuationBlanksAndCase) {
  const planning::ClProgram p = read(
      "$$ first comment\n"
      "partno / My Part\n"
      "units / mm\n"
      "goto / 1.5 , 2 ,  3 $$ trailing note\n"
      "GOTO/4,$\n"
      "  5,$\n"
      "6\r\n"
      "\n"
      "Goto/+7, -8.25e1, .5\n"
      "fini\n");
  EXPECT_EQ(p.partName, "My Part");
  EXPECT_EQ(p.comments, (std::vector<std::string>{"first comment", "trailing note"}));
  ASSERT_EQ(p.points.size(), 3u);
  EXPECT_EQ(p.points[0].positionMm, ddf::Vec3(1.5, 2, 3));
  EXPECT_EQ(p.points[1].positionMm, ddf::Vec3(4, 5, 6));
  EXPECT_EQ(p.points[2].positionMm, ddf::Vec3(7, -82.5, 0.5));
  EXPECT_EQ(p.points[0].sourceLine, 4);
  EXPECT_EQ(p.points[1].sourceLine, 5);
  EXPECT_EQ(p.points[2].sourceLine, 9);
  EXPECT_TRUE(p.warnings.empty());
  EXPECT_EQ(p.pointKind, planning::ClPointKind::ToolReference);
}

TEST(AptReader, ReadsPartnoWithAndWithoutSlash) {
  EXPECT_EQ(read("PARTNO CORE_WORK\nGOTO/0,0,0\n").partName, "CORE_WORK");
  EXPECT_EQ(read("PARTNO/ABC 12\nGOTO/0,0,0\n").partName, "ABC 12");
}

TEST(AptReader, ConvertsInchesAndFeedsInBothOrders) {
  const planning::ClProgram p = read(
      "UNITS / INCHES\n"
      "FEDRAT / 10.0, IPM\n"
      "GOTO / 1, 2, 3\n"
      "FEDRAT/MMPM,500\n"
      "GOTO/1,0,0\n"
      "FEDRAT/2\n"
      "GOTO/0,0,1\n"
      "UNIT/MM\n"
      "GOTO/1,1,1\n");
  EXPECT_EQ(p.sourceUnit, LengthUnit::Inch);
  ASSERT_EQ(p.points.size(), 4u);
  EXPECT_NEAR((p.points[0].positionMm - ddf::Vec3(25.4, 50.8, 76.2)).norm(), 0.0, 1e-12);
  EXPECT_DOUBLE_EQ(p.points[0].feedMmPerMin, 254.0);
  EXPECT_DOUBLE_EQ(p.points[1].feedMmPerMin, 500.0);
  EXPECT_DOUBLE_EQ(p.points[2].feedMmPerMin, 50.8);  // a bare number is in the file unit
  EXPECT_EQ(p.points[3].positionMm, ddf::Vec3(1, 1, 1));
}

TEST(AptReader, InfersInchesFromTheFeedWordWithoutUnits) {
  const planning::ClProgram p = read("GOTO/1,0,0\nFEDRAT/IPM,10.0000\nGOTO/2,0,0\n");
  EXPECT_EQ(p.sourceUnit, LengthUnit::Inch);
  EXPECT_DOUBLE_EQ(p.points[0].positionMm.x(), 25.4);
  EXPECT_TRUE(hasWarning(p, "no UNITS record"));
  EXPECT_EQ(read("GOTO/1,0,0\n").sourceUnit, LengthUnit::Millimetre);
}

TEST(AptReader, WarnsOnFeedPerRevolution) {
  const planning::ClProgram p = read("SPINDL/RPM,1000,CCLW\nFEDRAT/0.1,MMPR\nGOTO/1,0,0\n");
  EXPECT_TRUE(hasWarning(p, "per revolution"));
  EXPECT_DOUBLE_EQ(p.points[0].feedMmPerMin, 100.0);
  EXPECT_DOUBLE_EQ(p.spindleRpm, 1000.0);
  EXPECT_FALSE(p.spindleClockwise);
}

TEST(AptReader, AppliesRapidToTheNextMotionOnlyAndStartsPathsAfterRapids) {
  const planning::ClProgram p = read(
      "FROM/0,0,100\n"
      "FEDRAT/300,MMPM\n"
      "RAPID\nGOTO/0,0,10\n"
      "GOTO/0,0,0\nGOTO/10,0,0\n"
      "RAPID\nGOTO/10,0,10\n"
      "RAPID\nGOTO/20,0,10\n"
      "GOTO/20,0,0\nGOTO/30,0,0\n");
  ASSERT_EQ(p.points.size(), 8u);
  const std::vector<MoveKind> moves = {MoveKind::Rapid, MoveKind::Rapid, MoveKind::Cut,
                                       MoveKind::Cut,   MoveKind::Rapid, MoveKind::Rapid,
                                       MoveKind::Cut,   MoveKind::Cut};
  const std::vector<int> paths = {0, 0, 0, 0, 0, 0, 1, 1};
  const std::vector<int> indices = {0, 1, 2, 3, 4, 5, 0, 1};
  for (std::size_t k = 0; k < moves.size(); ++k) {
    EXPECT_EQ(p.points[k].move, moves[k]) << k;
    EXPECT_EQ(p.points[k].path, paths[k]) << k;
    EXPECT_EQ(p.points[k].point, indices[k]) << k;
    EXPECT_DOUBLE_EQ(p.points[k].feedMmPerMin, moves[k] == MoveKind::Rapid ? 0.0 : 300.0) << k;
  }
  EXPECT_EQ(p.pathCount(), 2);
}

TEST(AptReader, TakesTheToolAxisFromSixValueGotosWithOrWithoutMultax) {
  const planning::ClProgram p = read("GOTO/0,0,0,0,0,2\nGOTO/1,0,0\nMULTAX/ON\nGOTO/1,1,0,0,3,4\n");
  ASSERT_EQ(p.points.size(), 3u);
  EXPECT_EQ(p.points[0].axis, ddf::Vec3(0, 0, 1));
  EXPECT_EQ(p.points[1].axis, ddf::Vec3(0, 0, 1));  // the axis in force
  EXPECT_NEAR((*p.points[2].axis - ddf::Vec3(0, 0.6, 0.8)).norm(), 0.0, 1e-15);
  EXPECT_TRUE(p.multiAxis());
}

TEST(AptReader, KeepsATiltedAxisOverThreeValueGotosUntilMultaxOff) {
  const planning::ClProgram p =
      read("GOTO/0,0,0\nGOTO/1,0,0,0,0.6,0.8\nGOTO/2,0,0\nGOTO/3,0,0\nMULTAX/OFF\nGOTO/4,0,0\n");
  ASSERT_EQ(p.points.size(), 5u);
  EXPECT_FALSE(p.points[0].axis.has_value());  // nothing given yet: 3-axis
  for (int i = 1; i <= 3; ++i) {
    ASSERT_TRUE(p.points[i].axis.has_value()) << i;
    EXPECT_NEAR((*p.points[i].axis - ddf::Vec3(0, 0.6, 0.8)).norm(), 0.0, 1e-15) << i;
  }
  EXPECT_FALSE(p.points[4].axis.has_value());
  // An arc after a tilted GOTO keeps the tilt on every interpolated point.
  const planning::ClProgram arc =
      read("GOTO/1,0,0,0,0.6,0.8\nCIRCLE/0,0,0,0,0,1,1\nGOTO/0,1,0\n", {.chordToleranceMm = 0.01});
  ASSERT_GT(arc.points.size(), 3u);
  for (const planning::ClPoint& q : arc.points) {
    ASSERT_TRUE(q.axis.has_value());
    EXPECT_NEAR((*q.axis - ddf::Vec3(0, 0.6, 0.8)).norm(), 0.0, 1e-15);
  }
}

TEST(AptReader, RefusesAProgramWithoutMotion) {
  EXPECT_THAT(errorOf(""), HasSubstr("snippet.apt: no GOTO or FROM record"));
  EXPECT_THAT(errorOf("PARTNO EMPTY\nUNITS/MM\nLOADTL/1\nFINI\n"),
              HasSubstr("holds no tool motion"));
}

TEST(AptReader, KeepsEveryToolOfAMultiToolProgram) {
  const planning::ClProgram p = read(
      "LOADTL/1\nCUTTER/10,5\nGOTO/0,0,0\nGOTO/1,0,0\n"
      "LOADTL/2\nCUTTER/6\nRAPID\nGOTO/5,0,0\nGOTO/6,0,0\n"
      "LOADTL/2\nGOTO/7,0,0\n"  // the same tool again: no change
      "LOADTL/7\nCUTTER/3,1\nGOTO/8,0,0\n");
  ASSERT_EQ(p.points.size(), 6u);
  EXPECT_EQ(p.toolNumber, 1);
  EXPECT_EQ(p.cutter, (planning::ClCutter{10, 5, 0, 5, 0, 0, 0}));
  ASSERT_EQ(p.toolChanges.size(), 2u);
  EXPECT_EQ(p.toolChanges[0].firstPoint, 2u);
  EXPECT_EQ(p.toolChanges[0].toolNumber, 2);
  EXPECT_EQ(p.toolChanges[0].cutter, (planning::ClCutter{6, 0, 3, 0, 0, 0, 0}));
  EXPECT_EQ(p.toolChanges[0].sourceLine, 6);
  EXPECT_EQ(p.toolChanges[1].firstPoint, 5u);
  EXPECT_EQ(p.toolChanges[1].toolNumber, 7);
  EXPECT_EQ(p.toolChanges[1].cutter, (planning::ClCutter{3, 1, 0.5, 1, 0, 0, 0}));
  EXPECT_TRUE(read("LOADTL/3\nGOTO/0,0,0\nGOTO/1,0,0\n").toolChanges.empty());
}

TEST(AptReader, RecordsToolData) {
  const planning::ClProgram a =
      read("LOADTL/8\nCUTTER/10,2,3,2,0,0,40\nSPINDL/2000,CLW\nCOOLNT/FLOOD\nGOTO/0,0,0\n");
  EXPECT_EQ(a.toolNumber, 8);
  EXPECT_EQ(a.cutter, (planning::ClCutter{10, 2, 3, 2, 0, 0, 40}));
  EXPECT_DOUBLE_EQ(a.spindleRpm, 2000.0);
  EXPECT_TRUE(a.coolant);
  const planning::ClProgram b =
      read("UNITS/INCHES\nTLDATA/MILL,1.0000,0.5000,3.0000,0.0000,0.0000\nGOTO/0,0,0\n");
  ASSERT_TRUE(b.cutter.has_value());
  EXPECT_DOUBLE_EQ(b.cutter->diameterMm, 25.4);
  EXPECT_DOUBLE_EQ(b.cutter->cornerRadiusMm, 12.7);
  EXPECT_DOUBLE_EQ(b.cutter->eMm, 0.0);
  EXPECT_DOUBLE_EQ(b.cutter->heightMm, 76.2);
  EXPECT_EQ(read("CUTTER/6\nGOTO/0,0,0\n").cutter, (planning::ClCutter{6, 0, 3, 0, 0, 0, 0}));
}

TEST(AptReader, KeepsUnknownWordsAsCommentsWithOneWarningEach) {
  const planning::ClProgram p = read(
      "TOOL PATH/NORM_PART,TOOL,BALL_MILL_1.00\n"
      "PAINT/COLOR,4\nPAINT/COLOR,5\nMACHIN / MILL, M0001\nLOAD/TOOL,1\n"
      "MSYS/3,3,0,1,0,0,0,1,0\nGOTO/1,2,3\nEND-OF-PATH\nEND\nFINI\nGOTO/9,9,9\n");
  EXPECT_EQ(p.toolName, "BALL_MILL_1.00");
  EXPECT_THAT(p.comments, ::testing::Contains("PAINT/COLOR,5"));
  EXPECT_THAT(p.comments, ::testing::Contains("MACHIN / MILL, M0001"));
  int paint = 0;
  for (const planning::ClMessage& m : p.warnings)
    paint += m.text.find("'PAINT'") != std::string::npos;
  EXPECT_EQ(paint, 1);
  EXPECT_TRUE(hasWarning(p, "'TOOL PATH'"));
  EXPECT_TRUE(hasWarning(p, "'MACHIN'"));
  EXPECT_TRUE(hasWarning(p, "'LOAD'"));
  EXPECT_TRUE(hasWarning(p, "MSYS"));
  EXPECT_EQ(p.points.size(), 1u);  // nothing after FINI is read
  EXPECT_FALSE(hasWarning(read("MSYS/0,0,0,1,0,0,0,1,0\nGOTO/0,0,0\n"), "MSYS"));
}

TEST(AptReader, ReportsBadInputWithTheLineNumber) {
  EXPECT_THAT(errorOf("GOTO/1,2,3\nGOTO/1,$\n"), HasSubstr("snippet.apt: line 2: "));
  EXPECT_THAT(errorOf("\nGOTO/1,x,3\n"), HasSubstr("line 2: GOTO: 'x' is not a finite number"));
  EXPECT_THAT(errorOf("GOTO/1,2\n"), HasSubstr("line 1: GOTO needs 3 or 6 values"));
  EXPECT_THAT(errorOf("GOTO/1,2,3,4\n"), HasSubstr("line 1"));
  EXPECT_THAT(errorOf("GOTO/1,2,3,\n"), HasSubstr("line 1"));
  EXPECT_THAT(errorOf("GOTO/1,2,3,0,0,0\n"), HasSubstr("line 1: GOTO: zero tool axis"));
  EXPECT_THAT(errorOf("GOTO/1,2,3,nan,0,1\n"), HasSubstr("line 1"));
  EXPECT_THAT(errorOf("GOTO/1e999,2,3\n"), HasSubstr("line 1"));
  EXPECT_THAT(errorOf("GOTO/1,0,0\nCIRCLE/0,0,0,0,0,1,1\nFEDRAT/5\nGOTO/0,1,0\n"),
              HasSubstr("line 2: CIRCLE is not followed by a GOTO"));
  EXPECT_THAT(errorOf("GOTO/1,0,0\nCIRCLE/0,0,0,0,0,1,1\n"), HasSubstr("line 2: CIRCLE"));
  EXPECT_THAT(errorOf("GOTO/1,0,0\nCIRCLE/0,0,0,0,0,1,2\nGOTO/0,1,0\n"),
              HasSubstr("line 2: CIRCLE: start or end point is not at the radius"));
  EXPECT_THAT(errorOf("CIRCLE/0,0,0,0,0,1,1\nGOTO/0,1,0\n"), HasSubstr("line 1"));
  EXPECT_THAT(errorOf("GOTO/1,0,0\nCIRCLE/0,0,0,0,0,0,1\nGOTO/0,1,0\n"), HasSubstr("line 2"));
  EXPECT_THAT(errorOf("UNITS/FURLONG\n"), HasSubstr("line 1"));
  EXPECT_THAT(errorOf("GOTO/1,2,3\nGO\x01TO/1,2,3\n"), HasSubstr("line 2: binary data"));
  EXPECT_THROW(read("GOTO/1,0,0\n", {.chordToleranceMm = 0.0}), InvalidInput);
}

TEST(AptReader, NeverCrashesOnRandomInput) {
  const std::string alphabet = "GOTOCIRCLEFEDRATUNITSRAPID/,$ .-+0123456789e\n\n,,//$$";
  std::mt19937 rng(7);
  for (int trial = 0; trial < 3000; ++trial) {
    std::string text;
    const int length = static_cast<int>(rng() % 200);
    for (int k = 0; k < length; ++k) text += alphabet[rng() % alphabet.size()];
    if (trial % 2 == 0) text = "GOTO/1,0,0\nCIRCLE/0,0,0,0,0,1,1\n" + text;
    try {
      const planning::ClProgram p = read(text);
      for (const planning::ClPoint& q : p.points) ASSERT_TRUE(q.positionMm.allFinite());
    } catch (const IoError& e) {
      EXPECT_THAT(e.what(), ::testing::AnyOf(HasSubstr("snippet.apt: line "),
                                             HasSubstr("snippet.apt: no GOTO or FROM record")));
    }
  }
}

/// The angle of @p q about the z axis through @p centre.
double angleAbout(const ddf::Vec3& q, const ddf::Vec3& centre) {
  return std::atan2(q.y() - centre.y(), q.x() - centre.x());
}

TEST(AptReader, InterpolatesCircleArcsOnTheCircleWithinTheChordTolerance) {
  // Axis +z: clockwise seen from +z (G02 as NX writes it). Start at angle 90 deg, end at 0.
  const ddf::Vec3 centre(10, 20, 5);
  const double r = 7.5;
  for (const double tolerance : {0.1, 0.005, 0.0001}) {
    const planning::ClProgram p = read(
        "FEDRAT/MMPM,250\nGOTO/10,27.5,5\nCIRCLE/10,20,5,0,0,1,7.5,0.06,0.5,30,0\nGOTO/17.5,20,5\n",
        {.chordToleranceMm = tolerance});
    ASSERT_GT(p.points.size(), 3u);
    EXPECT_EQ(p.points.back().positionMm, ddf::Vec3(17.5, 20, 5));  // ends at the GOTO
    EXPECT_EQ(p.points.back().sourceLine, 4);
    double previous = angleAbout(p.points[0].positionMm, centre);
    for (std::size_t k = 1; k < p.points.size(); ++k) {
      const ddf::Vec3& q = p.points[k].positionMm;
      const ddf::Vec3 radial = q - centre;
      EXPECT_NEAR(radial.norm(), r, 1e-9 * r) << k;
      EXPECT_NEAR(q.z(), 5.0, 1e-12);
      const double angle = angleAbout(q, centre);
      EXPECT_LT(angle, previous) << "clockwise about +z";
      // Sagitta of the chord from the previous point.
      const double turn = previous - angle;
      EXPECT_LE(r * (1.0 - std::cos(turn / 2.0)), tolerance * (1 + 1e-12)) << k;
      EXPECT_EQ(p.points[k].move, MoveKind::Cut);
      EXPECT_DOUBLE_EQ(p.points[k].feedMmPerMin, 250.0);
      if (k + 1 < p.points.size()) {
        EXPECT_EQ(p.points[k].sourceLine, 3);
      }
      previous = angle;
    }
    EXPECT_NEAR(previous, 0.0, 1e-12);
    // Not more chords than needed: one fewer would break the tolerance.
    const double step = 2.0 * std::acos(1.0 - tolerance / r);
    EXPECT_EQ(p.points.size() - 1, static_cast<std::size_t>(std::ceil((M_PI / 2) / step)));
  }
}

TEST(AptReader, TurnsCounterclockwiseForANegativeAxisAndMakesFullCircles) {
  // Axis -z: counter-clockwise seen from +z, from angle 180 to 270 deg (a quarter).
  const planning::ClProgram p = read(
      "GOTO/-272.5,172.5,100\nCIRCLE/-265,172.5,100,0,0,-1,7.5\n"
      "GOTO/-265,165,100\n");
  for (const planning::ClPoint& q : p.points) {
    EXPECT_LE(q.positionMm.x(), -265.0 + 1e-9);
    EXPECT_LE(q.positionMm.y(), 172.5 + 1e-9);
  }
  const planning::ClProgram full =
      read("GOTO/1,0,0\nCIRCLE/0,0,0,0,0,1,1\nGOTO/1,0,0\n", {.chordToleranceMm = 0.01});
  double turned = 0.0;
  for (std::size_t k = 1; k < full.points.size(); ++k) {
    const double a0 = angleAbout(full.points[k - 1].positionMm, ddf::Vec3::Zero());
    const double a1 = angleAbout(full.points[k].positionMm, ddf::Vec3::Zero());
    double d = a0 - a1;
    if (d < 0) d += 2 * M_PI;
    turned += d;
  }
  EXPECT_NEAR(turned, 2 * M_PI, 1e-9);
}

TEST(AptReader, InterpolatesHelicalArcsAndInchCircles) {
  const planning::ClProgram p =
      read("UNITS/INCHES\nGOTO/1,0,0\nCIRCLE/0,0,0,0,0,-1,1\nGOTO/-1,0,1\n",
           {.chordToleranceMm = 0.001});
  ASSERT_GT(p.points.size(), 10u);
  for (std::size_t k = 1; k + 1 < p.points.size(); ++k) {
    const ddf::Vec3& q = p.points[k].positionMm;
    EXPECT_NEAR(std::hypot(q.x(), q.y()), 25.4, 1e-9 * 25.4);
    EXPECT_GT(q.y(), 0.0);  // counter-clockwise about +z from 0 to 180 deg
    const double angle = angleAbout(q, ddf::Vec3::Zero());
    EXPECT_NEAR(q.z(), 25.4 * angle / M_PI, 1e-9);  // height linear in the angle
  }
}

}  // namespace
}  // namespace ddfcam::io
