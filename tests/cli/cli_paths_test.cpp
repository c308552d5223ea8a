// SPDX-License-Identifier: MIT
// Runs ddfcam-cli paths and simulate on path files: every shared file to CSV and APT and back,
// G-code through rs274, APT against CSV in the simulation, units and transforms, bad input.
#include <ddfcam/ddf/analytic_generators.h>
#include <ddfcam/io/mesh/ddf_file.h>
#include <ddfcam/io/programs/apt_reader.h>
#include <ddfcam/io/programs/apt_writer.h>
#include <ddfcam/io/programs/path_file.h>
#include <ddfcam/io/programs/tool_path_csv.h>

#include <gmock/gmock.h>
#include <gtest/gtest.h>

#include <Eigen/Geometry>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <filesystem>
#include <fstream>
#include <sstream>

#include "cli_simulate_support.h"
#include "../io/programs/rs274_run.h"

namespace ddfcam::io {
namespace {

namespace fs = std::filesystem;
using test::cli;
using test::CliRun;
using ::testing::HasSubstr;

const fs::path kPaths = fs::path(DDFCAM_SHARED_DATA_DIR) / "paths";

#define SKIP_WITHOUT_SHARED_PATHS() \
  if (!fs::exists(kPaths)) GTEST_SKIP() << "shared data not found at " << kPaths

/// Largest rounding error of a length written with @p decimals digits in @p unit, mm, plus
/// the error of the double arithmetic on it.
double written(int decimals, LengthUnit unit) {
  return 0.5 * std::pow(10.0, -decimals) * millimetresPer(unit) * (1.0 + 1e-9) + 1e-9;
}

/// @p back has the points of @p truth: same count, positions within @p tol mm, axes within
/// @p axisTol, rapid moves at the same places.
void expectSamePoints(const planning::ClProgram& truth, const planning::ClProgram& back, double tol,
                      double axisTol, const std::string& what) {
  ASSERT_EQ(back.points.size(), truth.points.size()) << what;
  double worst = 0.0;
  for (std::size_t i = 0; i < truth.points.size(); ++i) {
    const planning::ClPoint &a = truth.points[i], &b = back.points[i];
    worst = std::max(worst, (a.positionMm - b.positionMm).lpNorm<Eigen::Infinity>());
    EXPECT_EQ(a.move == planning::MoveKind::Rapid, b.move == planning::MoveKind::Rapid)
        << what << " point " << i;
    ASSERT_EQ(a.axis.has_value(), b.axis.has_value()) << what << " point " << i;
    if (a.axis) {
      EXPECT_LE((*a.axis - *b.axis).lpNorm<Eigen::Infinity>(), axisTol) << what << " " << i;
    }
  }
  EXPECT_LE(worst, tol) << what;
}

TEST(CliPaths, EverySharedPathFileConvertsToCsvAndAptAndReadsBack) {
  SKIP_WITHOUT_SHARED_PATHS();
  test::ScratchDir dir;
  const std::vector<fs::path> files = {
      "mech491-nx-clsf/APT_Variable_Axis.txt",         "mech491-nx-clsf/APT_Zig_Zag_Smoothed.txt",
      "mech491-nx-clsf/APT_SimpleMillPlane_ZIG.txt",   "nist-proe-clfile/traj1.ncl",
      "crs-robotic-sanding/part_2_job_0_degrees.yaml", "crs-robotic-sanding/surface_cartesian.ls"};
  for (const fs::path& name : files) {
    const fs::path in = kPaths / name;
    const planning::ClProgram truth =
        readPathFile(in).program;  // the oracle: the reader on the original
    ASSERT_FALSE(truth.points.empty()) << name;
    CliRun run = cli(dir, "paths", {in.string(), "-o", (dir / "out.csv").string()});
    ASSERT_EQ(run.exitCode, 0) << name << ": " << run.err;
    EXPECT_THAT(run.out, HasSubstr(std::to_string(truth.points.size()) + " points")) << name;
    for (const planning::ClMessage& m : truth.warnings) {
      const std::string where = m.line > 0 ? "line " + std::to_string(m.line) + ": " : "";
      EXPECT_THAT(run.err, HasSubstr("warning: " + in.string() + ": " + where + m.text)) << name;
    }
    // CSV: 6 decimals in the file's own unit (metres stay metres).
    const planning::ClProgram csv = readToolPathCsv(dir / "out.csv");
    EXPECT_EQ(csv.sourceUnit, truth.sourceUnit) << name;
    // Axes: components rounded, then normalised again by the reader.
    expectSamePoints(truth, csv, written(6, truth.sourceUnit), 1e-6, name.string() + " as CSV");
    // APT: 5 decimals of lengths, 8 of axis components; metres become millimetres.
    run = cli(dir, "paths",
              {in.string(), "-o", (dir / "out.apt").string(), "--decimals", "5",
               "--vector-decimals", "8", "--dialect", "nx"});
    ASSERT_EQ(run.exitCode, 0) << name << ": " << run.err;
    const planning::ClProgram apt = readApt(dir / "out.apt");
    const LengthUnit aptUnit =
        truth.sourceUnit == LengthUnit::Metre ? LengthUnit::Millimetre : truth.sourceUnit;
    EXPECT_EQ(apt.sourceUnit, aptUnit) << name;
    expectSamePoints(truth, apt, written(5, aptUnit), 1e-7, name.string() + " as APT");
    const bool fed = std::any_of(truth.points.begin(), truth.points.end(),
                                 [](const planning::ClPoint& p) { return p.feedMmPerMin > 0.0; });
    if (fed) {  // the NX dialect writes the feed unit first
      EXPECT_THAT(test::readBytes(dir / "out.apt"),
                  HasSubstr(aptUnit == LengthUnit::Inch ? "FEDRAT/IPM," : "FEDRAT/MMPM,"))
          << name;
    }
  }
}

TEST(CliPaths, VariableAxisProgramAsFiveAxisGCodeIsAcceptedByRs274) {
  SKIP_WITHOUT_SHARED_PATHS();
  if (!fs::exists(test::kRs274Path))
    GTEST_SKIP() << "rs274 (Debian package linuxcnc-uspace) not installed: the G-code is not "
                    "checked by a strict interpreter";
  test::ScratchDir dir;
  const fs::path in = kPaths / "mech491-nx-clsf/APT_Variable_Axis.txt";
  const planning::ClProgram truth = readPathFile(in).program;
  ASSERT_TRUE(truth.multiAxis());
  // The NX file cuts with a 1" ball mill (shared/data/README.md).
  const CliRun run = cli(dir, "paths",
                         {in.string(), "-o", (dir / "v.ngc").string(), "--dialect", "5axis-ac",
                          "--tool", "ball_end", "--radius", "12.7", "--units", "mm"});
  ASSERT_EQ(run.exitCode, 0) << run.err;
  const std::string ngc = test::readBytes(dir / "v.ngc");
  EXPECT_THAT(ngc, HasSubstr("G21"));
  const test::Rs274Run rs = test::runRs274(ngc);
  ASSERT_EQ(rs.exitCode, 0) << rs.errors;
  EXPECT_EQ(rs.errors, "");
  // One canonical move per program point, plus the writer's rapid to the safe plane, the one
  // over the first point and the final retract (gcode_writer.h).
  std::istringstream calls(rs.out);
  std::size_t moves = 0;
  for (std::string line; std::getline(calls, line);)
    moves += line.find("STRAIGHT_") != std::string::npos ? 1 : 0;
  EXPECT_EQ(moves, truth.points.size() + 3);
}

TEST(CliPaths, MachineFileWritesTheHaasPostsAxesAndRefusesWhatDoesNotFit) {
  SKIP_WITHOUT_SHARED_PATHS();
  test::ScratchDir dir;
  const fs::path in = kPaths / "mech491-nx-clsf/APT_Variable_Axis.txt";
  const fs::path haas = fs::path(DDFCAM_SOURCE_DIR) / "resources/machines/haas-umc750.json";
  CliRun run =
      cli(dir, "paths", {in.string(), "-o", (dir / "h.ngc").string(), "--machine", haas.string()});
  ASSERT_EQ(run.exitCode, 0) << run.err;
  const std::string ngc = test::readBytes(dir / "h.ngc");
  EXPECT_THAT(ngc, HasSubstr("(machine: Haas UMC-750"));
  EXPECT_THAT(ngc, HasSubstr("G234 H"));
  // NX's post moves to B-22.201 C1.05 first (3 and 2 decimals); ours writes 4.
  const std::size_t b = ngc.find(" B", ngc.find("\nG0 X"));  // the first move with B and C
  ASSERT_NE(b, std::string::npos);
  double bDeg = 0.0, cDeg = 0.0;
  ASSERT_EQ(std::sscanf(ngc.c_str() + b, " B%lf C%lf", &bDeg, &cDeg), 2);
  EXPECT_NEAR(bDeg, -22.201, 1e-3);
  EXPECT_NEAR(cDeg, 1.05, 5e-3);
  run = cli(dir, "paths",
            {in.string(), "-o", (dir / "h.ngc").string(), "--machine", haas.string(), "--dialect",
             "5axis-bc"});
  EXPECT_NE(run.exitCode, 0);
  EXPECT_THAT(run.err, HasSubstr("--machine replaces --dialect"));
  run =
      cli(dir, "paths", {in.string(), "-o", (dir / "h.csv").string(), "--machine", haas.string()});
  EXPECT_NE(run.exitCode, 0);
  EXPECT_THAT(run.err, HasSubstr("--machine applies to G-code output"));
  std::ofstream(dir / "bad.json") << R"({"name": "x", "tilt_direction": 2})";
  run =
      cli(dir, "paths",
          {in.string(), "-o", (dir / "h.ngc").string(), "--machine", (dir / "bad.json").string()});
  EXPECT_NE(run.exitCode, 0);
  EXPECT_THAT(run.err, HasSubstr("\"tilt_direction\" must be 1 or -1"));
}

TEST(CliPaths, AnEmptyProgramIsAnErrorNotAnEmptyFile) {
  test::ScratchDir dir;
  std::ofstream(dir / "empty.apt") << "PARTNO EMPTY\nUNITS/MM\nFINI\n";
  const CliRun run =
      cli(dir, "paths", {(dir / "empty.apt").string(), "-o", (dir / "out.ngc").string()});
  EXPECT_NE(run.exitCode, 0);
  EXPECT_THAT(run.err, HasSubstr("holds no tool motion"));
  EXPECT_THAT(run.out, ::testing::Not(HasSubstr("inf")));
  EXPECT_FALSE(fs::exists(dir / "out.ngc"));
}

/// z = h of every raster point of @p ddf, in the order of allHeights().
std::vector<float> heightsOf(const fs::path& file) {
  const ddf::DisplacementField out = readDdf(file);
  return {out.allHeights().begin(), out.allHeights().end()};
}

TEST(CliPaths, SimulatingTheAptOfAPlanEqualsSimulatingItsCsv) {
  test::ScratchDir dir;
  const CliRun plan =
      cli(dir, "plan",
          {"demo", "-o", (dir / "plan.csv").string(), "--field", "fixed", "--no-smooth",
           "--seeding", "transverse", "--spacing", "8", "--tool", "ball", "--point", "reference"});
  ASSERT_EQ(plan.exitCode, 0) << plan.err;
  // APT has no link moves (a link GOTO reads back as a cut): keep the cuts and rapids only,
  // and every 16th cut for a fast test.
  planning::ClProgram program = readToolPathCsv(dir / "plan.csv");
  std::erase_if(program.points, [](const planning::ClPoint& p) {
    return p.move == planning::MoveKind::Link ||
           (p.move == planning::MoveKind::Cut && p.point % 16 != 0);
  });
  std::size_t cuts = 0;
  for (const planning::ClPoint& p : program.points)
    cuts += p.move == planning::MoveKind::Cut ? 1 : 0;
  writeToolPathCsv(program, dir / "p.csv");
  // p.apt: the plan as APT; back.csv: that APT as CSV again (positions and axes, no normals).
  CliRun run = cli(dir, "paths",
                   {(dir / "p.csv").string(), "-o", (dir / "p.apt").string(), "--decimals", "6"});
  ASSERT_EQ(run.exitCode, 0) << run.err;
  run = cli(dir, "paths", {(dir / "p.apt").string(), "-o", (dir / "back.csv").string()});
  ASSERT_EQ(run.exitCode, 0) << run.err;
  const std::vector<std::string> common = {
      "--tool", "ball", "--no-vconvexity-check", "--allowance", "0.05", "--tolerance", "0.02"};
  for (const std::string file : {"p.csv", "p.apt", "back.csv"}) {
    std::vector<std::string> args = {"demo",
                                     "--paths",
                                     (dir / file).string(),
                                     "-o",
                                     (dir / (file + ".ddf")).string(),
                                     "--report",
                                     (dir / (file + ".json")).string()};
    args.insert(args.end(), common.begin(), common.end());
    run = cli(dir, "simulate", args);
    ASSERT_EQ(run.exitCode, 0) << file << ": " << run.err;
  }
  const std::string csvJson = test::readBytes(dir / "p.csv.json");
  const std::string aptJson = test::readBytes(dir / "p.apt.json");
  EXPECT_THAT(csvJson, HasSubstr("\"placement\": \"contacts\""));
  EXPECT_THAT(aptJson, HasSubstr("\"format\": \"APT/CLDATA\""));
  EXPECT_THAT(aptJson, HasSubstr("\"placement\": \"program axes\""));
  EXPECT_THAT(test::readBytes(dir / "back.csv.json"), HasSubstr("\"placement\": \"program axes\""));
  EXPECT_EQ(test::jsonNumber(aptJson, "points_read"), static_cast<double>(program.points.size()));
  EXPECT_EQ(test::jsonNumber(aptJson, "poses"), static_cast<double>(cuts));  // rapids dropped
  EXPECT_EQ(test::jsonNumber(aptJson, "points_off_part"), 0.0);
  EXPECT_EQ(test::jsonNumber(csvJson, "poses"), static_cast<double>(cuts));
  const ddf::DisplacementField demo = ddf::demoPart().ddf;
  const std::vector<float> fromCsv = heightsOf(dir / "p.csv.ddf");
  const std::vector<float> fromApt = heightsOf(dir / "p.apt.ddf");
  const std::vector<float> fromBack = heightsOf(dir / "back.csv.ddf");
  ASSERT_EQ(fromApt.size(), demo.allHeights().size());
  ASSERT_EQ(fromCsv.size(), fromApt.size());
  ASSERT_EQ(fromBack.size(), fromApt.size());
  // The same program as APT and as CSV: the same poses (positions to 1e-6 mm, axes to 1e-7),
  // so the same heights.
  std::size_t cut = 0;
  double meanDifference = 0.0;
  for (std::size_t i = 0; i < fromApt.size(); ++i) {
    EXPECT_NEAR(fromBack[i], fromApt[i], 1e-4) << i;
    cut += fromApt[i] < demo.allHeights()[i] + 0.049f ? 1 : 0;
    meanDifference += std::abs(fromCsv[i] - fromApt[i]) / static_cast<double>(fromApt.size());
    // The plan's CSV (placed at its contacts) gives the same sphere centres, but the faceted
    // spheres (vertices on the sphere, chord 0.02 / 4 mm) stand turned differently about
    // them: the cut surface moves by up to the chord along the normal, up to 2 chords in
    // height units where |v| n.v >= 0.5 mm.
    EXPECT_NEAR(fromCsv[i], fromApt[i], 0.01 + 1e-5) << i;
  }
  EXPECT_GT(cut, fromApt.size() / 100);
  EXPECT_LT(meanDifference, 1e-3);
}

/// APT of a 3-axis ball-end pass: tips @p tips (file units), UNITS/MM, 6 decimals.
void writePass(const std::vector<ddf::Vec3>& tips, const fs::path& file) {
  planning::ClProgram program;
  for (std::size_t i = 0; i < tips.size(); ++i) {
    planning::ClPoint p;
    p.point = static_cast<int>(i);
    p.positionMm = tips[i];
    p.feedMmPerMin = 500.0;
    program.points.push_back(p);
  }
  AptWriteParams params;
  params.coordinateDecimals = 6;
  writeApt(program, file, params);
}

TEST(CliPaths, PathUnitsRotateAndTranslatePlaceLikeAPreparedFile) {
  test::ScratchDir dir;
  writeDdf(test::plate(), dir / "part.ddf");
  // Part frame: the tip runs along x at y = 10 on the plate (z = 0). The raw file holds
  // raw = Rz(-90) (p - t) / 25.4 under a false UNITS/MM: placed by --path-units in
  // --rotate 0,0,90 --translate t it must give p = t + Rz(90) 25.4 raw.
  const ddf::Vec3 t(3.0, -2.0, 0.0);
  const Eigen::Matrix3d back = Eigen::AngleAxisd(-M_PI / 2, ddf::Vec3::UnitZ()).toRotationMatrix();
  std::vector<ddf::Vec3> part, raw;
  for (int i = 0; i <= 80; ++i) {
    part.emplace_back(2.0 + 0.2 * i, 10.0, 0.0);
    raw.push_back(back * (part.back() - t) / 25.4);
  }
  writePass(part, dir / "prepared.apt");
  writePass(raw, dir / "raw.apt");
  const std::vector<std::string> tool = {
      "--tool", "ball_end", "--radius", "2", "--allowance", "0.1", "--no-vconvexity-check"};
  auto simulate = [&](const std::string& file, std::vector<std::string> extra) {
    std::vector<std::string> args = {(dir / "part.ddf").string(),
                                     "--paths",
                                     (dir / file).string(),
                                     "-o",
                                     (dir / (file + ".ddf")).string(),
                                     "--report",
                                     (dir / (file + ".json")).string()};
    args.insert(args.end(), tool.begin(), tool.end());
    args.insert(args.end(), extra.begin(), extra.end());
    const CliRun run = cli(dir, "simulate", args);
    EXPECT_EQ(run.exitCode, 0) << file << ": " << run.err;
    return test::heightGrid(readDdf(dir / (file + ".ddf")));
  };
  const auto prepared = simulate("prepared.apt", {});
  const auto placed =
      simulate("raw.apt", {"--path-units", "in", "--rotate", "0,0,90", "--translate", "3,-2,0"});
  ASSERT_EQ(prepared.size(), placed.size());
  for (const auto& [at, z] : prepared) {
    EXPECT_NEAR(placed.at(at), z, 1e-4) << at.first << ", " << at.second;
    // Independent truth: the ball-end's cross-section under the stock; poses 0.2 mm apart
    // leave cusps of R - sqrt(R^2 - 0.1^2) = 0.0025 mm, the facets up to their chord 0.0025.
    const double x = at.first * test::kSpacing, dy = std::abs(at.second * test::kSpacing - 10.0);
    if (x >= 3.0 && x <= 17.0) {
      EXPECT_NEAR(z, std::min(0.1, dy < 2.0 ? 2.0 - std::sqrt(4.0 - dy * dy) : 1.0), 5.1e-3)
          << x << ", " << dy;
    }
  }
  const std::string json = test::readBytes(dir / "raw.apt.json");
  EXPECT_THAT(json, HasSubstr("\"unit\": \"in\""));
  EXPECT_EQ(test::jsonNumber(json, "points_off_part"), 0.0) << json;
  EXPECT_LT(test::jsonNumber(json, "max_contact_distance_mm"), 1e-3) << json;
}

TEST(CliPaths, RotateAndTranslateMoveACsvWithNormalsLikeAPreparedOne) {
  test::ScratchDir dir;
  writeDdf(test::plate(), dir / "part.ddf");
  // The straight roll pass (axis y, normal z) stored turned by -90 deg about z and moved by
  // -t: --rotate 0,0,90 --translate t must restore positions, axes and normals.
  const planning::ClProgram prepared = test::straightPass(0.5);
  planning::ClProgram raw = prepared;
  const ddf::Vec3 t(-4.0, 7.0, 0.0);
  const Eigen::Matrix3d back = Eigen::AngleAxisd(-M_PI / 2, ddf::Vec3::UnitZ()).toRotationMatrix();
  for (planning::ClPoint& p : raw.points) {
    p.positionMm = back * (p.positionMm - t);
    p.axis = back * *p.axis;
    p.normal = back * *p.normal;
  }
  writeToolPathCsv(prepared, dir / "prepared.csv");
  writeToolPathCsv(raw, dir / "raw.csv");
  auto simulate = [&](const std::string& file, std::vector<std::string> extra) {
    std::vector<std::string> args = {(dir / "part.ddf").string(),
                                     "--paths",
                                     (dir / file).string(),
                                     "-o",
                                     (dir / (file + ".ddf")).string(),
                                     "--radius",
                                     "5",
                                     "--width",
                                     "4.1",
                                     "--allowance",
                                     "0.1"};
    args.insert(args.end(), extra.begin(), extra.end());
    const CliRun run = cli(dir, "simulate", args);
    EXPECT_EQ(run.exitCode, 0) << file << ": " << run.err;
    return test::heightGrid(readDdf(dir / (file + ".ddf")));
  };
  const auto a = simulate("prepared.csv", {});
  const auto b = simulate("raw.csv", {"--rotate", "0,0,90", "--translate", "-4,7,0"});
  ASSERT_EQ(a.size(), b.size());
  int grooved = 0;
  for (const auto& [at, z] : a) {
    EXPECT_NEAR(b.at(at), z, 1e-5) << at.first << ", " << at.second;
    grooved += z < 0.05 ? 1 : 0;
  }
  EXPECT_GT(grooved, 500);  // the groove is there: 16 x 4 mm of 0.25 mm cells
}

TEST(CliPaths, KeepRapidsPlacesTheRapidMovesToo) {
  test::ScratchDir dir;
  writeDdf(test::plate(), dir / "part.ddf");
  planning::ClProgram program;  // a rapid to the start, then 11 cut points along x at y = 10
  for (int i = 0; i <= 11; ++i) {
    planning::ClPoint p;
    p.point = i;
    p.positionMm = {i == 0 ? 2.0 : 2.0 + 1.5 * (i - 1), 10.0, i == 0 ? 0.5 : 0.0};
    p.move = i == 0 ? planning::MoveKind::Rapid : planning::MoveKind::Cut;
    p.feedMmPerMin = i == 0 ? 0.0 : 800.0;
    program.points.push_back(p);
  }
  writeApt(program, dir / "rapid.apt");
  for (const bool keep : {false, true}) {
    std::vector<std::string> args = {(dir / "part.ddf").string(),
                                     "--paths",
                                     (dir / "rapid.apt").string(),
                                     "-o",
                                     (dir / "o.ddf").string(),
                                     "--report",
                                     (dir / "r.json").string(),
                                     "--tool",
                                     "ball_end",
                                     "--radius",
                                     "2",
                                     "--allowance",
                                     "0.1"};
    if (keep) args.push_back("--keep-rapids");
    const CliRun run = cli(dir, "simulate", args);
    ASSERT_EQ(run.exitCode, 0) << run.err;
    const std::string json = test::readBytes(dir / "r.json");
    EXPECT_EQ(test::jsonNumber(json, "points_read"), 12.0) << json;
    EXPECT_EQ(test::jsonNumber(json, "poses"), keep ? 12.0 : 11.0) << json;
    EXPECT_EQ(test::jsonNumber(json, "poses_placed"), keep ? 12.0 : 11.0) << json;
  }
}

TEST(CliPaths, BadOptionsAndNonPathFilesGiveClearErrors) {
  test::ScratchDir dir;
  writeDdf(test::plate(), dir / "part.ddf");
  writeToolPathCsv(test::straightPass(1.0), dir / "pass.csv");
  writePass({{2, 10, 0}, {18, 10, 0}}, dir / "pass.apt");
  test::writeBytes(dir / "notes.txt", "shopping list\nmilk and bread\n");
  const std::string csv = (dir / "pass.csv").string(), apt = (dir / "pass.apt").string();
  const std::string out = (dir / "o.apt").string(), part = (dir / "part.ddf").string();
  struct Case {
    std::string command;
    std::vector<std::string> args;
    int code;
    std::string message;
  };
  const std::vector<Case> cases = {
      {"paths", {csv}, 2, "--output"},
      {"paths", {csv, "-o", out, "--format", "xml"}, 2, "--format xml"},
      {"paths", {csv, "-o", out, "--units", "m"}, 2, "--units m"},
      {"paths", {csv, "-o", out, "--in-units", "ft"}, 2, "--in-units ft"},
      {"paths", {apt, "-o", out, "--decimals", "9"}, 2, "--decimals"},
      {"paths", {apt, "-o", out, "--dialect", "5axis-ac"}, 2, "standard|nx"},
      {"paths", {apt, "-o", (dir / "o.csv").string(), "--dialect", "nx"}, 2, "--dialect"},
      {"paths", {apt, "-o", out + ".ngc", "--dialect", "4axis"}, 2, "3axis|5axis-ac|5axis-bc"},
      {"paths", {apt, "-o", (dir / "o.csv").string(), "--vector-decimals", "7"}, 2, "apt only"},
      {"paths", {apt, "-o", out, "--radius", "3"}, 2, "--tool"},
      {"paths", {apt, "-o", out + ".ngc"}, 1, "G-code needs a cutter"},
      {"paths", {csv, "-o", out}, 1, "--point reference"},
      {"paths", {apt, "-o", out + ".ngc", "--tool", "roll"}, 1, "cutter"},
      {"paths", {(dir / "notes.txt").string(), "-o", out}, 1, "not a tool-path file"},
      {"paths", {part, "-o", out}, 1, "not a tool-path file"},
      {"paths", {(dir / "missing.apt").string(), "-o", out}, 1, "missing.apt"},
      {"simulate", {part, "--paths", apt, "-o", out, "--path-units", "ft"}, 2, "mm|in|m"},
      {"simulate", {part, "--paths", apt, "-o", out, "--translate", "1,2"}, 2, "--translate 1,2"},
      {"simulate", {part, "--paths", apt, "-o", out, "--rotate", "a,b,c"}, 2, "--rotate"},
      {"simulate",
       {part, "--paths", (dir / "notes.txt").string(), "-o", out},
       1,
       "not a tool-path"},
      {"simulate", {part, "--paths", apt, "-o", out, "--lead", "10"}, 1, "--lead"},
      {"simulate", {part, "--paths", apt, "-o", out, "--step", "0.5"}, 1, "--step"},
      {"simulate", {part, "--paths", csv, "-o", out, "--keep-rapids"}, 1, "--keep-rapids"},
  };
  for (const Case& c : cases) {
    const CliRun run = cli(dir, c.command, c.args);
    EXPECT_EQ(run.exitCode, c.code) << c.command << " " << c.args.back() << ": " << run.err;
    EXPECT_THAT(run.err, HasSubstr(c.message)) << c.command << " " << c.args.back();
  }
  EXPECT_FALSE(fs::exists(out));
  EXPECT_FALSE(fs::exists(out + ".ngc"));
}

}  // namespace
}  // namespace ddfcam::io
