// SPDX-License-Identifier: MIT
// Runs ddfcam-cli run on small jobs on the demo part: outputs read back with the project's own
// readers, two runs give identical bytes, and bad jobs fail naming the problem.
#include <ddfcam/ddf/analytic_generators.h>
#include <ddfcam/io/mesh/ddf_file.h>
#include <ddfcam/io/mesh/mesh_io.h>
#include <ddfcam/io/programs/tool_path_csv.h>
#include <ddfcam/io/project/project_file.h>
#include <ddfcam/io/project/tool_library_file.h>
#include <ddfcam/planning/lines/scallop_spacing.h>

#include <gmock/gmock.h>
#include <gtest/gtest.h>
#include <nlohmann/json.hpp>

#include <sys/wait.h>

#include <algorithm>
#include <cmath>
#include <fstream>

#include "../io/io_test_support.h"

namespace ddfcam::io {
namespace {

using ::testing::HasSubstr;
using ::testing::Not;

struct RunResult {
  int exitCode = -1;
  std::string out;
  std::string err;
};

std::string quote(const std::string& word) {
  std::string quoted = "'";
  quoted += word;
  return quoted + "'";
}

/// ddfcam-cli with @p args, without a display (screenshots are skipped, deterministically).
RunResult cli(const test::ScratchDir& dir, const std::vector<std::string>& args) {
  std::string command = "env -u DISPLAY ";
  command += quote(DDFCAM_CLI_PATH);
  for (const auto& a : args) command.append(" ").append(quote(a));
  const auto out = dir / "stdout.txt", err = dir / "stderr.txt";
  command += " > " + quote(out.string()) + " 2> " + quote(err.string()) + " < /dev/null";
  const int status = std::system(command.c_str());
  return {WIFEXITED(status) ? WEXITSTATUS(status) : -1, test::readBytes(out), test::readBytes(err)};
}

void writeText(const std::filesystem::path& file, const std::string& text) {
  std::filesystem::create_directories(file.parent_path());
  std::ofstream(file, std::ios::binary) << text;
}

/// The demo part's shape on a coarse grid (96 faces, m = 9), so that a job takes a second.
void writeCoarseDemoPart(const std::filesystem::path& file) {
  std::filesystem::create_directories(file.parent_path());
  writeDdf(ddf::demoPart({.cellsX = 8, .cellsY = 6, .m = 9}).ddf, file);
}

/// A coarse job on @p part: one region, lines 3 mm apart, a ball-end tool, allowance 0.02 mm.
std::string smallJob(const std::string& part) {
  return R"({
  "part": ")" +
         part +
         R"(",
  "tools": [{"name": "ball end", "kind": "ball_end", "radiusMm": 5, "widthMm": 10}],
  "regions": [{"field": "fixed", "direction": [0, 1, 0], "smooth": false, "spacingMm": 3}],
  "placement": {"samplingToleranceMm": 0.01, "samplingStepMm": 2},
  "simulation": {"allowanceMm": 0.02, "mode": "swept"},
  "errorMap": {"lowerMm": -0.01, "upperMm": 0.01, "vtp": "errors.vtp"},
  "exports": [
    {"format": "csv", "file": "paths.csv", "decimals": 9},
    {"format": "apt", "file": "paths.apt", "dialect": "nx"},
    {"format": "gcode", "file": "paths.ngc", "dialect": "5axis-bc"}
  ],
  "project": "job.ddfproj",
  "report": "report.json",
  "screenshots": ["view.png"]
})";
}

const planning::SimulationState* stateNamed(const planning::Project& p, const std::string& name) {
  for (const planning::SimulationState& s : p.states)
    if (s.name == name) return &s;
  return nullptr;
}

