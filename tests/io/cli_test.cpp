// SPDX-License-Identifier: MIT
// Runs the ddfcam-cli executable on small inputs and checks exit codes, messages and outputs.
#include <ddfcam/io/ddf_file.h>
#include <ddfcam/io/mesh_io.h>

#include <gmock/gmock.h>
#include <gtest/gtest.h>

#include <sys/wait.h>
#include <regex>

#include "io_test_support.h"

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

/// The 3-vector under "key": {"min": [...], "max": [...]} as {min, max}.
std::array<Eigen::Vector3d, 2> jsonBox(const std::string& json, const std::string& key) {
  const std::string num = "(-?[0-9.eE+-]+)";
  const std::string vec = "\\[" + num + ", " + num + ", " + num + "\\]";
  const std::regex pattern("\"" + key + "\": \\{\"min\": " + vec + ", \"max\": " + vec + "\\}");
  std::smatch m;
  if (!std::regex_search(json, m, pattern)) {
    ADD_FAILURE() << "no box for " << key;
    return {};
  }
  return {Eigen::Vector3d(std::stod(m[1]), std::stod(m[2]), std::stod(m[3])),
          Eigen::Vector3d(std::stod(m[4]), std::stod(m[5]), std::stod(m[6]))};
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
  expectOneLineError(cli(dir, {"info"}), 2, "'info' needs an input .ddf file");
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
    const CliRun convert =
        cli(dir, {"convert", dataFile(input), "-o", ddfPath, "--resolution", "5"});
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
    EXPECT_THAT(info.out, HasSubstr("\"validation\": {\"ok\": "));
  }
}

TEST(Cli, ExtractWritesTheRasterMeshAndAnAdaptiveOne) {
  test::ScratchDir dir;
  const auto ddfPath = (dir / "bowl.ddf").string();
  ASSERT_EQ(cli(dir, {"convert", dataFile("bowl_patch.off"), "-o", ddfPath, "--resolution", "5"})
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

TEST(Cli, DemoWritesAGroundPart) {
  test::ScratchDir dir;
  const auto out = (dir / "demo").string();
  const CliRun demo = cli(dir, {"demo", "--out", out});
  ASSERT_EQ(demo.exitCode, 0) << demo.err;
  EXPECT_THAT(demo.out, HasSubstr("heights lowered"));
  const ddf::DisplacementField field = readDdf(dir / "demo" / "demo.ddf");
  // The stock sits 0.2 mm above the design inside a 1 mm crust (h ~ 0.2); the roll sinks
  // 0.02 mm below the design along the passes, so some height must now be negative.
  const auto [lo, hi] = std::minmax_element(field.allHeights().begin(), field.allHeights().end());
  EXPECT_LT(*lo, 0.0f);
  EXPECT_GT(*hi, 0.0f);
  EXPECT_GT(readMesh(dir / "demo" / "demo.stl").triangles.size(), 1000u);
}

}  // namespace
}  // namespace ddfcam::io
