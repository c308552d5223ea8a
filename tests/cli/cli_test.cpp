// SPDX-License-Identifier: MIT
// Runs the ddfcam-cli executable on small inputs and checks exit codes, messages and outputs.
#include <ddfcam/ddf/analytic_generators.h>
#include <ddfcam/io/mesh/ddf_file.h>
#include <ddfcam/io/mesh/mesh_io.h>
#include <ddfcam/io/project/project_file.h>

#include <gmock/gmock.h>
#include <gtest/gtest.h>
#include <nlohmann/json.hpp>

#include <sys/wait.h>
#include <regex>
#include <sstream>

#include "../io/io_test_support.h"

namespace ddfcam::io {
namespace {

using ::testing::HasSubstr;

struct CliRun {
  int exitCode = -1;
  std::string out;
  std::string err;
};

std::string quote(const std::string& word) {
  std::string quoted = "'";  // piecewise: "lit" + string trips GCC 12's -Wrestrict
  quoted += word;
  return quoted + "'";
}

/// Runs ddfcam-cli with @p args (no shell expansion inside the words).
CliRun cli(const test::ScratchDir& dir, const std::vector<std::string>& args) {
  std::string command = quote(DDFCAM_CLI_PATH);
  for (const auto& a : args) command.append(" ").append(quote(a));
  const auto out = dir / "stdout.txt", err = dir / "stderr.txt";
  command += " > " + quote(out.string()) + " 2> " + quote(err.string()) + " < /dev/null";
  const int status = std::system(command.c_str());
  CliRun run;
  run.exitCode = WIFEXITED(status) ? WEXITSTATUS(status) : -1;
  run.out = test::readBytes(out);
  run.err = test::readBytes(err);
  return run;
}

std::string dataFile(const std::string& name) {
  return (std::filesystem::path(DDFCAM_TEST_DATA_DIR) / name).string();
}

/// The number after "key": in a JSON text.
double jsonNumber(const std::string& json, const std::string& key) {
  std::smatch match;
  const std::regex pattern("\"" + key + "\": (-?[0-9.eE+-]+)");
  if (!std::regex_search(json, match, pattern)) {
    ADD_FAILURE() << "no number for " << key << " in " << json;
    return 0.0;
  }
  return std::stod(match[1]);
}

/// The box under "key": {"min": [x, y, z], "max": [x, y, z]} as {min, max}.
std::array<Eigen::Vector3d, 2> jsonBox(const std::string& json, const std::string& key) {
  const nlohmann::json box = nlohmann::json::parse(json).value(key, nlohmann::json());
  const auto corner = [&](const char* name) {
    const nlohmann::json& c = box.at(name);
    return Eigen::Vector3d(c.at(0).get<double>(), c.at(1).get<double>(), c.at(2).get<double>());
  };
  if (!box.is_object() || box.size() != 2) {
    ADD_FAILURE() << "no box for " << key;
    return {};
  }
  return {corner("min"), corner("max")};
}

void expectOneLineError(const CliRun& run, int code, const std::string& text) {
  EXPECT_EQ(run.exitCode, code) << run.err;
  EXPECT_EQ(std::count(run.err.begin(), run.err.end(), '\n'), 1) << run.err;
  EXPECT_THAT(run.err, HasSubstr(text));
}

TEST(Cli, HelpForTheToolAndEveryCommand) {
  test::ScratchDir dir;
  const CliRun top = cli(dir, {"--help"});
  EXPECT_EQ(top.exitCode, 0);
  for (const char* command : {"convert", "extract", "info", "demo"}) {
    EXPECT_THAT(top.out, HasSubstr(command));
    const CliRun help = cli(dir, {command, "--help"});
    EXPECT_EQ(help.exitCode, 0);
    EXPECT_THAT(help.out, HasSubstr(std::string("usage: ddfcam-cli ") + command));
  }
}

TEST(Cli, BadArgumentsGiveOneLineAndExitCode2) {
  test::ScratchDir dir;
  expectOneLineError(cli(dir, {}), 2, "missing command");
  expectOneLineError(cli(dir, {"grind"}), 2, "unknown command 'grind'");
  const std::string off = dataFile("bowl_patch.off");
  expectOneLineError(cli(dir, {"convert", off, "-o", "x.ddf", "--fast"}), 2,
                     "unknown option --fast for 'convert'");
  expectOneLineError(cli(dir, {"convert", off, "-o", "x.ddf", "--resolution", "1"}), 2,
                     "--resolution expects an integer in [2, 1024], got '1'");
  expectOneLineError(cli(dir, {"convert", off}), 2, "'convert' needs --output");
  expectOneLineError(cli(dir, {"convert", off, "-o"}), 2, "option -o needs a value");
  expectOneLineError(cli(dir, {"extract", "a.ddf", "-o", "b.txt"}), 2, "must end in .stl");
  expectOneLineError(cli(dir, {"extract", "a.ddf", "-o", "b.stl", "--eps", "-1"}), 2,
                     "--eps expects a positive number");
  expectOneLineError(cli(dir, {"info"}), 2, "'info' needs an input .ddf, mesh or CAD file");
}

TEST(Cli, MissingOrCorruptInputGivesOneLineAndExitCode1) {
  test::ScratchDir dir;
  const std::string missing = (dir / "absent.stl").string();
  expectOneLineError(cli(dir, {"convert", missing, "-o", (dir / "x.ddf").string()}), 1,
                     "absent.stl does not exist");
  EXPECT_FALSE(std::filesystem::exists(dir / "x.ddf"));
  test::writeBytes(dir / "bad.ddf", "DDFCAM\x1a\n garbage");
  expectOneLineError(cli(dir, {"info", (dir / "bad.ddf").string()}), 1, "bad.ddf");
}

TEST(Cli, ConvertThenInfoJsonReportsTheGridNumbers) {
  test::ScratchDir dir;
  for (const char* input : {"bowl_patch.off", "bowl_patch_ascii.stl"}) {
    const auto ddfPath = (dir / "bowl.ddf").string();
    const CliRun convert = cli(dir, {"convert", dataFile(input), "-o", ddfPath, "--resolution", "5",
                                     "--support", "input"});
    ASSERT_EQ(convert.exitCode, 0) << convert.err;
    const CliRun info = cli(dir, {"info", ddfPath, "--json"});
    ASSERT_EQ(info.exitCode, 0) << info.err;
    // Oracle: a 6 x 6 cell grid has 49 vertices and 72 triangles; at m = 5 its raster is the
    // regular lattice of (6 (m-1) + 1)^2 points; heights are filled from the mesh itself, ~0.
    EXPECT_EQ(jsonNumber(info.out, "vertices"), 49);
    EXPECT_EQ(jsonNumber(info.out, "faces"), 72);
    EXPECT_EQ(jsonNumber(info.out, "resolution"), 5);
    EXPECT_EQ(jsonNumber(info.out, "pointsPerFace"), 15);
    EXPECT_EQ(jsonNumber(info.out, "storedHeights"), 72 * 15);
    EXPECT_EQ(jsonNumber(info.out, "rasterPoints"), 25 * 25);
    EXPECT_NEAR(jsonNumber(info.out, "heightMin"), 0.0, 1e-6);
    EXPECT_NEAR(jsonNumber(info.out, "heightMax"), 0.0, 1e-6);
    EXPECT_EQ(jsonNumber(info.out, "fileBytes"), std::filesystem::file_size(ddfPath));
    const auto box = jsonBox(info.out, "surfaceBounds");
    EXPECT_NEAR((box[0] - Eigen::Vector3d(0, 0, 0)).norm(), 0.0, 1e-9);
    EXPECT_NEAR((box[1] - Eigen::Vector3d(10, 10, 1)).norm(), 0.0, 1e-9);
    EXPECT_TRUE(nlohmann::json::parse(info.out)["validation"]["ok"].is_boolean()) << info.out;
  }
}

TEST(Cli, ExtractWritesTheRasterMeshAndAnAdaptiveOne) {
  test::ScratchDir dir;
  const auto ddfPath = (dir / "bowl.ddf").string();
  ASSERT_EQ(cli(dir, {"convert", dataFile("bowl_patch.off"), "-o", ddfPath, "--resolution", "5",
                      "--support", "input"})
                .exitCode,
            0);
  const auto full = (dir / "full.obj").string();
  const CliRun extract = cli(dir, {"extract", ddfPath, "-o", full});
  ASSERT_EQ(extract.exitCode, 0) << extract.err;
  const ddf::TriangleMesh raster = readMesh(full);
  EXPECT_EQ(raster.triangles.size(), 72u * 16u);  // (m-1)^2 per support face
  EXPECT_EQ(raster.vertices.size(), 625u);
  const auto adaptive = (dir / "adaptive.ply").string();
  const CliRun coarse = cli(dir, {"extract", ddfPath, "-o", adaptive, "--eps", "0.001"});
  ASSERT_EQ(coarse.exitCode, 0) << coarse.err;
  const ddf::TriangleMesh mesh = readMesh(adaptive);
  // All heights are 0, so the surface is the flat-faced support: a flat triangle per face
  // already meets any eps.
  EXPECT_GE(mesh.triangles.size(), 72u);
  EXPECT_LT(mesh.triangles.size(), raster.triangles.size());
}

TEST(Cli, DemoRunsTheBuiltInJob) {
  test::ScratchDir dir;
  const auto out = (dir / "demo").string();
  const CliRun demo = cli(dir, {"demo", "--out", out});
  ASSERT_EQ(demo.exitCode, 0) << demo.err;
  EXPECT_THAT(demo.out, HasSubstr("error map"));
  // The built-in job segments the demo part by curvature type, covers every region with lines
  // 0.9 mm apart, raises the part by 0.05 mm and grinds it with a 5 mm ball.
  const planning::Project project = readProject(dir / "demo" / "demo.ddfproj");
  ASSERT_GE(project.regions.size(), 2u);
  ASSERT_EQ(project.paths.size(), project.regions.size());
  const auto state = [&](const std::string& name) -> const std::vector<float>* {
    for (const planning::SimulationState& s : project.states)
      if (s.name == name) return &s.heights;
    return nullptr;
  };
  const std::vector<float>* design = state("design");
  const std::vector<float>* raised = state("stock +0.05 mm");
  ASSERT_TRUE(design && raised);
  const ddf::DisplacementField& ground = *project.part;
  const std::vector<float> after = ground.allHeights();
  ASSERT_EQ(after.size(), design->size());
  // Deviation along the vectors, |dh| |v|, from the saved heights alone (not the error map):
  // the scallops of 0.9 mm spacing stay within -0.01..+0.03 mm over nearly all of the part.
  std::size_t lowered = 0, inBand = 0;
  double worst = -1.0;
  for (int f = 0; f < ground.faceCount(); ++f)
    for (int k = 0; k < ground.resolution(); ++k)
      for (int i = 0; i + k < ground.resolution(); ++i) {
        const std::size_t at = f * ground.pointsPerFace() + ground.raster().index(i, k);
        const double length = ground.vectorAt(f, ground.rasterBary(i, k)).norm();
        const double deviationMm = (after[at] - (*design)[at]) * length;
        lowered += after[at] < (*raised)[at] ? 1 : 0;
        inBand += deviationMm >= -0.01 && deviationMm <= 0.03 ? 1 : 0;
        worst = std::max(worst, deviationMm);
      }
  EXPECT_GT(lowered, after.size() * 9 / 10);
  EXPECT_GT(inBand, after.size() * 95 / 100) << inBand << " of " << after.size();
  EXPECT_LE(worst, 0.05 + 1e-3);
  const std::string report = test::readBytes(dir / "demo" / "demo_report.json");
  EXPECT_THAT(report, HasSubstr("in_tolerance_percent"));
  for (const char* file : {"demo_paths.csv", "demo_paths.apt", "demo_paths.ngc",
                           "demo_error_map.vtp", "demo_report.json"})
    EXPECT_TRUE(std::filesystem::exists(dir / "demo" / file)) << file;
}

// --- ddfcam-cli curvature (section C) ---

/// A CSV text as its header and rows of numbers (strtod, so "nan" reads as NaN).
struct Csv {
  std::vector<std::string> header;
  std::vector<std::vector<double>> rows;