TEST(CliRun, SmallJobWritesOutputsThatReadBack) {
  test::ScratchDir dir;
  writeCoarseDemoPart(dir / "coarse_demo.ddf");
  writeText(dir / "job.json", smallJob("coarse_demo.ddf"));
  const RunResult run =
      cli(dir, {"run", (dir / "job.json").string(), "--out", (dir / "out").string()});
  ASSERT_EQ(run.exitCode, 0) << run.err;
  for (const char* stage : {"load", "curvature", "segmentation", "paths", "simulation"})
    EXPECT_THAT(run.err, HasSubstr(stage));
  const planning::Project project = readProject(dir / "out" / "job.ddfproj");
  ASSERT_EQ(project.regions.size(), 1u);
  ASSERT_EQ(project.paths.size(), 1u);
  ASSERT_EQ(project.tools.size(), 1u);
  const planning::ToolPath& path = project.paths[0];
  ASSERT_GT(path.passStarts.size(), 1u);
  // The states the Simulation panel records: design, raised stock, after the path.
  ASSERT_NE(stateNamed(project, "design"), nullptr);
  ASSERT_NE(stateNamed(project, "stock +0.02 mm"), nullptr);
  const planning::SimulationState* after = stateNamed(project, "after " + path.name);
  ASSERT_NE(after, nullptr);
  EXPECT_EQ(after->heights, project.part->allHeights());
  const auto& stock = stateNamed(project, "stock +0.02 mm")->heights;
  std::size_t lowered = 0;
  for (std::size_t i = 0; i < stock.size(); ++i) {
    EXPECT_LE(after->heights[i], stock[i]);  // grinding only removes
    lowered += after->heights[i] < stock[i] ? 1 : 0;
  }
  // Grooves of a 5 mm ball 0.02 mm deep are 0.9 mm wide, every 3 mm: a fifth to a third.
  EXPECT_GT(lowered, stock.size() / 8);
  // The CSV's cut contacts are the project path's contacts, pass by pass, to 1e-9 mm.
  const planning::ClProgram csv = readToolPathCsv(dir / "out" / "paths.csv");
  EXPECT_EQ(csv.pointKind, planning::ClPointKind::Contact);
  std::vector<ddf::Vec3> cuts;
  for (const planning::ClPoint& p : csv.points)
    if (p.move == planning::MoveKind::Cut) cuts.push_back(p.positionMm);
  ASSERT_EQ(cuts.size(), path.poses.size());
  for (std::size_t i = 0; i < cuts.size(); ++i)
    EXPECT_LT((cuts[i] - path.poses[i].contact).norm(), 2e-9) << "pose " << i;
  const std::string apt = test::readBytes(dir / "out" / "paths.apt");
  EXPECT_THAT(apt, HasSubstr("FEDRAT/MMPM,"));
  EXPECT_THAT(apt, HasSubstr("FINI"));
  EXPECT_THAT(test::readBytes(dir / "out" / "paths.ngc"), HasSubstr("5-axis table-table B/C"));
  EXPECT_TRUE(std::filesystem::exists(dir / "out" / "errors.vtp"));
  const nlohmann::json report = nlohmann::json::parse(test::readBytes(dir / "out" / "report.json"));
  EXPECT_EQ(report["paths"][0]["poses"].get<std::size_t>(), path.poses.size());
  EXPECT_EQ(report["notes"][0].get<std::string>(), "screenshots skipped: no display");
  // Raised by 0.02 mm and ground back: nothing left above the allowance, the region's
  // deviation is the material the roll did not reach.
  EXPECT_LE(report["error_map"]["max_mm"].get<double>(), 0.02 + 1e-4);
  for (const char* file :
       {"job.ddfproj", "paths.csv", "paths.apt", "paths.ngc", "errors.vtp", "report.json"})
    EXPECT_NE(std::ranges::find(report["files"], file), report["files"].end()) << file;
  EXPECT_TRUE(report.contains("timings"));
}

TEST(CliRun, TwoRunsGiveIdenticalFiles) {
  test::ScratchDir dir;
  writeCoarseDemoPart(dir / "coarse_demo.ddf");
  writeText(dir / "job.json", smallJob("coarse_demo.ddf"));
  for (const char* out : {"a", "b"}) {
    const RunResult run = cli(
        dir, {"run", (dir / "job.json").string(), "--out", (dir / out).string(), "--no-timings"});
    ASSERT_EQ(run.exitCode, 0) << run.err;
  }
  for (const char* file :
       {"job.ddfproj", "paths.csv", "paths.apt", "paths.ngc", "errors.vtp", "report.json"})
    EXPECT_EQ(test::readBytes(dir / "a" / file), test::readBytes(dir / "b" / file)) << file;
  EXPECT_THAT(test::readBytes(dir / "a" / "report.json"), Not(HasSubstr("timings")));
}

TEST(CliRun, RelativePathsResolveAgainstTheJobFile) {
  test::ScratchDir dir;
  writeCoarseDemoPart(dir / "jobs" / "parts" / "demo.ddf");
  const std::string job = smallJob("parts/demo.ddf");
  writeText(dir / "jobs" / "job.json", job);
  const RunResult run = cli(dir, {"run", (dir / "jobs" / "job.json").string()});
  ASSERT_EQ(run.exitCode, 0) << run.err;
  const planning::Project project = readProject(dir / "jobs" / "job.ddfproj");
  EXPECT_EQ(project.partName, "demo.ddf");
  EXPECT_TRUE(std::filesystem::exists(dir / "jobs" / "paths.csv"));
}

