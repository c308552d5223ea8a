// SPDX-License-Identifier: MIT
// Tests of the tool-path CSV writer and reader: documented layout, units, round trips, the
// common variants, the shared robot path file, errors with line numbers, garbage input.
#include <ddfcam/error.h>
#include <ddfcam/io/programs/tool_path_csv.h>

#include <gmock/gmock.h>
#include <gtest/gtest.h>

#include <clocale>
#include <cmath>
#include <fstream>
#include <locale>
#include <optional>
#include <random>
#include <set>
#include <string>
#include <vector>

#include "../io_test_support.h"

namespace ddfcam::io {
namespace {

using planning::MoveKind;
using ::testing::HasSubstr;

std::vector<std::string> linesOf(const std::string& text) {
  std::vector<std::string> lines;
  for (std::size_t at = 0, end; (end = text.find('\n', at)) != std::string::npos; at = end + 1)
    lines.push_back(text.substr(at, end - at));
  return lines;
}

/// Two hand-made points: a 5-axis cut and a rapid without axis and normal.
planning::ClProgram handMade(planning::ClPointKind kind) {
  planning::ClProgram program;
  program.pointKind = kind;
  planning::ClPoint a;
  a.positionMm = {25.4, -2.0, 0.5};
  a.axis = ddf::Vec3(0, 0.6, 0.8);
  a.normal = ddf::Vec3(0, 0, 1);
  a.feedMmPerMin = 254.0;
  planning::ClPoint b;
  b.path = 1;
  b.point = 3;
  b.positionMm = {0.0, 50.8, -1.25};
  b.move = MoveKind::Rapid;
  program.points = {a, b};
  return program;
}

TEST(ToolPathCsv, HeaderNamesThePointKindAndTheUnits) {
  EXPECT_EQ(toolPathCsvHeader(planning::ClPointKind::Contact),
            "path,point,contact_x_mm,contact_y_mm,contact_z_mm,axis_i,axis_j,axis_k,normal_x,"
            "normal_y,normal_z,feed_mm_per_min,move");
  EXPECT_EQ(toolPathCsvHeader(planning::ClPointKind::ToolReference, LengthUnit::Inch),
            "path,point,tool_x_in,tool_y_in,tool_z_in,axis_i,axis_j,axis_k,normal_x,normal_y,"
            "normal_z,feed_in_per_min,move");
  EXPECT_THAT(toolPathCsvHeader(planning::ClPointKind::Contact, LengthUnit::Metre),
              HasSubstr("contact_z_m,axis_i"));
}

TEST(ToolPathCsv, WritesTheDocumentedColumns) {
  const std::string mm =
      encodeToolPathCsv(handMade(planning::ClPointKind::Contact), {.decimals = 3});
  EXPECT_EQ(mm, toolPathCsvHeader(planning::ClPointKind::Contact) +
                    "\n"
                    "0,0,25.400,-2.000,0.500,0.000,0.600,0.800,0.000,0.000,1.000,254.000,cut\n"
                    "1,3,0.000,50.800,-1.250,,,,,,,0.000,rapid\n");
  const std::string inch = encodeToolPathCsv(handMade(planning::ClPointKind::ToolReference),
                                             {.decimals = 2, .unit = LengthUnit::Inch});
  EXPECT_EQ(linesOf(inch)[1], "0,0,1.00,-0.08,0.02,0.00,0.60,0.80,0.00,0.00,1.00,10.00,cut");
  EXPECT_EQ(linesOf(inch)[2], "1,3,0.00,2.00,-0.05,,,,,,,0.00,rapid");
  EXPECT_THROW(encodeToolPathCsv(handMade(planning::ClPointKind::Contact), {.decimals = 18}),
               InvalidInput);
  EXPECT_THROW(encodeToolPathCsv(handMade(planning::ClPointKind::Contact), {.decimals = -1}),
               InvalidInput);
  planning::ClProgram bad = handMade(planning::ClPointKind::Contact);
  bad.points[1].positionMm.x() = NAN;
  EXPECT_THROW(encodeToolPathCsv(bad), InvalidInput);
}

struct CommaDecimal : std::numpunct<char> {
  char do_decimal_point() const override { return ','; }
  char do_thousands_sep() const override { return '.'; }
  std::string do_grouping() const override { return "\3"; }
};

TEST(ToolPathCsv, DecimalPointIgnoresTheGlobalLocale) {
  // A German-like global locale (comma decimal point, dot grouping); also the C locale of a
  // German system if one is installed.
  const std::locale previous =
      std::locale::global(std::locale(std::locale::classic(), new CommaDecimal));
  const char* german = std::setlocale(LC_ALL, "de_DE.UTF-8");
  const std::string text =
      encodeToolPathCsv(handMade(planning::ClPointKind::Contact), {.decimals = 3});
  const planning::ClProgram back = decodeToolPathCsv(text, "de.csv");
  std::setlocale(LC_ALL, "C");
  std::locale::global(previous);
  EXPECT_THAT(linesOf(text)[1], HasSubstr("25.400,-2.000,0.500"));
  for (const std::string& line : linesOf(text))
    EXPECT_EQ(std::count(line.begin(), line.end(), ','), 12) << line;
  EXPECT_EQ(back.points[1].positionMm, ddf::Vec3(0.0, 50.8, -1.25));
  if (!german) GTEST_LOG_(INFO) << "de_DE.UTF-8 not installed; checked the C++ global locale";
}

/// A random program: 1-4 paths of 1-20 points, all columns exercised.
planning::ClProgram randomProgram(std::mt19937& rng, planning::ClPointKind kind) {
  std::uniform_real_distribution<double> coordinate(-500.0, 500.0), unit(-1.0, 1.0);
  std::uniform_int_distribution<int> count(1, 20), paths(1, 4), move(0, 2), coin(0, 3);
  planning::ClProgram program;
  program.pointKind = kind;
  const int pathCount = paths(rng);
  for (int path = 0; path < pathCount; ++path) {
    const int points = count(rng);
    for (int point = 0; point < points; ++point) {
      planning::ClPoint p;
      p.path = path;
      p.point = point;
      p.positionMm = {coordinate(rng), coordinate(rng), coordinate(rng)};
      if (coin(rng) > 0) p.axis = ddf::Vec3(unit(rng), unit(rng), unit(rng) + 2.0).normalized();
      if (coin(rng) > 0) p.normal = ddf::Vec3(unit(rng) + 2.0, unit(rng), unit(rng)).normalized();
      p.move = static_cast<MoveKind>(move(rng));
      p.feedMmPerMin = p.move == MoveKind::Rapid ? 0.0 : 10000.0 * (unit(rng) + 1.0);
      program.points.push_back(p);
    }
  }
  return program;
}

void expectSameToPrecision(const planning::ClProgram& a, const planning::ClProgram& b,
                           double unitMm, int decimals) {
  const std::vector<std::optional<ddf::Vec3>> axes = test::axesInForce(a);
  ASSERT_EQ(a.points.size(), b.points.size());
  EXPECT_EQ(a.pointKind, b.pointKind);
  const double lengthTolerance = 0.51 * std::pow(10.0, -decimals) * unitMm + 1e-9;
  const double vectorTolerance = 2.0 * std::pow(10.0, -decimals) + 1e-12;
  for (std::size_t i = 0; i < a.points.size(); ++i) {
    const planning::ClPoint& p = a.points[i];
    const planning::ClPoint& q = b.points[i];
    EXPECT_EQ(p.path, q.path) << i;
    EXPECT_EQ(p.point, q.point) << i;
    EXPECT_EQ(p.move, q.move) << i;
    EXPECT_EQ(q.sourceLine, static_cast<int>(i) + 2) << i;
    EXPECT_LE((p.positionMm - q.positionMm).lpNorm<Eigen::Infinity>(), lengthTolerance) << i;
    EXPECT_NEAR(p.feedMmPerMin, q.feedMmPerMin, lengthTolerance) << i;
    // A blank axis cell keeps the axis in force, as APT does.
    const std::optional<ddf::Vec3>& inForce = axes[i];
    ASSERT_EQ(inForce.has_value(), q.axis.has_value()) << i;
    ASSERT_EQ(p.normal.has_value(), q.normal.has_value()) << i;
    if (inForce) {
      EXPECT_LE((*inForce - *q.axis).norm(), vectorTolerance) << i;
    }
    if (p.normal) {
      EXPECT_LE((*p.normal - *q.normal).norm(), vectorTolerance) << i;
    }
  }
}

TEST(ToolPathCsv, RoundTripKeepsTheWrittenPrecision) {
  std::mt19937 rng(7);
  for (const planning::ClPointKind kind :
       {planning::ClPointKind::Contact, planning::ClPointKind::ToolReference})
    for (const LengthUnit unit : {LengthUnit::Millimetre, LengthUnit::Inch, LengthUnit::Metre})
      for (const int decimals : {4, 6, 9}) {
        const planning::ClProgram program = randomProgram(rng, kind);
        // The reader must take the unit from the header, whatever it is told to assume.
        const planning::ClProgram back = decodeToolPathCsv(
            encodeToolPathCsv(program, {.decimals = decimals, .unit = unit}), "t.csv",
            {.unitIfUnstated = LengthUnit::Inch, .kindIfUnstated = planning::ClPointKind::Contact});
        expectSameToPrecision(program, back, millimetresPer(unit), decimals);
        EXPECT_EQ(back.sourceUnit, unit);
        EXPECT_EQ(back.partName, "t");
      }
}

TEST(ToolPathCsv, FileRoundTripAndOneFilePerProgram) {
  test::ScratchDir dir;
  std::mt19937 rng(3);
  const planning::ClProgram program = randomProgram(rng, planning::ClPointKind::Contact);
  writeToolPathCsv(program, dir / "p.csv", {.decimals = 12});
  expectSameToPrecision(program, readToolPathCsv(dir / "p.csv"), 1.0, 12);
  EXPECT_THROW(readToolPathCsv(dir / "missing.csv"), IoError);

  const std::vector<planning::NamedProgram> programs = {
      {"left wing", randomProgram(rng, planning::ClPointKind::Contact)},
      {"left-wing", randomProgram(rng, planning::ClPointKind::Contact)},
      {"left/wing", randomProgram(rng, planning::ClPointKind::Contact)},
      {"", randomProgram(rng, planning::ClPointKind::Contact)}};
  const std::vector<std::filesystem::path> files =
      writeToolPathCsvFiles(programs, dir / "job.csv", {.decimals = 9});
  const std::vector<std::filesystem::path> expected = {
      dir / "job_left_wing.csv", dir / "job_left-wing.csv", dir / "job_left_wing_2.csv",
      dir / "job_program.csv"};
  EXPECT_EQ(files, expected);
  for (std::size_t i = 0; i < files.size(); ++i)
    expectSameToPrecision(programs[i].program, readToolPathCsv(files[i]), 1.0, 9);
  EXPECT_EQ(writeToolPathCsvFiles({programs[0]}, dir / "one.csv"),
            std::vector<std::filesystem::path>{dir / "one.csv"});
  EXPECT_TRUE(std::filesystem::exists(dir / "one.csv"));
  EXPECT_THROW(writeToolPathCsvFiles({}, dir / "none.csv"), InvalidInput);
}

TEST(ToolPathCsv, ReadsThreeAndSixColumnVariantsWithAnyDelimiter) {
  const planning::ClProgram blanks = decodeToolPathCsv("1 2 3\n  4\t5   6.5e1\n", "b.xyz");
  ASSERT_EQ(blanks.points.size(), 2u);
  EXPECT_EQ(blanks.points[1].positionMm, ddf::Vec3(4, 5, 65));
  EXPECT_EQ(blanks.points[1].point, 1);
  EXPECT_EQ(blanks.points[1].sourceLine, 2);
  EXPECT_FALSE(blanks.points[0].axis.has_value());
  EXPECT_EQ(blanks.pointKind, planning::ClPointKind::ToolReference);
  EXPECT_EQ(blanks.partName, "b");

  const planning::ClProgram semicolons =
      decodeToolPathCsv("X;Y;Z;I;J;K\r\n1;2;3;0;0;2\r\n\r\n+1.5;-2;3e-1;3;4;0\r\n", "s.csv");
  ASSERT_EQ(semicolons.points.size(), 2u);
  EXPECT_EQ(*semicolons.points[0].axis, ddf::Vec3(0, 0, 1));  // normalised
  EXPECT_LT((*semicolons.points[1].axis - ddf::Vec3(0.6, 0.8, 0)).norm(), 1e-15);
  EXPECT_EQ(semicolons.points[1].positionMm, ddf::Vec3(1.5, -2, 0.3));
  EXPECT_EQ(semicolons.points[1].sourceLine, 4);

  const planning::ClProgram tabs =
      decodeToolPathCsv("x\ty\tz\n1\t2\t3\n", "t.tsv", {.unitIfUnstated = LengthUnit::Inch});
  EXPECT_LT((tabs.points[0].positionMm - ddf::Vec3(25.4, 50.8, 76.2)).norm(), 1e-12);
  EXPECT_EQ(tabs.sourceUnit, LengthUnit::Inch);

  const planning::ClProgram headerless = decodeToolPathCsv("1,2,3,0,1,0\n", "h.csv");
  EXPECT_EQ(*headerless.points[0].axis, ddf::Vec3(0, 1, 0));
}

TEST(ToolPathCsv, ReadsPathColumnsCommentsAndUnitsFromTheHeader) {
  const std::string text =
      "\xEF\xBB\xBF# exported by a robot cell\n"
      "\n"
      "path_index, x [m], y [m], z [m], quality\n"
      "7, 0.001, 0.002, 0.003, good   # inline remark\n"
      "7, 0.004, 0.005, 0.006, good\n"
      "  # between paths\n"
      "3, 0.007, 0.008, 0.009, bad\n"
      "7, 0.010, 0.011, 0.012, good\n";
  const planning::ClProgram program = decodeToolPathCsv(text, "robot.csv");
  ASSERT_EQ(program.points.size(), 4u);
  EXPECT_EQ(program.sourceUnit, LengthUnit::Metre);
  EXPECT_LT((program.points[0].positionMm - ddf::Vec3(1, 2, 3)).norm(), 1e-12);
  EXPECT_EQ(program.points[2].path, 1);  // 7 -> 0, 3 -> 1, in order of appearance
  EXPECT_EQ(program.points[3].path, 0);
  EXPECT_EQ(program.points[3].point, 2);
  EXPECT_EQ(program.points[2].point, 0);
  EXPECT_EQ(program.points[2].sourceLine, 7);
  EXPECT_EQ(program.comments,
            (std::vector<std::string>{"exported by a robot cell", "between paths"}));
  ASSERT_EQ(program.warnings.size(), 1u);
  EXPECT_EQ(program.warnings[0].line, 3);
  EXPECT_THAT(program.warnings[0].text, HasSubstr("'quality'"));

  const planning::ClProgram four = decodeToolPathCsv("2 1 1 1\n2 2 2 2\n5 3 3 3\n", "four.txt");
  EXPECT_EQ(four.pathCount(), 2);
  EXPECT_EQ(four.points[2].positionMm, ddf::Vec3(3, 3, 3));

  const planning::ClProgram own = decodeToolPathCsv(
      "path,point,contact_x_in,contact_y_in,contact_z_in,normal_x,normal_y,normal_z,"
      "feed_in_per_min,move\n0,0,1,2,3,0,0,5,10,LINK\n",
      "own.csv", {.unitIfUnstated = LengthUnit::Metre});
  EXPECT_EQ(own.pointKind, planning::ClPointKind::Contact);
  EXPECT_EQ(own.sourceUnit, LengthUnit::Inch);
  EXPECT_LT((own.points[0].positionMm - ddf::Vec3(25.4, 50.8, 76.2)).norm(), 1e-12);
  EXPECT_EQ(*own.points[0].normal, ddf::Vec3(0, 0, 1));
  EXPECT_DOUBLE_EQ(own.points[0].feedMmPerMin, 254.0);
  EXPECT_EQ(own.points[0].move, MoveKind::Link);
  EXPECT_FALSE(own.points[0].axis.has_value());
}

TEST(ToolPathCsv, ReadsTheSharedRoboticSandingPath) {
  const std::filesystem::path file = std::filesystem::path(DDFCAM_SHARED_DATA_DIR) / "paths" /
                                     "crs-robotic-sanding" / "part_2_job_0_degrees.xyzijk.csv";
  if (!std::filesystem::exists(file)) GTEST_SKIP() << file << " is absent (shared data)";
  const planning::ClProgram program = readToolPathCsv(file, {.unitIfUnstated = LengthUnit::Metre});
  ASSERT_EQ(program.points.size(), 98u);
  EXPECT_EQ(program.pathCount(), 7);
  EXPECT_EQ(program.sourceUnit, LengthUnit::Metre);
  EXPECT_EQ(program.comments.size(), 1u);
  std::set<int> paths;
  for (const planning::ClPoint& p : program.points) {
    ASSERT_TRUE(p.axis.has_value());
    EXPECT_NEAR(p.axis->norm(), 1.0, 1e-12);
    EXPECT_LT(p.positionMm.norm(), 2000.0);  // metres read as millimetres
    paths.insert(p.path);
  }
  EXPECT_EQ(paths, (std::set<int>{0, 1, 2, 3, 4, 5, 6}));
  // First row of the file (line 2): 0,0.605343,-0.122467,-0.052194,0.096173,-0.164257,0.981718
  const planning::ClPoint& first = program.points.front();
  EXPECT_EQ(first.sourceLine, 2);
  EXPECT_LT((first.positionMm - ddf::Vec3(605.343, -122.467, -52.194)).norm(), 1e-9);
  EXPECT_LT((*first.axis - ddf::Vec3(0.096173, -0.164257, 0.981718).normalized()).norm(), 1e-12);
  EXPECT_EQ(program.points.back().sourceLine, 99);
}

/// The message of the IoError @p text raises (empty if none).
std::string errorOf(const std::string& text, const CsvReadParams& params = {}) {
  try {
    decodeToolPathCsv(text, "bad.csv", params);
  } catch (const IoError& e) {
    return e.what();
  }
  return {};
}

TEST(ToolPathCsv, BadInputNamesTheLine) {
  const std::string own = toolPathCsvHeader(planning::ClPointKind::Contact) + "\n";
  const std::string row = "0,0,1,2,3,0,0,1,0,0,1,100,cut\n";
  const std::vector<std::pair<std::string, std::string>> cases = {
      {"x,y,z\n1,2,3\n1,2\n", "bad.csv: line 3: 2 fields, expected 3"},
      {"x,y,z\n1,2,3\n1,zwei,3\n", "line 3: field 2 ('zwei') is not a number"},
      {"1;2,5;3\n", "line 1: field 2 ('2,5') is not a number (decimal comma"},
      {"x y z i j k\n\n1 2 3 0 0 0\n", "line 3: the axis vector is zero"},
      {"x,y,z,i,j,k\n1,2,3,nan,0,1\n", "line 2: field 4 ('nan') is not finite"},
      {"x,y,z,i,j,k\n1,2,3,inf,0,1\n", "line 2: field 4 ('inf') is not finite"},
      {"x,y,z,i,j,k\n1,2,3,,0,1\n", "line 2: the axis has 2 of 3 values"},
      {own + row + "0,1,1,2,3,0,0,1,0,0,1,100,plunge\n", "line 3: field 13 ('plunge') is not a"},
      {own + row + "-1,1,1,2,3,0,0,1,0,0,1,100,cut\n", "line 3: field 1 ('-1') is not a non-neg"},
      {own + row + "0,0,1,2,3,0,0,1,0,0,0,100,cut\n", "line 3: the normal vector is zero"},
      {"x,y,i,j,k\n", "line 1: header: the header has 2 of the 3 x y z columns"},
      {"x,y,z,x\n", "line 1: header: column 'x' names a quantity"},
      {"x [ft],y,z\n", "line 1: header: column 'x [ft]': unknown unit 'ft'"},
      {"# only\n\n", "bad.csv: no header and no data row"},
      {"", "bad.csv: no header and no data row"},
      {"1,2,3,4,5\n", "line 1: 5 fields and no header; expected 3 (x,y,z)"},
      {std::string("x,y,z\n1,2,3\n4,5\0,6\n", 19), "line 3: control character 0x00"},
      {std::string("x,y,z\n1,2,3\n\x01\x02\x03\n"), "line 3: control character 0x01"},
      {"x,y,z\n1,2,3\n4,5,6\n7,8,9\n", "line 4: more than 2 rows"},
  };
  for (const auto& [text, expected] : cases)
    EXPECT_THAT(errorOf(text, {.maxRows = 2}), HasSubstr(expected)) << "input: " << text;
  // A header alone holds no path: an error like every other reader's empty program, not an
  // empty program that downstream would turn into an empty G-code file.
  EXPECT_THAT([&] { decodeToolPathCsv(own, "h.csv"); },
              ::testing::ThrowsMessage<IoError>(HasSubstr("h.csv: a header but no data row")));
}

TEST(ToolPathCsv, GarbageNeverCrashesTheReader) {
  // Random bytes, and valid files with bytes flipped, cut or duplicated: only IoError.
  std::mt19937 rng(5);
  std::uniform_int_distribution<int> byte(0, 255), length(0, 200);
  const std::string valid = encodeToolPathCsv(randomProgram(rng, planning::ClPointKind::Contact)) +
                            "x,y,z\n1 2 3\n# c\n;;;\n,,,,,,\n";
  const std::string alphabet = "0123456789.,;-+eE \t\n\r#xyzijkpathcutlinkrapidnanINF\"";
  std::uniform_int_distribution<std::size_t> pick(0, alphabet.size() - 1);
  for (int trial = 0; trial < 3000; ++trial) {
    std::string text;
    if (trial % 3 == 0) {
      for (int i = length(rng); i > 0; --i) text += static_cast<char>(byte(rng));
    } else if (trial % 3 == 1) {
      for (int i = length(rng); i > 0; --i) text += alphabet[pick(rng)];
    } else {
      text = valid;
      std::uniform_int_distribution<std::size_t> at(0, text.size() - 1);
      for (int i = 0; i < 4; ++i) text[at(rng)] = alphabet[pick(rng)];
      text.resize(at(rng));
    }
    try {
      const planning::ClProgram program = decodeToolPathCsv(text, "garbage.csv");
      for (const planning::ClPoint& p : program.points) {
        EXPECT_TRUE(p.positionMm.allFinite());
        EXPECT_GE(p.path, 0);
        if (p.axis) {
          EXPECT_NEAR(p.axis->norm(), 1.0, 1e-9);
        }
      }
    } catch (const IoError&) {
    }
  }
}

}  // namespace
}  // namespace ddfcam::io
