// SPDX-License-Identifier: MIT
// Tests of the FANUC TP (.ls) reader on hand-written programs with hand-computed results.
#include <ddfcam/error.h>
#include <ddfcam/io/programs/fanuc_ls_reader.h>

#include <gmock/gmock.h>
#include <gtest/gtest.h>

#include <string>

namespace ddfcam::io {
namespace {

using planning::MoveKind;
using ::testing::HasSubstr;

std::string position(int n, const std::string& xyz, const std::string& wpr, int uf = 0) {
  return "P[" + std::to_string(n) + "]{\n   GP1:\n\tUF : " + std::to_string(uf) +
         ", UT : 1,\t\tCONFIG : 'N U T, 0, 0, 0',\n\t" + xyz + ",\n\t" + wpr + "\n};\n";
}

std::string xyz(double x, double y, double z) {
  return "X = " + std::to_string(x) + " mm, Y = " + std::to_string(y) +
         " mm, Z = " + std::to_string(z) + " mm";
}

std::string wpr(double w, double p, double r) {
  return "W = " + std::to_string(w) + " deg, P = " + std::to_string(p) +
         " deg, R = " + std::to_string(r) + " deg";
}

std::string program(const std::string& main, const std::string& pos) {
  return "/PROG  TEST_PATH\n/ATTR\nOWNER\t\t= MNEDITOR;\nCOMMENT\t\t= \"\";\n/MN\n" + main +
         "/POS\n" + pos + "/END\n";
}

std::string fourPoints() {
  return position(1, xyz(1, 2, 3), wpr(0, 0, 0)) + position(2, xyz(4, 5, 6), wpr(90, 0, 0)) +
         position(3, xyz(7, 8, 9), wpr(0, 90, 0)) + position(4, xyz(10, 11, 12), wpr(90, 0, 90));
}

std::string decodeError(const std::string& text) {
  try {
    decodeFanucLs(text, "p.ls");
  } catch (const IoError& e) {
    return e.what();
  }
  return "";
}

TEST(FanucLsReader, ReadsMotionsFeedsAndToolAxes) {
  const std::string main =
      "   1:  UTOOL_NUM=3 ;\n"
      "   2:  !approach ;\n"
      "   3:J P[1] 100% FINE    ;\n"
      "   4:L P[2] 100mm/sec CNT100    ;\n"
      "   5:L P[3] 60cm/min CNT50 ACC80   ;\n"
      "   6:L P[4] 10inch/min FINE    ;\n"
      "   7:  CALL FOO ;\n"
      "   8:J P[1] 50% CNT100    ;\n"
      "   9:L P[2:\"second\"] 2000mm/sec FINE    ;\n";
  const planning::ClProgram p = decodeFanucLs("\xEF\xBB\xBF" + program(main, fourPoints()), "p.ls");
  EXPECT_EQ(p.partName, "TEST_PATH");
  EXPECT_EQ(p.toolNumber, 3);
  EXPECT_EQ(p.sourceUnit, LengthUnit::Millimetre);
  EXPECT_EQ(p.pointKind, planning::ClPointKind::ToolReference);
  ASSERT_EQ(p.points.size(), 6u);
  const MoveKind moves[] = {MoveKind::Rapid, MoveKind::Cut,   MoveKind::Cut,
                            MoveKind::Cut,   MoveKind::Rapid, MoveKind::Cut};
  const double feeds[] = {0, 6000, 600, 254, 0, 120000};
  const int paths[] = {0, 0, 0, 0, 1, 1};
  const int lines[] = {8, 9, 10, 11, 13, 14};
  for (std::size_t i = 0; i < 6; ++i) {
    EXPECT_EQ(p.points[i].move, moves[i]) << i;
    EXPECT_DOUBLE_EQ(p.points[i].feedMmPerMin, feeds[i]) << i;
    EXPECT_EQ(p.points[i].path, paths[i]) << i;
    EXPECT_EQ(p.points[i].sourceLine, lines[i]) << i;
  }
  EXPECT_EQ(p.points[5].point, 1);
  EXPECT_TRUE(p.points[1].positionMm.isApprox(ddf::Vec3(4, 5, 6), 1e-12));
  // Hand-computed z axes of R = Rz(R) Ry(P) Rx(W): identity; Rx(90) z = -y; Ry(90) z = +x;
  // Rz(90) Rx(90) z = Rz(90) (-y) = +x.
  const ddf::Vec3 axes[] = {ddf::Vec3(0, 0, 1), ddf::Vec3(0, -1, 0), ddf::Vec3(1, 0, 0),
                            ddf::Vec3(1, 0, 0)};
  for (std::size_t i = 0; i < 4; ++i)
    EXPECT_LT((*p.points[i].axis - axes[i]).norm(), 1e-6) << i;  // angles have 6 decimals
  ASSERT_EQ(p.warnings.size(), 1u);
  EXPECT_EQ(p.warnings[0].line, 12);
  EXPECT_THAT(p.warnings[0].text, HasSubstr("CALL FOO"));
  EXPECT_THAT(p.comments, ::testing::Contains("approach"));
  EXPECT_THAT(p.comments, ::testing::Contains("CALL FOO"));
}

TEST(FanucLsReader, ApproximatesCircularMotionAndWarnsAboutMissingFeeds) {
  const std::string main =
      "   1:J P[1] 100% FINE    ;\n"
      "   2:C P[2]    \n"
      "    :  P[3] 100mm/sec FINE    ;\n"
      "   3:L P[4] 30deg/sec FINE Offset,PR[1]   ;\n"
      "   4:L PR[5] 100mm/sec FINE    ;\n";
  const planning::ClProgram p = decodeFanucLs(program(main, fourPoints()), "p.ls");
  ASSERT_EQ(p.points.size(), 4u);
  EXPECT_TRUE(p.points[2].positionMm.isApprox(ddf::Vec3(7, 8, 9), 1e-12));
  EXPECT_DOUBLE_EQ(p.points[2].feedMmPerMin, 6000.0);
  EXPECT_EQ(p.points[3].feedMmPerMin, 0.0);
  std::string all;
  for (const planning::ClMessage& m : p.warnings)
    all += std::to_string(m.line) + ":" + m.text + "\n";
  EXPECT_THAT(all, HasSubstr("7:circular motion approximated"));
  EXPECT_THAT(all, HasSubstr("9:speed '30deg/sec' gives no linear feed"));
  EXPECT_THAT(all, HasSubstr("9:motion option 'Offset,PR[1]' ignored"));
  EXPECT_THAT(all, HasSubstr("10:motion to a position register"));
}

TEST(FanucLsReader, RejectsBadProgramsWithTheLine) {
  const std::string pos = fourPoints();
  EXPECT_THAT(decodeError(program("   1:L P[9] 100mm/sec FINE ;\n", pos)),
              HasSubstr("p.ls: line 6: P[9] is used but has no /POS entry"));
  EXPECT_THAT(decodeError(program("   1:L P[1] 100mm/sec FINE\n   2:L P[2] 1mm/sec FINE ;\n", pos)),
              HasSubstr("line 6: instruction does not end with ';'"));
  EXPECT_THAT(decodeError(program("   1:L P[1] 100furlong/sec FINE ;\n", pos)),
              HasSubstr("line 6: unknown speed unit"));
  EXPECT_THAT(decodeError(program("   1:L P[1] 100mm/sec ;\n", pos)),
              HasSubstr("line 6: motion needs a speed and a termination"));
  EXPECT_THAT(decodeError(program("   1:L P[x] 100mm/sec FINE ;\n", pos)),
              HasSubstr("line 6: bad position number"));
  EXPECT_THAT(decodeError(program("  L P[1] 100mm/sec FINE ;\n", pos)),
              HasSubstr("line 6: expected a numbered instruction"));
  EXPECT_THAT(decodeError("OWNER = X;\n"), HasSubstr("line 1: not a FANUC TP program"));
  EXPECT_THAT(decodeError("/PROG A\n/END\n"), HasSubstr("p.ls: no /MN section"));
  EXPECT_THAT(decodeError(program("   1: !nothing ;\n", pos)), HasSubstr("no motion"));
  const std::string main = "   1:L P[1] 100mm/sec FINE ;\n";
  EXPECT_THAT(decodeError(program(main, pos + position(1, xyz(0, 0, 0), wpr(0, 0, 0)))),
              HasSubstr("P[1] is defined twice"));
  const std::string noR =
      "P[1]{\n GP1:\n UF : 0, X = 1 mm, Y = 2 mm, Z = 3 mm, W = 0 deg, "
      "P = 0 deg\n};\n";
  EXPECT_THAT(decodeError(program(main, noR)), HasSubstr("P[1] has no R value"));
  const std::string joints = "P[1]{\n GP1:\n UF : 0, UT : 1, J1 = 10 deg, J2 = 0 deg\n};\n";
  EXPECT_THAT(decodeError(program(main, joints)), HasSubstr("line 6: P[1] is given in joint"));
  const std::string badUnit =
      "P[1]{\n GP1:\n X = 1 in, Y = 2 mm, Z = 3 mm, W = 0 deg, P = 0 "
      "deg, R = 0 deg\n};\n";
  EXPECT_THAT(decodeError(program(main, badUnit)), HasSubstr("line 10: X must be in mm"));
  EXPECT_THAT(decodeError(program(main, "P[1]{\n GP1:\n X = 1 mm,\n")),
              HasSubstr("position entry does not end"));
  EXPECT_THAT(decodeError(std::string("/PROG A\n\x01\n")), HasSubstr("line 2: control"));
}

TEST(FanucLsReader, WarnsAboutUserFramesAndAMissingEnd) {
  std::string text =
      program("   1:L P[1] 100mm/sec FINE ;\n", position(1, xyz(1, 2, 3), wpr(0, 0, 0), 2));
  text.resize(text.size() - 5);  // drop "/END\n"
  const planning::ClProgram p = decodeFanucLs(text, "p.ls");
  ASSERT_EQ(p.warnings.size(), 2u);
  EXPECT_THAT(p.warnings[0].text, HasSubstr("no /END"));
  EXPECT_THAT(p.warnings[1].text, HasSubstr("user frame 2"));
}

TEST(FanucLsReader, EveryTruncationOfAValidFileReadsOrFailsCleanly) {
  const std::string text =
      program("   1:J P[1] 100% FINE ;\n   2:L P[2] 100mm/sec FINE ;\n", fourPoints());
  for (std::size_t n = 0; n <= text.size(); ++n) {
    try {
      const planning::ClProgram p = decodeFanucLs(text.substr(0, n), "p.ls");
      EXPECT_EQ(p.points.size(), 2u);
    } catch (const IoError&) {
    }
  }
}

}  // namespace
}  // namespace ddfcam::io