TEST(CliRun, PerRegionExportWritesOneFilePerRegion) {
  test::ScratchDir dir;
  writeCoarseDemoPart(dir / "part.ddf");
  writeText(dir / "job.json", R"({
  "part": "part.ddf",
  "segmentation": {"method": "curvatureType", "minFaces": 12},
  "regions": [{"region": "all", "field": "fixed", "direction": [0, 1, 0], "smooth": false,
               "spacingMm": 3}],
  "exports": [{"format": "csv", "file": "paths.csv", "perRegion": true}]
})");
  const RunResult run = cli(dir, {"run", (dir / "job.json").string()});
  ASSERT_EQ(run.exitCode, 0) << run.err;
  const planning::Project project = readProject(dir / "job.ddfproj");
  ASSERT_GE(project.regions.size(), 2u);
  ASSERT_EQ(project.paths.size(), project.regions.size());
  std::size_t cuts = 0, poses = 0;
  for (std::size_t r = 0; r < project.regions.size(); ++r) {
    const auto file = toolPathCsvFileFor(dir / "paths.csv", project.regions[r].name);
    ASSERT_TRUE(std::filesystem::exists(file)) << file;
    for (const planning::ClPoint& p : readToolPathCsv(file).points)
      cuts += p.move == planning::MoveKind::Cut ? 1 : 0;
    poses += project.paths[r].poses.size();
  }
  EXPECT_EQ(cuts, poses);
}

TEST(CliRun, TransverseFamilyWithALibraryTool) {
  test::ScratchDir dir;
  writeCoarseDemoPart(dir / "part.ddf");
  const planning::Tool ball{.name = "ball R3", .kind = planning::ToolKind::Sphere, .radiusMm = 3};
  writeText(dir / "tools.txt", formatToolLibrary({planning::Tool{}, ball}));
  writeText(dir / "job.json", R"({
  "part": "part.ddf",
  "toolLibrary": "tools.txt",
  "regions": [{"tool": 1, "field": "fixed", "direction": [1, 0, 0], "smooth": false,
               "lines": "transverse", "spacingMm": 5, "link": false}]
})");
  const RunResult run = cli(dir, {"run", (dir / "job.json").string()});
  ASSERT_EQ(run.exitCode, 0) << run.err;
  const planning::Project project = readProject(dir / "job.ddfproj");
  ASSERT_EQ(project.tools.size(), 2u);
  EXPECT_TRUE(project.tools[1] == ball);
  ASSERT_EQ(project.paths.size(), 1u);
  EXPECT_EQ(project.paths[0].name, "streamline family 1");
  EXPECT_EQ(project.paths[0].tool, 1);
  // Lines along x every 5 mm across the 30 mm of y: about six passes.
  EXPECT_GE(project.paths[0].passStarts.size(), 5u);
  EXPECT_LE(project.paths[0].passStarts.size(), 7u);
  EXPECT_EQ(project.regions[0].plan.tool, 1);
}

// A job's scallop height sets the spacing by the formula for a ball on a plane, and its feed
// sign the cutting direction: with one-direction linking every pass runs against +x.
TEST(CliRun, ScallopHeightAndFeedSignReachThePath) {
  test::ScratchDir dir;
  std::filesystem::create_directories(dir.path());
  writeDdf(ddf::planePatch({}).ddf, dir / "plane.ddf");  // 40 x 30 mm
  writeText(dir / "job.json", R"({
  "part": "plane.ddf",
  "tools": [{"name": "ball", "kind": "sphere", "radiusMm": 5}],
  "regions": [{"field": "fixed", "direction": [1, 0, 0], "smooth": false,
               "scallopMm": 0.05, "feedSign": -1, "linking": "oneDirection"}]
})");
  const RunResult run = cli(dir, {"run", (dir / "job.json").string()});
  ASSERT_EQ(run.exitCode, 0) << run.err;
  const planning::Project project = readProject(dir / "job.ddfproj");
  ASSERT_EQ(project.paths.size(), 1u);
  EXPECT_EQ(project.regions[0].plan.spacingMode, planning::SpacingMode::ScallopTolerance);
  const planning::ToolPath& path = project.paths[0];
  const double spacing = 2.0 * std::sqrt(2.0 * 5.0 * 0.05 - 0.05 * 0.05);
  const double passes = static_cast<double>(path.passStarts.size());
  EXPECT_NEAR(passes, 30.0 / spacing, 2.5) << "spacing " << spacing << " mm";
  for (std::size_t s = 0; s < path.passStarts.size(); ++s) {
    const std::size_t end =
        s + 1 < path.passStarts.size() ? path.passStarts[s + 1] - 1 : path.poses.size() - 1;
    EXPECT_LT(path.poses[end].contact.x(), path.poses[path.passStarts[s]].contact.x() - 10.0)
        << "pass " << s;
  }
}

