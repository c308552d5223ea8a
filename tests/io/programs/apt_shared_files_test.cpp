// SPDX-License-Identifier: MIT
// The APT reader on every third-party APT file under ../shared/data/paths, checked against an
// independent scan of the raw text (GOTO counts, bounds, units, CIRCLE geometry).
#include <ddfcam/io/programs/apt_reader.h>

#include <gmock/gmock.h>
#include <gtest/gtest.h>

#include <algorithm>
#include <cctype>
#include <cmath>
#include <filesystem>
#include <fstream>
#include <map>
#include <optional>
#include <sstream>
#include <string>
#include <vector>

namespace ddfcam::io {
namespace {

namespace fs = std::filesystem;

const fs::path kPaths = fs::path(DDFCAM_SHARED_DATA_DIR) / "paths";

/// What a plain scan of the raw text finds: one entry per line starting with GOTO or CIRCLE
/// (none of these files continues records), values split at '/' and commas.
struct RawScan {
  std::map<int, std::vector<double>> gotos;    ///< line -> values
  std::map<int, std::vector<double>> circles;  ///< line -> values
  /// line -> the tool axis in force there: the axis of the last 6-value GOTO (APT keeps it
  /// over 3-value ones); none before the first.
  std::map<int, std::optional<ddf::Vec3>> axes;
  int withAxis = 0;  ///< GOTOs with an axis in force
  int sixValue = 0;  ///< GOTOs that give an axis
  ddf::Vec3 lo = ddf::Vec3::Constant(1e300);
  ddf::Vec3 hi = ddf::Vec3::Constant(-1e300);
};

std::vector<double> valuesAfterSlash(const std::string& line) {
  std::vector<double> values;
  std::stringstream in(line.substr(line.find('/') + 1));
  for (std::string item; std::getline(in, item, ',');) values.push_back(std::stod(item));
  return values;
}

RawScan scan(const fs::path& file) {
  RawScan raw;
  std::ifstream in(file);
  int number = 0;
  std::optional<ddf::Vec3> axis;
  for (std::string line; std::getline(in, line);) {
    ++number;
    std::string head = line.substr(0, 6);
    for (char& c : head) c = static_cast<char>(std::toupper(static_cast<unsigned char>(c)));
    if (head.rfind("GOTO", 0) == 0) {
      const std::vector<double> v = valuesAfterSlash(line);
      raw.gotos[number] = v;
      if (v.size() == 6) axis = ddf::Vec3(v[3], v[4], v[5]).normalized();
      raw.sixValue += v.size() == 6;
      raw.axes[number] = axis;
      raw.withAxis += axis.has_value();
      for (int d = 0; d < 3; ++d) {
        raw.lo[d] = std::min(raw.lo[d], v[d]);
        raw.hi[d] = std::max(raw.hi[d], v[d]);
      }
    } else if (head == "CIRCLE") {
      raw.circles[number] = valuesAfterSlash(line);
    }
  }
  return raw;
}

bool warns(const planning::ClProgram& p, const std::string& word) {
  return std::any_of(p.warnings.begin(), p.warnings.end(), [&](const planning::ClMessage& m) {
    return m.text.find("'" + word + "'") != std::string::npos;
  });
}

void expectMatchesRawScan(const planning::ClProgram& p, const RawScan& raw, double per) {
  int gotoPoints = 0;
  int withAxis = 0;
  ddf::Vec3 lo = ddf::Vec3::Constant(1e300);
  ddf::Vec3 hi = ddf::Vec3::Constant(-1e300);
  for (const planning::ClPoint& q : p.points) {
    const auto it = raw.gotos.find(q.sourceLine);
    if (it == raw.gotos.end()) continue;
    ++gotoPoints;
    withAxis += q.axis.has_value();
    const std::optional<ddf::Vec3>& inForce = raw.axes.at(q.sourceLine);
    EXPECT_EQ(q.axis.has_value(), inForce.has_value()) << "line " << q.sourceLine;
    if (q.axis && inForce) EXPECT_LT((*q.axis - *inForce).norm(), 1e-12) << q.sourceLine;
    for (int d = 0; d < 3; ++d) EXPECT_NEAR(q.positionMm[d], it->second[d] * per, 1e-9);
    lo = lo.cwiseMin(q.positionMm);
    hi = hi.cwiseMax(q.positionMm);
  }
  EXPECT_EQ(gotoPoints, static_cast<int>(raw.gotos.size()));
  EXPECT_EQ(withAxis, raw.withAxis);
  EXPECT_NEAR((lo - raw.lo * per).norm(), 0.0, 1e-9);
  EXPECT_NEAR((hi - raw.hi * per).norm(), 0.0, 1e-9);
}

/// Every interpolated CIRCLE point lies at the radius from the centre line, each arc is the
/// short way round (these NX arcs are corner fillets and lead moves), and ends at its GOTO.
void expectArcsOnTheirCircles(const planning::ClProgram& p, const RawScan& raw, double per) {
  std::map<int, int> arcPoints;
  for (std::size_t k = 0; k < p.points.size(); ++k) {
    const auto it = raw.circles.find(p.points[k].sourceLine);
    if (it == raw.circles.end()) continue;
    const std::vector<double>& c = it->second;
    const ddf::Vec3 centre = ddf::Vec3(c[0], c[1], c[2]) * per;
    const ddf::Vec3 axis = ddf::Vec3(c[3], c[4], c[5]).normalized();
    const ddf::Vec3 d = p.points[k].positionMm - centre;
    EXPECT_NEAR((d - d.dot(axis) * axis).norm(), c[6] * per, 1e-9 * c[6] * per);
    ++arcPoints[it->first];
    // The point after the last arc point is the GOTO on the next line.
    if (k + 1 < p.points.size() && p.points[k + 1].sourceLine != it->first) {
      EXPECT_EQ(p.points[k + 1].sourceLine, it->first + 1);
    }
  }
  for (const auto& [line, values] : raw.circles) {
    // A quarter circle at the default 0.005 mm needs at most ceil((pi/2) / step) chords.
    const double r = values[6] * per;
    const double step = 2.0 * std::acos(1.0 - 0.005 / r);
    EXPECT_LE(arcPoints[line], static_cast<int>(std::ceil(M_PI / step))) << "line " << line;
  }
}

TEST(AptSharedFiles, ReadsTheNxVariableAxisFileInInches) {
  const fs::path file = kPaths / "mech491-nx-clsf" / "APT_Variable_Axis.txt";
  const RawScan raw = scan(file);
  ASSERT_EQ(raw.gotos.size(), 348u);
  ASSERT_EQ(raw.sixValue, 329);  // shared/data/README.md
  ASSERT_EQ(raw.withAxis, 348);  // the first GOTO gives one: every later GOTO keeps an axis
  const planning::ClProgram p = readApt(file);
  EXPECT_EQ(p.sourceUnit, LengthUnit::Inch);
  EXPECT_EQ(p.points.size(), 348u);
  expectMatchesRawScan(p, raw, 25.4);
  // Points picked from the raw text: line 10 and line 16.
  EXPECT_NEAR((p.points[0].positionMm - 25.4 * ddf::Vec3(-4.2721, -3.0148, 3.0)).norm(), 0.0, 1e-9);
  EXPECT_NEAR((*p.points[0].axis - ddf::Vec3(-0.3778015, -0.0069217, 0.9258607)).norm(), 0.0, 1e-6);
  EXPECT_EQ(p.points[2].sourceLine, 16);
  EXPECT_NEAR((p.points[2].positionMm - 25.4 * ddf::Vec3(-3.5411, -3.0016, 1.2387)).norm(), 0.0,
              1e-9);
  EXPECT_DOUBLE_EQ(p.points[2].feedMmPerMin, 254.0);
  EXPECT_EQ(p.points[0].move, planning::MoveKind::Rapid);
  EXPECT_TRUE(p.multiAxis());
  ASSERT_TRUE(p.cutter.has_value());
  EXPECT_DOUBLE_EQ(p.cutter->diameterMm, 25.4);
  EXPECT_EQ(p.toolName, "BALL_MILL_1.00");
  EXPECT_TRUE(warns(p, "PAINT"));
  EXPECT_TRUE(warns(p, "TOOL PATH"));
  EXPECT_TRUE(std::any_of(p.warnings.begin(), p.warnings.end(), [](const planning::ClMessage& m) {
    return m.text.find("MSYS") != std::string::npos;
  }));
}

TEST(AptSharedFiles, ReadsTheNxFilesWithCircles) {
  // Paths (cut runs after rapids) counted by an awk scan of the raw text: 15 and 1.
  for (const auto& [name, paths] : std::vector<std::pair<std::string, int>>{
           {"APT_SimpleMillPlane_ZIG.txt", 15}, {"APT_Zig_Zag_Smoothed.txt", 1}}) {
    SCOPED_TRACE(name);
    const fs::path file = kPaths / "mech491-nx-clsf" / name;
    const RawScan raw = scan(file);
    ASSERT_FALSE(raw.circles.empty());
    const planning::ClProgram p = readApt(file);
    EXPECT_EQ(p.sourceUnit, LengthUnit::Millimetre);
    EXPECT_GT(p.points.size(), raw.gotos.size());
    expectMatchesRawScan(p, raw, 1.0);
    expectArcsOnTheirCircles(p, raw, 1.0);
    EXPECT_TRUE(warns(p, "PAINT"));
    EXPECT_TRUE(warns(p, "TOOL PATH"));
    EXPECT_TRUE(warns(p, "LOAD"));
    EXPECT_EQ(p.points.front().move, planning::MoveKind::Rapid);  // RAPID before the first GOTO
    EXPECT_DOUBLE_EQ(p.points.front().feedMmPerMin, 0.0);
    EXPECT_EQ(p.pathCount(), paths);
  }
  EXPECT_EQ(scan(kPaths / "mech491-nx-clsf" / "APT_SimpleMillPlane_ZIG.txt").gotos.size(), 118u);
  EXPECT_EQ(scan(kPaths / "mech491-nx-clsf" / "APT_Zig_Zag_Smoothed.txt").gotos.size(), 75u);
}

TEST(AptSharedFiles, ReadsTheProEClFileInInches) {
  const fs::path file = kPaths / "nist-proe-clfile" / "traj1.ncl";
  const RawScan raw = scan(file);
  const planning::ClProgram p = readApt(file);
  EXPECT_EQ(p.partName, "CORE_WORK");
  EXPECT_EQ(p.sourceUnit, LengthUnit::Inch);
  EXPECT_EQ(p.toolNumber, 8);
  EXPECT_DOUBLE_EQ(p.spindleRpm, 2000.0);
  EXPECT_TRUE(p.spindleClockwise);
  ASSERT_EQ(p.points.size(), raw.gotos.size() + 1);  // FROM + GOTOs
  EXPECT_EQ(p.points[0].move, planning::MoveKind::Rapid);
  EXPECT_NEAR((p.points[0].positionMm - ddf::Vec3(0, 0, 3.775 * 25.4)).norm(), 0.0, 1e-9);
  expectMatchesRawScan(p, raw, 25.4);
  // GOTO / 4.6175, 7.6380, 1.9579 is the first cut, at FEDRAT / 10 IPM.
  EXPECT_EQ(p.points[3].move, planning::MoveKind::Cut);
  EXPECT_NEAR((p.points[3].positionMm - 25.4 * ddf::Vec3(4.6175, 7.6380, 1.9579)).norm(), 0.0,
              1e-9);
  EXPECT_DOUBLE_EQ(p.points[3].feedMmPerMin, 254.0);
  EXPECT_TRUE(warns(p, "MACHIN"));
  EXPECT_FALSE(p.multiAxis());
  // Three passes, each approached by two rapids.
  EXPECT_EQ(p.pathCount(), 3);
  EXPECT_THAT(p.comments, ::testing::Contains("-> CUTTER / 0.375000"));
}

}  // namespace
}  // namespace ddfcam::io
