// SPDX-License-Identifier: MIT
// ddfcam-cli convert on the shared third-party meshes: after convert, either info's check of
// the written file passes, or convert said which constraints fail (and wrote nothing).
#include <gmock/gmock.h>
#include <gtest/gtest.h>

#include "cli_convert_support.h"

namespace ddfcam::io {
namespace {

using ::testing::HasSubstr;

class CliConvertShared : public ::testing::TestWithParam<const char*> {};

/// Whether convert's warnings name constraint @p c as failing.
bool namesFailure(const std::string& err, int c) {
  return std::regex_search(
      err, std::regex("constraint " + std::to_string(c) + " \\([^)]*\\) fails at [0-9]+ "));
}

TEST_P(CliConvertShared, EitherInfoValidatesTheResultOrConvertSaidItDoesNot) {
  const auto mesh = std::filesystem::path(DDFCAM_SHARED_DATA_DIR) / "meshes" / GetParam();
  if (!std::filesystem::exists(mesh)) GTEST_SKIP() << "shared data not found at " << mesh;
  test::ScratchDir dir;
  const auto output = (dir / "part.ddf").string();
  const auto run = test::runCli(dir, {"convert", mesh.string(), "-o", output});
  RecordProperty("convert_exit_code", run.exitCode);
  if (run.exitCode == 0) {
    EXPECT_THAT(run.out, HasSubstr("valid DDF"));
    const auto info = test::runCli(dir, {"info", output, "--json"});
    ASSERT_EQ(info.exitCode, 0) << info.err;
    EXPECT_TRUE(test::infoSaysValid(info.out))
        << "convert reported success but info finds the DDF invalid:\n"
        << info.out;
    return;
  }
  ASSERT_EQ(run.exitCode, 3) << run.err;
  EXPECT_THAT(run.err, HasSubstr("INVALID DDF: violates"));
  EXPECT_FALSE(std::filesystem::exists(output));
  // Written anyway, the file fails info's check on exactly the constraints convert named.
  const auto allowed =
      test::runCli(dir, {"convert", mesh.string(), "-o", output, "--allow-invalid"});
  ASSERT_EQ(allowed.exitCode, 0) << allowed.err;
  const auto info = test::runCli(dir, {"info", output, "--json"});
  ASSERT_EQ(info.exitCode, 0) << info.err;
  EXPECT_FALSE(test::infoSaysValid(info.out));
  for (int c = 1; c <= 3; ++c)
    EXPECT_EQ(namesFailure(run.err, c),
              test::jsonInteger(info.out, "constraint" + std::to_string(c)) > 0)
        << "constraint " << c << "\nconvert:\n"
        << run.err << "\ninfo:\n"
        << info.out;
}

/// A shared STEP file, or an empty path when the shared data is missing.
std::filesystem::path sharedCad(const char* name) {
  const auto file = std::filesystem::path(DDFCAM_SHARED_DATA_DIR) / "cad" / name;
  return std::filesystem::exists(file) ? file : std::filesystem::path{};
}

TEST(CliConvertCad, StepConvertsAndInfoNamesItsCadFaces) {
  // revolved_sphere.step (cad/SOURCES.md): one ADVANCED_FACE on a SPHERICAL_SURFACE, radius
  // 5 mm, in mm.
  const auto step = sharedCad("revolved_sphere.step");
  if (step.empty()) GTEST_SKIP() << "shared CAD data not found";
  test::ScratchDir dir;
  const auto output = (dir / "sphere.ddf").string();
  const auto run =
      test::runCli(dir, {"convert", step.string(), "-o", output, "--tolerance", "0.05"});
  ASSERT_EQ(run.exitCode, 0) << run.err;
  EXPECT_THAT(run.out, HasSubstr("unit: mm (stated by the file)"));
  EXPECT_THAT(run.out, HasSubstr("bounds [-5, -5, -5] to [5, 5, 5] mm"));
  EXPECT_THAT(run.out, HasSubstr("CAD faces: 1"));
  EXPECT_THAT(run.out, HasSubstr("within the tolerance 0.05 mm"));
  const auto info = test::runCli(dir, {"info", output});
  ASSERT_EQ(info.exitCode, 0) << info.err;
  EXPECT_THAT(info.out, HasSubstr("source unit: mm"));
  EXPECT_THAT(info.out, HasSubstr("CAD faces: 1"));
  EXPECT_THAT(info.out, HasSubstr("(sphere): "));
  EXPECT_THAT(info.out, HasSubstr("validation: ok"));
}

TEST(CliConvertCad, StepInMetresIsReadInItsOwnUnitWithoutAWarning) {
  // bolt_clip.step (cad/SOURCES.md): metres, 20 faces, about 11.7 x 5.1 x 3.2 mm.
  const auto step = sharedCad("bolt_clip.step");
  if (step.empty()) GTEST_SKIP() << "shared CAD data not found";
  test::ScratchDir dir;
  const auto info = test::runCli(
      dir, {"info", step.string(), "--json", "--support", "input", "--raster-spacing", "0.5"});
  ASSERT_EQ(info.exitCode, 0) << info.err;
  EXPECT_THAT(info.out, HasSubstr("\"sourceUnit\": \"m\""));
  EXPECT_EQ(test::jsonInteger(info.out, "cadFaces"), 20);
  EXPECT_THAT(info.err, ::testing::Not(HasSubstr("units across")));
}

INSTANTIATE_TEST_SUITE_P(SharedMeshes, CliConvertShared,
                         ::testing::Values("bun_zipper_res2.ply", "libigl-bunny.off",
                                           "turbine-blade-jigsaw.stl", "fandisk.obj",
                                           "featuretype.stl", "1002_tray_bottom.stl",
                                           "springback-deepdrawn/target_AF_bs.stl",
                                           "springback-deepdrawn/mesh_ausgerichtet1.stl"),
                         [](const auto& info) {
                           std::string name = std::filesystem::path(info.param).stem().string();
                           for (char& c : name)
                             if (!std::isalnum(static_cast<unsigned char>(c))) c = '_';
                           return name;
                         });

}  // namespace
}  // namespace ddfcam::io
