// SPDX-License-Identifier: MIT
// Every file under shared/data/paths/ through the path-file dispatcher, against oracles taken
// from the raw text, the derived CSV and the part mesh the robot path was planned on.
#include <ddfcam/error.h>
#include <ddfcam/io/mesh/mesh_io.h>
#include <ddfcam/io/programs/path_file.h>

#include <gmock/gmock.h>
#include <gtest/gtest.h>

#include <algorithm>
#include <cctype>
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <filesystem>
#include <map>
#include <numbers>
#include <set>
#include <string>
#include <vector>

#include "../io_test_support.h"

namespace ddfcam::io {
namespace {

using planning::MoveKind;
using ::testing::HasSubstr;
namespace fs = std::filesystem;

const fs::path kRoot = fs::path(DDFCAM_SHARED_DATA_DIR) / "paths";
const char* const kYaml = "crs-robotic-sanding/part_2_job_0_degrees.yaml";
const char* const kCsv = "crs-robotic-sanding/part_2_job_0_degrees.xyzijk.csv";
const char* const kLs = "crs-robotic-sanding/surface_cartesian.ls";
const char* const kStl = "crs-robotic-sanding/part_2.stl";
/// NX's Haas UMC-750 post of APT_Variable_Axis.txt: G-code, recognised by its content.
const char* const kPosted = "mech491-nx-clsf/PostProcessed_Variable_Axis.txt";

/// APT files with the unit their header or first FEDRAT gives (see shared/data/README.md).
const std::map<std::string, LengthUnit> kAptFiles = {
    {"mech491-nx-clsf/APT_Variable_Axis.txt", LengthUnit::Inch},
    {"mech491-nx-clsf/APT_Zig_Zag_Smoothed.txt", LengthUnit::Millimetre},
    {"mech491-nx-clsf/APT_SimpleMillPlane_ZIG.txt", LengthUnit::Millimetre},
    {"nist-proe-clfile/traj1.ncl", LengthUnit::Inch}};

/// Files that are not tool paths; readPathFile must say so.
const std::set<std::string> kNotPaths = {"crs-robotic-sanding/package.xml",
                                         "crs-robotic-sanding/part_2_crs.yaml",
                                         "mech491-nx-clsf/LICENSE", kStl};

std::string notAPathMessage(const fs::path& file) {
  return file.string() +
         ": not a tool-path file (expected CSV, APT/CLDATA, ROS toolpath YAML or FANUC .ls)";
}

#define SKIP_WITHOUT_SHARED_DATA() \
  if (!fs::exists(kRoot)) GTEST_SKIP() << "shared data not found at " << kRoot

TEST(SharedPaths, EveryFileIsReadOrKnownNotToBeAToolPath) {
  SKIP_WITHOUT_SHARED_DATA();
  std::set<std::string> seen;
  for (const fs::directory_entry& entry : fs::recursive_directory_iterator(kRoot)) {
    if (!entry.is_regular_file()) continue;
    const std::string name = fs::relative(entry.path(), kRoot).generic_string();
    seen.insert(name);
    SCOPED_TRACE(name);
    if (kNotPaths.count(name)) {
      EXPECT_EQ(test::ioErrorMessage([&] { readPathFile(entry.path()); }),
                notAPathMessage(entry.path()));
    } else if (kAptFiles.count(name) || name == kYaml || name == kLs) {
      EXPECT_GT(readPathFile(entry.path()).program.points.size(), 0u);
    } else if (name == kPosted) {
      EXPECT_EQ(detectPathFormat(entry.path(), test::readBytes(entry.path())), PathFormat::GCode);
      EXPECT_THAT(test::ioErrorMessage([&] { readPathFile(entry.path()); }),
                  HasSubstr(": G-code cannot be read"));
    } else if (name == kCsv) {
      PathReadParams params;
      params.csv.unitIfUnstated = LengthUnit::Metre;
      EXPECT_EQ(readPathFile(entry.path(), params).program.points.size(), 98u);
    } else {
      ADD_FAILURE() << "new file under shared/data/paths: add it and its oracle to this test";
    }
  }
  for (const auto& [name, unit] : kAptFiles) EXPECT_TRUE(seen.count(name)) << name;
  for (const std::string& name : kNotPaths) EXPECT_TRUE(seen.count(name)) << name;
  for (const char* name : {kYaml, kCsv, kLs, kPosted}) EXPECT_TRUE(seen.count(name)) << name;
  // The part mesh is a mesh: mesh_io reads it.
  EXPECT_GT(readMesh(kRoot / kStl).triangles.size(), 1000u);
}

// ---- the ROS sanding path: YAML against the derived CSV and the part mesh ----

TEST(SharedPaths, RosYamlMatchesTheDerivedCsvAndTheRawText) {
  SKIP_WITHOUT_SHARED_DATA();
  const planning::ClProgram yaml = readPathFile(kRoot / kYaml).program;
  PathReadParams params;
  params.csv.unitIfUnstated = LengthUnit::Metre;
  const planning::ClProgram csv = readPathFile(kRoot / kCsv, params).program;
  ASSERT_EQ(yaml.points.size(), 98u);
  ASSERT_EQ(csv.points.size(), 98u);
  EXPECT_EQ(yaml.pathCount(), 7);
  EXPECT_EQ(csv.pathCount(), 7);
  EXPECT_EQ(yaml.sourceUnit, LengthUnit::Metre);
  EXPECT_EQ(yaml.pointKind, planning::ClPointKind::ToolReference);
  // The derived CSV is the YAML's poses, pose for pose: same path and point indices, and the
  // tool z axis (the quaternion applied to +Z) as i,j,k.
  std::vector<int> yamlSizes(7, 0), csvSizes(7, 0);
  for (std::size_t i = 0; i < 98; ++i) {
    const planning::ClPoint& a = yaml.points[i];
    const planning::ClPoint& b = csv.points[i];
    ASSERT_TRUE(a.path >= 0 && a.path < 7 && b.path >= 0 && b.path < 7) << i;
    EXPECT_EQ(a.path, b.path) << i;
    EXPECT_EQ(a.point, yamlSizes[a.path]++) << i;
    EXPECT_EQ(b.point, csvSizes[b.path]++) << i;
    EXPECT_EQ(a.move, MoveKind::Cut);
    // The CSV has 6 decimals in metres: 5e-4 mm of rounding.
    EXPECT_LE((a.positionMm - b.positionMm).cwiseAbs().maxCoeff(), 1e-3) << i;
    ASSERT_TRUE(a.axis && b.axis) << i;
    EXPECT_LE((*a.axis - *b.axis).cwiseAbs().maxCoeff(), 2e-6) << i;
  }
  // Raw text: 7 "poses:" lists, 98 "- position:" items; the first pose's coordinates.
  const std::string text = test::readBytes(kRoot / kYaml);
  auto count = [&](const std::string& word) {
    std::size_t n = 0;
    for (std::size_t at = text.find(word); at != std::string::npos; at = text.find(word, at + 1))
      ++n;
    return n;
  };
  EXPECT_EQ(yamlSizes, std::vector<int>(7, 14));
  EXPECT_EQ(csvSizes, std::vector<int>(7, 14));
  EXPECT_EQ(count("poses:"), 7u);
  std::vector<int> rawSizes;  // "- position:" items per "poses:" list
  for (std::size_t at = text.find("poses:"); at != std::string::npos;) {
    const std::size_t next = text.find("poses:", at + 1);
    const std::size_t stop = next == std::string::npos ? text.size() : next;
    int n = 0;
    for (std::size_t p = text.find("- position:", at); p < stop;
         p = text.find("- position:", p + 1))
      ++n;
    rawSizes.push_back(n);
    at = next;
  }
  EXPECT_EQ(rawSizes, yamlSizes);
  EXPECT_EQ(count("- position:"), 98u);
  EXPECT_EQ(count("orientation:"), 98u + 1u);    // and the tool_offset of the process parameters
  auto rawValue = [&](const std::string& key) {  // first "key:" after the first position
    const std::size_t at = text.find(key + ": ", text.find("position:"));
    return std::strtod(text.c_str() + at + key.size() + 2, nullptr);
  };
  EXPECT_DOUBLE_EQ(yaml.points[0].positionMm.x(), rawValue("x") * 1000.0);
  EXPECT_DOUBLE_EQ(yaml.points[0].positionMm.y(), rawValue("y") * 1000.0);
  EXPECT_DOUBLE_EQ(yaml.points[0].positionMm.z(), rawValue("z") * 1000.0);
}

/// Distance from @p p to triangle (a, b, c) (Ericson, Real-Time Collision Detection 5.1.5).
double pointTriangleDistance(const ddf::Vec3& p, const ddf::Vec3& a, const ddf::Vec3& b,
                             const ddf::Vec3& c) {
  const ddf::Vec3 ab = b - a, ac = c - a, ap = p - a;
  const double d1 = ab.dot(ap), d2 = ac.dot(ap);
  if (d1 <= 0 && d2 <= 0) return ap.norm();
  const ddf::Vec3 bp = p - b;
  const double d3 = ab.dot(bp), d4 = ac.dot(bp);
  if (d3 >= 0 && d4 <= d3) return bp.norm();
  const double vc = d1 * d4 - d3 * d2;
  if (vc <= 0 && d1 >= 0 && d3 <= 0) return (p - (a + d1 / (d1 - d3) * ab)).norm();
  const ddf::Vec3 cp = p - c;
  const double d5 = ab.dot(cp), d6 = ac.dot(cp);
  if (d6 >= 0 && d5 <= d6) return cp.norm();
  const double vb = d5 * d2 - d1 * d6;
  if (vb <= 0 && d2 >= 0 && d6 <= 0) return (p - (a + d2 / (d2 - d6) * ac)).norm();
  const double va = d3 * d6 - d5 * d4;
  if (va <= 0 && d4 - d3 >= 0 && d5 - d6 >= 0)
    return (p - (b + (d4 - d3) / ((d4 - d3) + (d5 - d6)) * (c - b))).norm();
  const double denom = 1.0 / (va + vb + vc);
  return (p - (a + ab * (vb * denom) + ac * (vc * denom))).norm();
}

TEST(SharedPaths, RosPathLiesOnThePartItWasPlannedOn) {
  SKIP_WITHOUT_SHARED_DATA();
  ddf::TriangleMesh mesh = readMesh(kRoot / kStl);
  for (ddf::Vec3& v : mesh.vertices) v *= 1000.0;  // the STL is in metres
  PathReadParams params;
  params.csv.unitIfUnstated = LengthUnit::Metre;
  for (const char* file : {kYaml, kCsv}) {
    SCOPED_TRACE(file);
    const planning::ClProgram program = readPathFile(kRoot / file, params).program;
    ASSERT_EQ(program.points.size(), 98u);
    double worstDistance = 0.0, worstCos = 1.0;
    // The CSV's last row is not a pose of the path (see the test above).
    const std::size_t count = std::string(file) == kCsv ? 97 : 98;
    for (std::size_t i = 0; i < count; ++i) {
      const planning::ClPoint& point = program.points[i];
      double nearest = INFINITY;
      ddf::Vec3 normal = ddf::Vec3::Zero();
      for (const auto& t : mesh.triangles) {
        const ddf::Vec3 &a = mesh.vertices[t[0]], &b = mesh.vertices[t[1]],
                        &c = mesh.vertices[t[2]];
        const double d = pointTriangleDistance(point.positionMm, a, b, c);
        if (d < nearest) {
          nearest = d;
          normal = (b - a).cross(c - a).normalized();
        }
      }
      worstDistance = std::max(worstDistance, nearest);
      worstCos = std::min(worstCos, std::abs(normal.dot(*point.axis)));
    }
    std::printf("%s: worst distance to part_2.stl %.4f mm, worst axis-normal angle %.2f deg\n",
                file, worstDistance, std::acos(worstCos) * 180.0 / std::numbers::pi);
    // Measured 0.567 mm (both files): the planner's poses lie on its own sampling of the
    // surface; 1 mm is < 0.1 % of the 1.2 m part, yet a unit slip (m vs mm) or a swapped
    // coordinate would be off by metres.
    EXPECT_LT(worstDistance, 1.0);
    // The sanding tool's z axis is the surface normal: measured 6.8 degrees from the
    // nearest facet's normal; an axis taken from another column of the rotation would be ~90 off.
    EXPECT_GT(worstCos, std::cos(10.0 * std::numbers::pi / 180.0));
  }
}

// ---- the FANUC program ----

TEST(SharedPaths, FanucProgramMatchesItsRawText) {
  SKIP_WITHOUT_SHARED_DATA();
  const planning::ClProgram p = readPathFile(kRoot / kLs).program;
  EXPECT_EQ(p.partName, "surface_cartesian");
  ASSERT_EQ(p.points.size(), 21u);
  EXPECT_EQ(p.pathCount(), 1);
  EXPECT_EQ(p.points[0].move, MoveKind::Rapid);
  EXPECT_EQ(p.points[0].feedMmPerMin, 0.0);
  for (std::size_t i = 1; i < 21; ++i) {
    EXPECT_EQ(p.points[i].move, MoveKind::Cut) << i;
    EXPECT_DOUBLE_EQ(p.points[i].feedMmPerMin, 12000.0) << i;  // 200 mm/sec
  }
  for (const planning::ClPoint& point : p.points) EXPECT_NEAR(point.axis->norm(), 1.0, 1e-12);
  // P[1] from the raw text.
  const std::string text = test::readBytes(kRoot / kLs);
  const std::size_t entry = text.find("P[1]{");
  auto raw = [&](const char* key) {
    const std::size_t at = text.find(key, entry);
    return std::strtod(text.c_str() + at + std::strlen(key), nullptr);
  };
  const planning::ClPoint& first = p.points[0];
  EXPECT_EQ(first.positionMm, ddf::Vec3(raw("X ="), raw("Y ="), raw("Z =")));
  EXPECT_EQ(first.positionMm.x(), 653.350855);
  // Tool z axis of R = Rz(R) Ry(P) Rx(W) multiplied out by hand.
  const double deg = std::numbers::pi / 180.0;
  const double w = raw("W =") * deg, pr = raw("P =") * deg, r = raw("R =") * deg;
  const ddf::Vec3 axis(std::cos(w) * std::sin(pr) * std::cos(r) + std::sin(w) * std::sin(r),
                       std::cos(w) * std::sin(pr) * std::sin(r) - std::sin(w) * std::cos(r),
                       std::cos(w) * std::cos(pr));
  EXPECT_LT((*first.axis - axis).norm(), 1e-12);
}

// ---- APT / CLDATA files through the dispatcher ----

struct RawMotion {
  int line = 0;
  std::vector<double> values;
};

/// GOTO and FROM records of an APT file by a plain line scan (no continuation in these files).
std::vector<RawMotion> rawMotions(const std::string& text) {
  std::vector<RawMotion> motions;
  std::size_t pos = 0;
  for (int line = 1; pos < text.size(); ++line) {
    const std::size_t end = std::min(text.find('\n', pos), text.size());
    std::string s = text.substr(pos, end - pos);
    pos = end + 1;
    for (char& c : s) c = static_cast<char>(std::toupper(static_cast<unsigned char>(c)));
    if (s.rfind("GOTO", 0) != 0 && s.rfind("FROM", 0) != 0) continue;
    RawMotion m{line, {}};
    const char* at = s.c_str() + s.find('/') + 1;
    for (char* next = nullptr;; at = next + (*next == ',' ? 1 : 0)) {
      const double v = std::strtod(at, &next);
      if (next == at) break;
      m.values.push_back(v);
    }
    motions.push_back(m);
  }
  return motions;
}

class SharedAptFiles : public ::testing::TestWithParam<std::pair<const std::string, LengthUnit>> {};

TEST_P(SharedAptFiles, EveryMotionRecordIsAPointInOrder) {
  SKIP_WITHOUT_SHARED_DATA();
  const auto& [name, unit] = GetParam();
  const std::string text = test::readBytes(kRoot / name);
  const planning::ClProgram program = readPathFile(kRoot / name).program;
  EXPECT_EQ(program.sourceUnit, unit);
  const double scale = unit == LengthUnit::Inch ? 25.4 : 1.0;
  const std::vector<RawMotion> raw = rawMotions(text);
  // GOTO + FROM records (shared/data/README.md, and `grep -c` on the files).
  const std::map<std::string, std::size_t> records = {
      {"mech491-nx-clsf/APT_Variable_Axis.txt", 348},
      {"mech491-nx-clsf/APT_Zig_Zag_Smoothed.txt", 75},
      {"mech491-nx-clsf/APT_SimpleMillPlane_ZIG.txt", 118},
      {"nist-proe-clfile/traj1.ncl", 61}};
  EXPECT_EQ(raw.size(), records.at(name));
  const bool hasCircles = text.find("CIRCLE") != std::string::npos;
  // Each GOTO / FROM is a point, in file order; CIRCLE records add arc points between them.
  std::size_t next = 0;
  ddf::Vec3 rawMin = ddf::Vec3::Constant(INFINITY), rawMax = -rawMin;
  for (const RawMotion& m : raw) {
    ASSERT_GE(m.values.size(), 3u) << "line " << m.line;
    const ddf::Vec3 expected = ddf::Vec3(m.values[0], m.values[1], m.values[2]) * scale;
    rawMin = rawMin.cwiseMin(expected);
    rawMax = rawMax.cwiseMax(expected);
    const std::size_t from = next;
    while (next < program.points.size() &&
           (program.points[next].positionMm - expected).norm() > 1e-9 * scale * 1e3)
      ++next;
    ASSERT_LT(next, program.points.size()) << "GOTO of line " << m.line << " not found";
    if (!hasCircles) {
      EXPECT_EQ(next, from) << "unexpected point before line " << m.line;
    }
    const planning::ClPoint& point = program.points[next++];
    if (m.values.size() >= 6) {
      const ddf::Vec3 axis = ddf::Vec3(m.values[3], m.values[4], m.values[5]).normalized();
      ASSERT_TRUE(point.axis.has_value()) << "line " << m.line;
      EXPECT_LT((*point.axis - axis).norm(), 1e-9) << "line " << m.line;
    }
  }
  if (!hasCircles) {
    EXPECT_EQ(program.points.size(), raw.size());
  }
  // Bounds: those of the records, grown only by arcs.
  ddf::Vec3 lo = ddf::Vec3::Constant(INFINITY), hi = -lo;
  for (const planning::ClPoint& p : program.points) {
    lo = lo.cwiseMin(p.positionMm);
    hi = hi.cwiseMax(p.positionMm);
  }
  EXPECT_TRUE(lo.isApprox(rawMin, 1e-12) || (hasCircles && (lo.array() <= rawMin.array()).all()));
  EXPECT_TRUE(hi.isApprox(rawMax, 1e-12) || (hasCircles && (hi.array() >= rawMax.array()).all()));
}

INSTANTIATE_TEST_SUITE_P(PathFile, SharedAptFiles, ::testing::ValuesIn(kAptFiles),
                         [](const auto& info) {
                           std::string s = fs::path(info.param.first).stem().string();
                           for (char& c : s)
                             if (!std::isalnum(static_cast<unsigned char>(c))) c = '_';
                           return s;
                         });

TEST(SharedPaths, AptFilesHaveTheDocumentedCountsAndFeeds) {
  SKIP_WITHOUT_SHARED_DATA();
  const planning::ClProgram variable =
      readPathFile(kRoot / "mech491-nx-clsf/APT_Variable_Axis.txt").program;
  EXPECT_EQ(variable.points.size(), 348u);  // README: 348 GOTO, 329 with a tool axis
  EXPECT_TRUE(variable.multiAxis());
  const auto cutFeed = [](const planning::ClProgram& p) {
    for (const planning::ClPoint& point : p.points)
      if (point.move == MoveKind::Cut) return point.feedMmPerMin;
    return 0.0;
  };
  EXPECT_DOUBLE_EQ(cutFeed(variable), 10.0 * 25.4);  // FEDRAT/IPM,10
  const planning::ClProgram proe = readPathFile(kRoot / "nist-proe-clfile/traj1.ncl").program;
  EXPECT_EQ(proe.points.size(), 61u);  // FROM + 60 GOTO
  EXPECT_EQ(proe.partName, "CORE_WORK");
  EXPECT_DOUBLE_EQ(cutFeed(proe), 10.0 * 25.4);     // FEDRAT / 10, IPM
  EXPECT_EQ(proe.points[0].move, MoveKind::Rapid);  // FROM
  const planning::ClProgram zig =
      readPathFile(kRoot / "mech491-nx-clsf/APT_Zig_Zag_Smoothed.txt").program;
  EXPECT_DOUBLE_EQ(cutFeed(zig), 250.0);  // FEDRAT/MMPM,250
  EXPECT_GT(zig.points.size(), 75u);      // 75 GOTO and 35 interpolated arcs
}

}  // namespace
}  // namespace ddfcam::io
