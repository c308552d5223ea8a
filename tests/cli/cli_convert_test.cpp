// SPDX-License-Identifier: MIT
// ddfcam-cli convert: it says what it repaired and dropped, and an invalid result is named as
// such (non-zero exit, no file) unless --allow-invalid is given.
#include <ddfcam/io/mesh/mesh_io.h>

#include <gmock/gmock.h>
#include <gtest/gtest.h>

#include "../support/conversion_meshes.h"
#include "cli_convert_support.h"

namespace ddfcam::io {
namespace {

using test::runCli;
using ::testing::HasSubstr;
using ::testing::Not;

TEST(CliConvert, ReportsTheUnusedVerticesAndDuplicateTrianglesItDrops) {
  test::ScratchDir dir;
  writeMesh(test::gridWithStrayVerticesAndDuplicates(), dir / "grid.obj");
  const auto ddfPath = (dir / "grid.ddf").string();
  const auto run =
      runCli(dir, {"convert", (dir / "grid.obj").string(), "-o", ddfPath, "--support", "input"});
  ASSERT_EQ(run.exitCode, 0) << run.err;
  EXPECT_THAT(run.out, HasSubstr("read " + (dir / "grid.obj").string() + ": 23 vertices"));
  EXPECT_THAT(run.out, HasSubstr("  7 unused vertices dropped"));
  EXPECT_THAT(run.out, HasSubstr("  2 duplicate triangles dropped"));
  EXPECT_THAT(run.out, HasSubstr("support: 16 vertices, 18 faces"));
  EXPECT_THAT(run.out, HasSubstr("valid DDF"));
  const auto info = runCli(dir, {"info", ddfPath, "--json"});
  ASSERT_EQ(info.exitCode, 0) << info.err;
  EXPECT_TRUE(test::infoSaysValid(info.out)) << info.out;
  EXPECT_EQ(test::jsonInteger(info.out, "vertices"), 16);
}

TEST(CliConvert, AnInvalidResultIsNamedAndNotWrittenWithoutAllowInvalid) {
  test::ScratchDir dir;
  const auto input = (dir / "fan.off").string(), output = (dir / "fan.ddf").string();
  writeMesh(test::foldedFanMesh(), input);
  const auto run = runCli(dir, {"convert", input, "-o", output, "--support", "input"});
  EXPECT_EQ(run.exitCode, 3) << run.out << run.err;
  EXPECT_THAT(run.err, HasSubstr("INVALID DDF: violates constraint 1 (front-facing vectors)"));
  EXPECT_THAT(run.err, HasSubstr("fails at 1 vertex"));
  EXPECT_THAT(run.err, HasSubstr("--allow-invalid"));
  EXPECT_THAT(run.out, Not(HasSubstr("wrote")));
  EXPECT_FALSE(std::filesystem::exists(output));

  const auto allowed =
      runCli(dir, {"convert", input, "-o", output, "--support", "input", "--allow-invalid"});
  EXPECT_EQ(allowed.exitCode, 0) << allowed.err;
  EXPECT_THAT(allowed.err, HasSubstr("INVALID DDF"));
  EXPECT_THAT(allowed.out, HasSubstr("(INVALID, --allow-invalid)"));
  ASSERT_TRUE(std::filesystem::exists(output));
  // info's own check of the written file agrees with what convert said.
  const auto info = runCli(dir, {"info", output, "--json"});
  ASSERT_EQ(info.exitCode, 0) << info.err;
  EXPECT_FALSE(test::infoSaysValid(info.out)) << info.out;
  EXPECT_GE(test::jsonInteger(info.out, "constraint1"), 1);
  EXPECT_EQ(test::jsonInteger(info.out, "constraint2"), 0);
  EXPECT_EQ(test::jsonInteger(info.out, "constraint3"), 0);
}

TEST(CliConvert, HelpNamesTheOptionsThatChangeTheResult) {
  test::ScratchDir dir;
  const auto help = runCli(dir, {"convert", "--help"});
  EXPECT_EQ(help.exitCode, 0);
  for (const char* option : {"--allow-invalid", "--weld-tolerance", "--max-vector-length"})
    EXPECT_THAT(help.out, HasSubstr(option));
}

}  // namespace
}  // namespace ddfcam::io