TEST(CliRun, ScallopHeightNeedsEvenLines) {
  test::ScratchDir dir;
  writeCoarseDemoPart(dir / "part.ddf");
  writeText(dir / "job.json", R"({"part": "part.ddf",
  "regions": [{"lines": "transverse", "scallopMm": 0.05}]})");
  const RunResult run = cli(dir, {"run", (dir / "job.json").string()});
  EXPECT_NE(run.exitCode, 0);
  EXPECT_THAT(run.err, HasSubstr("scallopMm"));
}

/// Plane z = 0.25 over x in [0, 2] (feed), y in [0, 20] (cross-feed): the part of the iso-scallop
/// oracle of tests/planning/spacing_refinement_test.cpp.
ddf::GeneratedSurface refinementPlane() {
  return ddf::planePatch({.size = {2.0, 20.0}, .cellsX = 1, .cellsY = 10, .m = 13});
}

TEST(CliRun, RefinedLinesMeetTheToleranceWithTheIsoScallopCount) {
  test::ScratchDir dir;
  const ddf::GeneratedSurface plane = refinementPlane();
  writeDdf(plane.ddf, dir / "plane.ddf");
  // The simulation starts from the stock refineSpacing assumes (2.5 x tolerance) and cuts
  // pose by pose like it, so the ground part must meet the refinement's tolerance.
  writeText(dir / "job.json", R"({
  "part": "plane.ddf",
  "tools": [{"name": "ball R5", "kind": "sphere", "radiusMm": 5, "segments": 96}],
  "regions": [{"field": "fixed", "direction": [1, 0, 0], "smooth": false, "lines": "refined",
               "toleranceMm": 0.05}],
  "simulation": {"allowanceMm": 0.125, "mode": "discrete"},
  "errorMap": {"lowerMm": -0.05, "upperMm": 0.05}
})");
  const RunResult run = cli(dir, {"run", (dir / "job.json").string()});
  ASSERT_EQ(run.exitCode, 0) << run.err;
  const planning::Project project = readProject(dir / "job.ddfproj");
  ASSERT_EQ(project.paths.size(), 1u);
  EXPECT_EQ(project.paths[0].name, "refined spacing");
  // Iso-scallop oracle: 20 mm across at the ball's analytic spacing on a plane.
  const double spacing = *planning::scallopSpacingMm(5.0, 0.0, 0.05);
  const int analytic = static_cast<int>(std::ceil(20.0 / spacing));
  const int passes = static_cast<int>(project.paths[0].passStarts.size());
  EXPECT_LE(std::abs(passes - analytic), 0.1 * analytic) << passes << " passes, " << analytic;
  // Material left measured from the saved heights against the exact plane.
  const ddf::DisplacementField& ground = *project.part;
  double worst = -1e9;
  for (int f = 0; f < ground.faceCount(); ++f)
    for (int k = 0; k < ground.resolution(); ++k)
      for (int i = 0; i + k < ground.resolution(); ++i)
        worst = std::max(worst, plane.surface->value(ground.surfacePoint(f, i, k)));
  EXPECT_GT(worst, 0.0) << "scallops stay between the passes";
  EXPECT_LE(worst, 0.05 + 1e-4);
  const auto field = std::ranges::find(project.fields, std::string("refinement error"),
                                       &planning::ScalarField::name);
  ASSERT_NE(field, project.fields.end());
  const nlohmann::json report = nlohmann::json::parse(test::readBytes(dir / "report.json"));
  EXPECT_LE(report["error_map"]["max_mm"].get<double>(), 0.05 + 1e-4);
  EXPECT_EQ(report["paths"][0]["lines"].get<int>(), passes);
}

/// Runs @p job and expects a failure (exit 1) whose message holds every one of @p words.
void expectFailure(const std::string& job, const std::vector<std::string>& words) {
  test::ScratchDir dir;
  writeText(dir / "job.json", job);
  const RunResult run =
      cli(dir, {"run", (dir / "job.json").string(), "--out", (dir / "out").string()});
  EXPECT_EQ(run.exitCode, 1) << run.err;
  for (const std::string& w : words) EXPECT_THAT(run.err, HasSubstr(w));
  EXPECT_FALSE(std::filesystem::exists(dir / "out" / "job.ddfproj"));
}

