// SPDX-License-Identifier: MIT
// ddfcam-cli option tables: every command's --help lists its options, bad usage exits with 2.
#include <gmock/gmock.h>
#include <gtest/gtest.h>

#include "arguments.h"
#include "cli_convert_support.h"

#include <map>
#include <sstream>
#include <string>
#include <vector>

namespace ddfcam::cli {
namespace {

using ::testing::HasSubstr;

/// The options each command documents (docs and the earlier hand-written help), -h aside.
const std::map<std::string, std::vector<std::string>>& documentedOptions() {
  static const std::vector<std::string> kConversion = {
      "--units",          "--support", "--resolution",     "--tolerance",
      "--raster-spacing", "--stock",   "--weld-tolerance", "--max-vector-length"};
  static const std::map<std::string, std::vector<std::string>> kOptions = [] {
    std::map<std::string, std::vector<std::string>> m = {
        {"convert", {"-o, --output", "--allow-invalid"}},
        {"extract", {"-o, --output", "--eps"}},
        {"info", {"--json"}},
        {"demo", {"--out", "--no-timings"}},
        {"run", {"--out", "--no-timings"}},
        {"curvature", {"-o, --output", "--csv", "--step", "--units"}},
        {"plan",
         {"-o, --output", "--units",   "--field",   "--direction",     "--no-smooth", "--method",
          "--seeding",    "--spacing", "--scallop", "--smooth-window", "--fair",      "--linking",
          "--point",      "--tool",    "--radius",  "--corner-radius", "--lead",      "--tilt",
          "--tolerance",  "--step",    "--feed",    "--decimals"}},
        {"simulate",
         {"--paths",
          "--path-units",
          "--rotate",
          "--translate",
          "--keep-rapids",
          "--vectors",
          "--points",
          "-o, --output",
          "--error-map",
          "--report",
          "--min-coverage",
          "--strict",
          "--tool",
          "--radius",
          "--width",
          "--corner-radius",
          "--tool-file",
          "--tool-name",
          "--lead",
          "--tilt",
          "--sample-tolerance",
          "--step",
          "--allowance",
          "--stock-mesh",
          "--units",
          "--swept",
          "--correct",
          "--correct-every",
          "--correct-grid",
          "--preston",
          "--kp",
          "--force",
          "--wheel-speed",
          "--feed",
          "--infeed",
          "--tolerance",
          "--no-vconvexity-check"}},
        {"paths",
         {"-o, --output", "--format", "--units", "--decimals", "--vector-decimals", "--dialect",
          "--machine", "--in-units", "--tool", "--radius", "--corner-radius"}},
        {"compare",
         {"-o, --output", "--csv", "--json", "--units", "--resolution", "--tolerance", "--band",
          "--flip-normal", "--align", "--max-stages", "--reach", "--min-coverage", "--strict"}},
        {"compensate",
         {"--formed", "--model-alpha", "--model-axes", "--calibrate-from", "--lambda",
          "--iterations", "--out-dir", "--json", "--units", "--resolution", "--reach"}}};
    for (const char* command : {"convert", "info"})
      m[command].insert(m[command].end(), kConversion.begin(), kConversion.end());
    return m;
  }();
  return kOptions;
}

/// Whether a line of @p help starts with @p option as an option entry ("  --name VALUE ...").
bool listsOption(const std::string& help, const std::string& option) {
  std::istringstream lines(help);
  const std::string entry = "  " + option;
  for (std::string line; std::getline(lines, line);)
    if (line.rfind(entry, 0) == 0 && (line.size() == entry.size() || line[entry.size()] == ' '))
      return true;
  return false;
}

TEST(CliOptions, HelpOfEveryCommandListsEachOption) {
  test::ScratchDir dir;
  for (const auto& [command, options] : documentedOptions()) {
    const test::ConvertRun help = test::runCli(dir, {command, "--help"});
    ASSERT_EQ(help.exitCode, 0) << command << ": " << help.err;
    EXPECT_THAT(help.out, HasSubstr("usage: ddfcam-cli " + command)) << command;
    EXPECT_TRUE(listsOption(help.out, "-h, --help")) << command;
    for (const std::string& option : options)
      EXPECT_TRUE(listsOption(help.out, option)) << command << " --help lacks " << option;
  }
}

TEST(CliOptions, UnknownOptionFailsWithExitCode2NamingIt) {
  test::ScratchDir dir;
  for (const auto& entry : documentedOptions()) {
    const std::string& command = entry.first;
    const test::ConvertRun run = test::runCli(dir, {command, "in.ddf", "--no-such-option"});
    EXPECT_EQ(run.exitCode, 2) << command << ": " << run.err;
    EXPECT_THAT(run.err, HasSubstr("unknown option --no-such-option for '" + command + "'"));
  }
}

TEST(CliOptions, NonNumberValueFailsWithExitCode2NamingTheOption) {
  test::ScratchDir dir;
  // One number option per command that has any; the value is checked before any file is read.
  const std::vector<std::pair<std::string, std::string>> cases = {
      {"convert", "--resolution"},    {"extract", "--eps"},       {"info", "--stock"},
      {"curvature", "--step"},        {"plan", "--spacing"},      {"simulate", "--radius"},
      {"paths", "--vector-decimals"}, {"compare", "--tolerance"}, {"compensate", "--lambda"}};
  for (const auto& [command, option] : cases) {
    for (const std::vector<std::string>& words :
         {std::vector<std::string>{command, "in.ddf", option, "lots"},
          std::vector<std::string>{command, "in.ddf", option + "=lots"}}) {
      const test::ConvertRun run = test::runCli(dir, words);
      EXPECT_EQ(run.exitCode, 2) << words.back() << ": " << run.err;
      EXPECT_THAT(run.err, HasSubstr(option + " expects")) << command;
      EXPECT_THAT(run.err, HasSubstr("'lots'")) << command;
    }
  }
}

/// A small table as a command declares it.
Arguments exampleTable() {
  Arguments args("example", "example IN [options]", "An example.");
  args.positional("IN", "input");
  args.option("-o,--output", "FILE", "output");
  args.option("--count", "N", "a count")->check(integerIn(1, 9))->default_str("3");
  args.option("--size", "MM", "a size")->check(positiveNumber());
  args.flag("--fast", "a flag");
  return args;
}

TEST(CliOptions, TableParsesLongShortAndInlineValuesWithDefaults) {
  Arguments args = exampleTable();
  const std::vector<std::string> words = {"a.stl", "-o", "b.ddf", "--size=2.5", "--fast"};
  args.parse(words);
  EXPECT_EQ(args.positionals(), std::vector<std::string>{"a.stl"});
  EXPECT_EQ(args.value("output"), "b.ddf");
  EXPECT_EQ(args.number("size"), 2.5);
  EXPECT_TRUE(args.has("fast"));
  EXPECT_FALSE(args.has("count"));
  EXPECT_EQ(args.integer("count", 0), 3);  // the table's default
  Arguments other = exampleTable();
  const std::vector<std::string> longForm = {"--output", "c.ddf", "--count", "9", "x"};
  other.parse(longForm);
  EXPECT_EQ(other.value("output"), "c.ddf");
  EXPECT_EQ(other.integer("count", 0), 9);
  EXPECT_EQ(other.positionals(), std::vector<std::string>{"x"});
  EXPECT_FALSE(other.number("size").has_value());
}

TEST(CliOptions, TableRejectsBadUsageNamingTheWord) {
  const auto message = [](std::vector<std::string> words) {
    Arguments args = exampleTable();
    try {
      args.parse(words);
    } catch (const UsageError& e) {
      return std::string(e.what());
    }
    return std::string("(accepted)");
  };
  EXPECT_EQ(message({"a", "--count", "0"}), "--count expects an integer in [1, 9], got '0'");
  EXPECT_EQ(message({"a", "--size", "-1"}), "--size expects a positive number, got '-1'");
  EXPECT_EQ(message({"a", "-o"}), "option -o needs a value");
  EXPECT_EQ(message({"a", "--fast=yes"}), "option --fast takes no value");
  EXPECT_EQ(message({"a", "--slow"}), "unknown option --slow for 'example'");
  EXPECT_EQ(message({"a", "b"}), "'example': unexpected argument 'b'");
}

}  // namespace
}  // namespace ddfcam::cli