  std::size_t column(const std::string& name) const {
    const auto it = std::find(header.begin(), header.end(), name);
    EXPECT_NE(it, header.end()) << "no column " << name;
    return static_cast<std::size_t>(it - header.begin());
  }
};

Csv readCsv(const std::filesystem::path& path) {
  std::istringstream in(test::readBytes(path));
  Csv csv;
  std::string line;
  for (bool first = true; std::getline(in, line); first = false) {
    std::istringstream cells(line);
    std::vector<double> row;
    for (std::string cell; std::getline(cells, cell, ',');) {
      if (first)
        csv.header.push_back(cell);
      else
        row.push_back(std::strtod(cell.c_str(), nullptr));
    }
    if (!first) csv.rows.push_back(row);
  }
  return csv;
}

/// NumberOfPoints of the Piece of a .vtp file.
std::size_t vtpPointCount(const std::filesystem::path& path) {
  std::smatch match;
  const std::string text = test::readBytes(path);
  if (!std::regex_search(text, match, std::regex("<Piece NumberOfPoints=\"([0-9]+)\""))) {
    ADD_FAILURE() << "no Piece in " << path;
    return 0;
  }
  return std::stoul(match[1]);
}

/// The numbers of the DataArray named @p name in a .vtp file.
std::vector<double> vtpArray(const std::filesystem::path& path, const std::string& name) {
  const std::string text = test::readBytes(path);
  const std::string open = "Name=\"" + name + "\"";
  const std::size_t at = text.find('>', text.find(open));
  std::istringstream in(text.substr(at + 1, text.find('<', at) - at - 1));
  std::vector<double> values;
  for (double v; in >> v;) values.push_back(v);
  return values;
}

TEST(Cli, CurvatureOfASphereIsOneOverTheRadiusAtEveryPoint) {
  test::ScratchDir dir;
  const ddf::GeneratedSurface part = ddf::spherePart({.radiusMm = 5.0, .subdivisions = 2, .m = 9});
  writeDdf(part.ddf, dir / "sphere.ddf");
  const auto vtp = dir / "k.vtp", csvPath = dir / "k.csv";
  const CliRun run = cli(dir, {"curvature", (dir / "sphere.ddf").string(), "-o", vtp.string(),
                               "--csv", csvPath.string()});
  ASSERT_EQ(run.exitCode, 0) << run.err;
  EXPECT_THAT(run.out, HasSubstr("convex"));
  const std::size_t points = part.ddf.topology().pointCount();  // closed: every point has a copy
  EXPECT_EQ(vtpPointCount(vtp), points);
  const std::vector<double> vtpKMax = vtpArray(vtp, "k_max");
  ASSERT_EQ(vtpKMax.size(), points);
  for (const double k : vtpKMax) ASSERT_NEAR(k, 0.2, 2e-3);
  const Csv csv = readCsv(csvPath);
  ASSERT_EQ(csv.header.size(), 18u);
  ASSERT_EQ(csv.rows.size(), points);
  const std::size_t id = csv.column("point_id"), x = csv.column("x"), kMax = csv.column("k_max"),
                    kMin = csv.column("k_min"), umbilic = csv.column("umbilic");
  for (std::size_t r = 0; r < csv.rows.size(); ++r) {
    const std::vector<double>& row = csv.rows[r];
    ASSERT_EQ(row.size(), 18u) << "row " << r;
    ASSERT_EQ(row[id], static_cast<double>(r));  // one row per raster point, in id order
    const Eigen::Vector3d q(row[x], row[x + 1], row[x + 2]);
    ASSERT_NEAR(q.norm(), 5.0, 1e-4) << "row " << r;   // raster points lie on the sphere
    ASSERT_NEAR(row[kMax], 0.2, 2e-3) << "row " << r;  // convex from outside: +1/R
    ASSERT_NEAR(row[kMin], 0.2, 2e-3) << "row " << r;
    ASSERT_EQ(row[umbilic], 1.0) << "row " << r;
  }
}

TEST(Cli, CurvatureOfACylinderFollowsTheAxisAndDefaultsTheOutputName) {
  test::ScratchDir dir;
  const ddf::GeneratedSurface part =
      ddf::cylinderPart({.radiusMm = 2.0, .lengthMm = 4.0, .segments = 16, .rings = 4, .m = 9});
  writeDdf(part.ddf, dir / "cyl.ddf");
  const auto csvPath = dir / "cyl.csv";
  const CliRun run = cli(dir, {"curvature", (dir / "cyl.ddf").string(), "--csv", csvPath.string()});
  ASSERT_EQ(run.exitCode, 0) << run.err;
  EXPECT_EQ(vtpPointCount(dir / "cyl.vtp"), part.ddf.topology().pointCount());
  const Csv csv = readCsv(csvPath);
  ASSERT_EQ(csv.rows.size(), part.ddf.topology().pointCount());
  const std::size_t kMax = csv.column("k_max"), kMin = csv.column("k_min"),
                    dirMaxZ = csv.column("dir_max_z"), dirMinZ = csv.column("dir_min_z");
  for (const std::vector<double>& row : csv.rows) {
    ASSERT_NEAR(row[kMax], 0.5, 1e-3);  // 1/r around the axis
    ASSERT_NEAR(row[kMin], 0.0, 1e-3);  // straight along it
    ASSERT_NEAR(row[dirMaxZ], 0.0, 1e-2);
    ASSERT_NEAR(std::abs(row[dirMinZ]), 1.0, 1e-3);
  }
}

TEST(Cli, CurvatureErrorsGiveOneLine) {
  test::ScratchDir dir;
  const std::string missing = (dir / "absent.ddf").string();
  expectOneLineError(cli(dir, {"curvature", missing, "-o", (dir / "x.vtp").string()}), 1,
                     "absent.ddf");
  EXPECT_FALSE(std::filesystem::exists(dir / "x.vtp"));
  expectOneLineError(cli(dir, {"curvature", missing, "-o", "x.stl"}), 2, "must end in .vtp");
  expectOneLineError(cli(dir, {"curvature", missing, "--step", "0"}), 2,
                     "--step expects an integer");
  expectOneLineError(cli(dir, {"curvature"}), 2, "'curvature' needs an input part");
  const CliRun help = cli(dir, {"curvature", "--help"});
  EXPECT_EQ(help.exitCode, 0);
  EXPECT_THAT(help.out, HasSubstr("usage: ddfcam-cli curvature"));
}

}  // namespace
}  // namespace ddfcam::io
