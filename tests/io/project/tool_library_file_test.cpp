// SPDX-License-Identifier: MIT
// Tests of the tool library text file: exact round trip, documented syntax, errors with file,
// line and column, and the committed sample library.
#include <ddfcam/error.h>
#include <ddfcam/io/project/tool_library_file.h>

#include <gmock/gmock.h>
#include <gtest/gtest.h>

#include <clocale>
#include <filesystem>
#include <fstream>
#include <string>
#include <vector>

#include "../io_test_support.h"
#include "project_test_support.h"

namespace ddfcam::io {
namespace {

using planning::Tool;
using planning::ToolKind;
using ::testing::HasSubstr;

std::string ioError(const std::string& text, const std::string& name = "lib.txt") {
  try {
    parseToolLibrary(text, name);
  } catch (const IoError& e) {
    return e.what();
  }
  ADD_FAILURE() << "accepted: " << text;
  return {};
}

TEST(ToolLibraryFile, EveryKindRoundTripsExactly) {
  const std::vector<Tool> tools = test::toolsOfEveryKind();
  EXPECT_EQ(parseToolLibrary(formatToolLibrary(tools), "mem"), tools);
  test::ScratchDir dir;
  writeToolLibrary(dir / "tools.txt", tools);
  EXPECT_EQ(readToolLibrary(dir / "tools.txt"), tools);
  EXPECT_TRUE(parseToolLibrary("", "empty").empty());
}

TEST(ToolLibraryFile, ReadsTheDocumentedSyntax) {
  const std::string text =
      "\xEF\xBB\xBF# a library\r\n"
      "\n"
      "   tool \"b\"  segments=0 kind=ball_end\twidth_mm=1.2e1 radius_mm=3  # ball end\r\n"
      "tool \"r\" kind=cylinder_roll\n";
  const std::vector<Tool> tools = parseToolLibrary(text, "doc");
  ASSERT_EQ(tools.size(), 2u);
  const Tool ball{
      .name = "b", .kind = ToolKind::BallEnd, .radiusMm = 3.0, .widthMm = 12.0, .segments = 0};
  EXPECT_EQ(tools[0], ball);
  EXPECT_EQ(tools[1], (Tool{.name = "r"}));  // every other key at planning::Tool's default
}

TEST(ToolLibraryFile, NumbersDoNotDependOnTheLocale) {
  // A decimal-comma locale, if installed, must not change what is written or read.
  const std::string previous = std::setlocale(LC_ALL, nullptr);
  std::setlocale(LC_ALL, "de_DE.UTF-8");
  const std::string text = formatToolLibrary(test::toolsOfEveryKind());
  const std::vector<Tool> back = parseToolLibrary(text, "mem");
  std::setlocale(LC_ALL, previous.c_str());
  EXPECT_THAT(text, HasSubstr("radius_mm=0.3333333333333333 "));
  EXPECT_EQ(back, test::toolsOfEveryKind());
}

TEST(ToolLibraryFile, ErrorsNameFileLineAndColumn) {
  EXPECT_THAT(ioError("# ok\ntool \"a\" kind=flat_end diameter_mm=3\n"),
              HasSubstr("lib.txt:2:24: unknown key 'diameter_mm'"));
  EXPECT_THAT(ioError("tool \"a\" kind=drill\n"),
              HasSubstr("lib.txt:1:15: unknown tool kind 'drill'"));
  EXPECT_THAT(ioError("tool \"a\" radius_mm=3\n"), HasSubstr("lib.txt:1:1: tool 'a' has no kind"));
  EXPECT_THAT(ioError("tool \"a\" kind=sphere radius_mm=3,5\n"),
              HasSubstr("lib.txt:1:32: '3,5' is not a finite number (key 'radius_mm')"));
  EXPECT_THAT(ioError("tool \"a\" kind=sphere radius_mm=inf\n"), HasSubstr("not a finite number"));
  EXPECT_THAT(ioError("tool \"a\" kind=sphere segments=4.5\n"),
              HasSubstr("lib.txt:1:31: '4.5' is not an integer (key 'segments')"));
  EXPECT_THAT(ioError("tool \"a\" kind=sphere kind=sphere\n"),
              HasSubstr("lib.txt:1:22: key 'kind' given twice"));
  EXPECT_THAT(ioError("tool \"a kind=sphere\n"),
              HasSubstr("lib.txt:1:6: the tool name has no closing double quote"));
  EXPECT_THAT(ioError("tool a kind=sphere\n"), HasSubstr("lib.txt:1:6: expected the tool name"));
  EXPECT_THAT(ioError("tool \"a\\q\" kind=sphere\n"), HasSubstr("lib.txt:1:8: unknown escape"));
  EXPECT_THAT(ioError("tol \"a\" kind=sphere\n"), HasSubstr("lib.txt:1:1: expected a line"));
  EXPECT_THAT(ioError("tool \"a\" kind=sphere radius\n"),
              HasSubstr("lib.txt:1:22: expected key=value, found 'radius'"));
  // A tool that parses but cannot be built: validateTool's message, at its line.
  EXPECT_THAT(ioError("\n\ntool \"w\" kind=cylinder_roll width_mm=-2\n"),
              HasSubstr("lib.txt:3:1: tool 'w': width -2 mm is not positive"));
}

TEST(ToolLibraryFile, InvalidToolsAreNotWritten) {
  test::ScratchDir dir;
  std::vector<Tool> tools = test::toolsOfEveryKind();
  tools[2].edgeRadiusMm = 100.0;
  EXPECT_THROW(writeToolLibrary(dir / "bad.txt", tools), InvalidInput);
  EXPECT_FALSE(std::filesystem::exists(dir / "bad.txt"));
  EXPECT_THROW(readToolLibrary(dir / "missing.txt"), IoError);
}

TEST(ToolLibraryFile, CommittedSampleLibraryLoads) {
  const auto path = std::filesystem::path(DDFCAM_TEST_DATA_DIR) / ".." / ".." / "resources" /
                    "tools" / "default_tools.txt";
  const std::vector<Tool> tools = readToolLibrary(path);
  ASSERT_EQ(tools.size(), 6u);
  std::vector<ToolKind> kinds;
  for (const Tool& tool : tools) kinds.push_back(tool.kind);
  EXPECT_EQ(kinds, (std::vector<ToolKind>{ToolKind::CylinderRoll, ToolKind::BeltContactWheel,
                                          ToolKind::Sphere, ToolKind::BallEnd, ToolKind::FlatEnd,
                                          ToolKind::TorusCutter}));
  EXPECT_EQ(tools[1].name, "contact wheel D100 W25");
  EXPECT_EQ(tools[1].crownRadiusMm, 200.0);
  EXPECT_EQ(tools[5].edgeRadiusMm, 2.0);
  EXPECT_EQ(tools[5].holderLengthMm, 45.0);
}

}  // namespace
}  // namespace ddfcam::io
