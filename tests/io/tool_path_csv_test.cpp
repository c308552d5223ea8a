// SPDX-License-Identifier: MIT
// Tests of the tool-path CSV writer and reader: documented layout, round trips, errors.
#include <ddfcam/error.h>
#include <ddfcam/io/tool_path_csv.h>
#include <ddfcam/planning/path_linking.h>
#include <ddfcam/planning/tool_placement.h>

#include <gmock/gmock.h>
#include <gtest/gtest.h>

#include <Eigen/Geometry>

#include <cmath>
#include <locale>
#include <random>
#include <string>

#include "io_test_support.h"

namespace ddfcam::io {
namespace {

using ::testing::HasSubstr;

planning::PathPose poseAt(const ddf::Vec3& contact, const ddf::Vec3& normal, double liftMm,
                          const Eigen::Matrix3d& rotation = Eigen::Matrix3d::Identity()) {
  planning::PathPose pose;
  pose.pose.linear() = rotation;
  pose.pose.translation() = contact + liftMm * normal.normalized();
  pose.contact = contact;
  return pose;
}

/// Two passes (2 and 1 poses) over the plane z = 0.5, the tool 3 mm above its contact.
planning::ToolPath twoPasses() {
  planning::ToolPath path;
  path.name = "two";
  path.feedMmPerMin = 1500.0;
  const Eigen::Matrix3d quarter = Eigen::AngleAxisd(M_PI / 2, ddf::Vec3::UnitZ()).matrix();
  path.poses = {poseAt({1, 2, 0.5}, {0, 0, 1}, 3.0), poseAt({1.25, 2, 0.5}, {0, 0, 1}, 3.0),
                poseAt({-1, 0.125, 0.5}, {0, 0, 1}, 3.0, quarter)};
  path.passStarts = {0, 2};
  return path;
}

std::vector<std::string> linesOf(const std::string& text) {
  std::vector<std::string> lines;
  for (std::size_t at = 0, end; (end = text.find('\n', at)) != std::string::npos; at = end + 1)
    lines.push_back(text.substr(at, end - at));
  return lines;
}

TEST(ToolPathCsv, WritesTheDocumentedColumns) {
  const ToolPathCsv table = toolPathCsvRows(twoPasses(), CsvPointKind::Contact);
  const std::vector<std::string> lines = linesOf(encodeToolPathCsv(table, {.decimals = 3}));
  ASSERT_EQ(lines.size(), 4u);
  EXPECT_EQ(lines[0],
            "path,point,contact_x_mm,contact_y_mm,contact_z_mm,axis_i,axis_j,axis_k,normal_x,"
            "normal_y,normal_z,feed_mm_per_min,move");
  EXPECT_EQ(lines[1], "0,0,1.000,2.000,0.500,1.000,0.000,0.000,0.000,0.000,1.000,1500.000,cut");
  EXPECT_EQ(lines[2], "0,1,1.250,2.000,0.500,1.000,0.000,0.000,0.000,0.000,1.000,1500.000,cut");
  // The second pass restarts the point count; the rotated tool's +x is the part's +y.
  EXPECT_EQ(lines[3], "1,0,-1.000,0.125,0.500,0.000,1.000,0.000,0.000,0.000,1.000,1500.000,cut");
  const ToolPathCsv reference = toolPathCsvRows(twoPasses(), CsvPointKind::ToolReference);
  const std::vector<std::string> refLines = linesOf(encodeToolPathCsv(reference, {.decimals = 1}));
  EXPECT_THAT(refLines[0], HasSubstr("path,point,tool_x_mm,tool_y_mm,tool_z_mm,axis_i"));
  EXPECT_EQ(refLines[1], "0,0,1.0,2.0,3.5,1.0,0.0,0.0,0.0,0.0,1.0,1500.0,cut");
  EXPECT_EQ(linesOf(encodeToolPathCsv(table, {.decimals = 0}))[3],
            "1,0,-1,0,0,0,1,0,0,0,1,1500,cut");
}

struct CommaDecimal : std::numpunct<char> {
  char do_decimal_point() const override { return ','; }
};

TEST(ToolPathCsv, DecimalPointIgnoresTheGlobalLocale) {
  const std::locale previous =
      std::locale::global(std::locale(std::locale::classic(), new CommaDecimal));
  const std::string text = encodeToolPathCsv(toolPathCsvRows(twoPasses(), CsvPointKind::Contact));
  std::locale::global(previous);
  EXPECT_THAT(linesOf(text)[1], HasSubstr("1.000000,2.000000,0.500000"));
}

TEST(ToolPathCsv, ExplicitNormalsAndErrors) {
  const planning::ToolPath path = twoPasses();
  const std::vector<ddf::Vec3> normals = {{1, 0, 0}, {0, 1, 0}, {0, 0, -1}};
  const ToolPathCsv table = toolPathCsvRows(path, CsvPointKind::Contact, normals);
  EXPECT_EQ(table.rows[1].normal, ddf::Vec3(0, 1, 0));
  EXPECT_THROW(toolPathCsvRows(path, CsvPointKind::Contact, {{1, 0, 0}}), InvalidInput);
  planning::ToolPath flat = path;
  flat.poses[2].contact = flat.poses[2].pose.translation();
  EXPECT_THROW(toolPathCsvRows(flat, CsvPointKind::Contact), InvalidInput);
  EXPECT_THROW(encodeToolPathCsv(table, {.decimals = 18}), InvalidInput);
  EXPECT_THROW(encodeToolPathCsv(table, {.decimals = -1}), InvalidInput);
}

ToolPathCsv randomTable(std::mt19937& rng, CsvPointKind kind) {
  std::uniform_real_distribution<double> coord(-500.0, 500.0), unit(-1.0, 1.0);
  ToolPathCsv table{kind, {}};
  for (int i = 0; i < 200; ++i) {
    ToolPathCsvRow row;
    row.path = i / 17;
    row.point = i % 17;
    row.position = {coord(rng), coord(rng), coord(rng)};
    row.toolAxis = ddf::Vec3(unit(rng), unit(rng), unit(rng)).normalized();
    row.normal = ddf::Vec3(unit(rng), unit(rng), unit(rng)).normalized();
    row.feedMmPerMin = 100.0 * (i % 5);
    row.move = static_cast<planning::MoveKind>(i % 3);
    table.rows.push_back(row);
  }
  return table;
}

TEST(ToolPathCsv, RoundTripKeepsTheWrittenPrecision) {
  std::mt19937 rng(7);
  for (const CsvPointKind kind : {CsvPointKind::Contact, CsvPointKind::ToolReference})
    for (const int decimals : {0, 3, 6, 12}) {
      const ToolPathCsv table = randomTable(rng, kind);
      const ToolPathCsv back =
          decodeToolPathCsv(encodeToolPathCsv(table, {.decimals = decimals}), "t.csv");
      ASSERT_EQ(back.pointKind, kind);
      ASSERT_EQ(back.rows.size(), table.rows.size());
      // Rounding to d decimals moves a value by at most half a unit in the last place (plus
      // the double's own rounding of values up to 500).
      const double tolerance = 0.5 * std::pow(10.0, -decimals) + 1e-12;
      for (std::size_t r = 0; r < table.rows.size(); ++r) {
        const ToolPathCsvRow& a = table.rows[r];
        const ToolPathCsvRow& b = back.rows[r];
        EXPECT_EQ(a.path, b.path);
        EXPECT_EQ(a.point, b.point);
        EXPECT_EQ(a.move, b.move);
        EXPECT_LE((a.position - b.position).cwiseAbs().maxCoeff(), tolerance) << r;
        EXPECT_LE((a.toolAxis - b.toolAxis).cwiseAbs().maxCoeff(), tolerance) << r;
        EXPECT_LE((a.normal - b.normal).cwiseAbs().maxCoeff(), tolerance) << r;
        EXPECT_NEAR(a.feedMmPerMin, b.feedMmPerMin, tolerance) << r;
      }
    }
}

TEST(ToolPathCsv, FileRoundTripAndWindowsLineEnds) {
  test::ScratchDir dir;
  std::mt19937 rng(11);
  const ToolPathCsv table = randomTable(rng, CsvPointKind::Contact);
  writeToolPathCsv(table, dir / "p.csv", {.decimals = 17});
  const ToolPathCsv back = readToolPathCsv(dir / "p.csv");
  ASSERT_EQ(back.rows.size(), table.rows.size());
  // 17 decimals of values below 500 keep every bit a double has there.
  EXPECT_EQ(back.rows[5].position, table.rows[5].position);
  std::string crlf;
  for (const std::string& line : linesOf(encodeToolPathCsv(table))) crlf += line + "\r\n";
  EXPECT_EQ(decodeToolPathCsv(crlf, "w.csv").rows.size(), table.rows.size());
}

std::string readError(const std::string& text) {
  try {
    decodeToolPathCsv(text, "bad.csv");
  } catch (const IoError& e) {
    return e.what();
  }
  ADD_FAILURE() << "no IoError for:\n" << text;
  return {};
}

TEST(ToolPathCsv, BadInputNamesTheLine) {
  const std::string header = toolPathCsvHeader(CsvPointKind::Contact) + "\n";
  const std::string good = "0,0,1,2,3,1,0,0,0,0,1,1000,cut\n";
  EXPECT_THAT(readError(""), HasSubstr("bad.csv: empty file"));
  EXPECT_THAT(readError("x,y,z\n" + good), HasSubstr("bad.csv: line 1: not a ddfcam tool-path"));
  EXPECT_THAT(readError(header + good + "0,1,1,2,3\n"),
              HasSubstr("bad.csv: line 3: 5 fields, expected 13"));
  EXPECT_THAT(readError(header + "0,0,1,2,abc,1,0,0,0,0,1,1000,cut\n"),
              HasSubstr("line 2: column 5 (x y z): 'abc' is not a number"));
  EXPECT_THAT(readError(header + "0,0,1,2,3,1,0,0,0,0,1,1.5.1,cut\n"),
              HasSubstr("line 2: column 12 (feed): '1.5.1' is not a number"));
  EXPECT_THAT(readError(header + "-1,0,1,2,3,1,0,0,0,0,1,1000,cut\n"),
              HasSubstr("line 2: column 1 (path): '-1' is not a non-negative integer"));
  EXPECT_THAT(readError(header + good + good + "0,2,1,2,3,1,0,0,0,0,1,1000,plunge\n"),
              HasSubstr("line 4: column 13 (move): 'plunge' is not cut, link or rapid"));
  EXPECT_THAT(readError(header + good + "\n" + good), HasSubstr("line 3: 1 fields"));
  EXPECT_THAT(readError(header + "0,0,1,2,,1,0,0,0,0,1,1000,cut\n"), HasSubstr("column 5"));
  test::ScratchDir dir;
  EXPECT_THROW(readToolPathCsv(dir / "missing.csv"), IoError);
  EXPECT_TRUE(decodeToolPathCsv(header, "h.csv").rows.empty());
}

TEST(ToolPathCsv, LinkedMovesCarryTypesFeedsAndTheLastCutsOrientation) {
  // Three parallel lines along x on the plane z = 0, 2 mm apart; every link lifts.
  std::vector<std::vector<ddf::Vec3>> lines;
  planning::ToolPath path;
  path.feedMmPerMin = 800.0;
  for (int l = 0; l < 3; ++l) {
    lines.emplace_back();
    path.passStarts.push_back(static_cast<int>(path.poses.size()));
    for (int i = 0; i <= 4; ++i) {
      const ddf::Vec3 contact(2.5 * i, 2.0 * l, 0.0);
      lines.back().push_back(contact);
      planning::PathPose pose;
      pose.pose =
          planning::rollPoseAtContact(contact, ddf::Vec3::UnitZ(), ddf::Vec3::UnitX(), 5.0, 0.0);
      pose.contact = contact;
      path.poses.push_back(pose);
    }
  }
  const planning::LinkedPaths linked =
      planning::linkPaths(lines, planning::LinkingParams{.clearanceMm = 2.0});
  for (const CsvPointKind kind : {CsvPointKind::Contact, CsvPointKind::ToolReference}) {
    const ToolPathCsv table = linkedToolPathCsvRows(linked, path, kind);
    std::size_t row = 0;
    for (std::size_t m = 0; m < linked.moves.size(); ++m) {
      const planning::PathMove& move = linked.moves[m];
      for (std::size_t i = 0; i < move.points.size(); ++i, ++row) {
        ASSERT_LT(row, table.rows.size());
        const ToolPathCsvRow& r = table.rows[row];
        EXPECT_EQ(r.path, static_cast<int>(m));
        EXPECT_EQ(r.point, static_cast<int>(i));
        EXPECT_EQ(r.move, move.kind);
        EXPECT_EQ(r.feedMmPerMin, move.kind == planning::MoveKind::Rapid ? 0.0 : 800.0);
        // A roll touching z = 0 from above: centre 5 mm up, axis across the feed (along y).
        const ddf::Vec3 expected =
            move.points[i] + ddf::Vec3(0, 0, kind == CsvPointKind::Contact ? 0 : 5);
        EXPECT_LT((r.position - expected).norm(), 1e-9) << "move " << m << " point " << i;
        EXPECT_LT((r.normal - ddf::Vec3::UnitZ()).norm(), 1e-9);
        EXPECT_NEAR(std::abs(r.toolAxis.y()), 1.0, 1e-9);
      }
    }
    EXPECT_EQ(row, table.rows.size());
  }
  EXPECT_GT(linked.liftedLinkCount, 0);
  planning::LinkedPaths broken = linked;
  broken.moves[0].points[1].x() += 0.1;
  EXPECT_THROW(linkedToolPathCsvRows(broken, path, CsvPointKind::Contact), InvalidInput);
  broken = linked;
  broken.moves[0].path = 3;
  EXPECT_THROW(linkedToolPathCsvRows(broken, path, CsvPointKind::Contact), InvalidInput);
}

}  // namespace
}  // namespace ddfcam::io