TEST(CliRun, PartInMetresIsConvertedInItsUnit) {
  test::ScratchDir dir;
  // A 0.2 x 0.1 m saddle: in mm its design mesh and part span 200 x 100 mm.
  ddf::TriangleMesh saddle;
  for (int j = 0; j <= 4; ++j)
    for (int i = 0; i <= 8; ++i)
      saddle.vertices.emplace_back(
          0.025 * i, 0.025 * j,
          0.5 * ((0.025 * i - 0.1) * (0.025 * i - 0.1) - (0.025 * j - 0.05) * (0.025 * j - 0.05)));
  for (int j = 0; j < 4; ++j)
    for (int i = 0; i < 8; ++i) {
      const int a = 9 * j + i;
      saddle.triangles.push_back({a, a + 1, a + 10});
      saddle.triangles.push_back({a, a + 10, a + 9});
    }
  writeMesh(saddle, dir / "saddle_m.obj");
  writeText(dir / "job.json", R"({
  "part": {"file": "saddle_m.obj", "units": "m", "support": "input", "resolution": 4},
  "regions": [{"field": "fixed", "direction": [0, 1, 0], "smooth": false, "spacingMm": 40}]
})");
  const RunResult run = cli(dir, {"run", (dir / "job.json").string()});
  ASSERT_EQ(run.exitCode, 0) << run.err;
  EXPECT_THAT(run.err, Not(HasSubstr("units across")));
  const planning::Project project = readProject(dir / "job.ddfproj");
  EXPECT_EQ(project.sourceUnit, ddfcam::LengthUnit::Metre);
  ASSERT_TRUE(project.part && project.designMesh);
  EXPECT_EQ(project.part->faceCount(), 64);  // the input support, not reduced
  EXPECT_EQ(project.part->resolution(), 4);
  const auto [lo, hi] = project.designMesh->bounds();
  EXPECT_NEAR((hi - lo).x(), 200.0, 1e-9);
  EXPECT_NEAR((hi - lo).y(), 100.0, 1e-9);
  for (int v = 0; v < project.part->vertexCount(); ++v)
    EXPECT_LE(project.part->position(v).x(), 200.0 + 1e-6);
  // Without "units" the file is read as mm, and its size (0.2237 across: 0.2 x 0.1 x 0.00625) draws
  // the warning naming the job file's key and the size the part would have in metres.
  writeText(dir / "job.json", R"({
  "part": {"file": "saddle_m.obj", "support": "input", "resolution": 4},
  "regions": [{"field": "fixed", "direction": [0, 1, 0], "smooth": false, "spacingMm": 0.04}]
})");
  const RunResult unstated = cli(dir, {"run", (dir / "job.json").string()});
  ASSERT_EQ(unstated.exitCode, 0) << unstated.err;
  EXPECT_THAT(unstated.err, HasSubstr("saddle_m.obj is 0.2237 units across; if it is not in mm, "
                                      "set \"units\" in the job's \"part\" object (as m it would "
                                      "be 223.7 mm)"));
}

TEST(CliRun, BadPartConversionKeysAreNamed) {
  expectFailure(R"({"part": {"file": "x.stl", "units": "ft"}})", {"part.units", "mm, cm, m or in"});
  expectFailure(R"({"part": {"file": "x.stl", "support": "coarse"}})",
                {"part.support", "input|reduced"});
  expectFailure(R"({"part": {"file": "x.stl", "toleranceMm": 0.1, "rasterSpacingMm": 1}})",
                {"part.rasterSpacingMm", "not both"});
}

TEST(CliRun, BadJsonNamesLineAndColumn) {
  expectFailure("{\n  \"part\": \"demo\",\n  \"regions\": [}\n}", {"job.json", "line 3"});
}

TEST(CliRun, UnknownKeyIsRefusedByName) {
  expectFailure(R"({"part": "demo", "regions": [{"spacingMM": 4}]})",
                {"job.json", "regions[0].spacingMM", "unknown key"});
  expectFailure(R"({"part": "demo", "simulaton": {}})", {"simulaton", "unknown key"});
}

TEST(CliRun, MissingPartFileIsNamed) {
  expectFailure(R"({"part": "no_such_part.stl"})", {"no_such_part.stl"});
}

TEST(CliRun, UnknownFormatIsNamed) {
  expectFailure(R"({"part": "demo", "exports": [{"format": "step", "file": "x.step"}]})",
                {"exports[0].format", "'step'"});
}

TEST(CliRun, MissingJobFileFails) {
  test::ScratchDir dir;
  const RunResult run = cli(dir, {"run", (dir / "nothing.json").string()});
  EXPECT_EQ(run.exitCode, 1);
  EXPECT_THAT(run.err, HasSubstr("nothing.json"));
}

}  // namespace
}  // namespace ddfcam::io
