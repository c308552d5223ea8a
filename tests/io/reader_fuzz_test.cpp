// SPDX-License-Identifier: MIT
// ddfcam tests: randomized robustness of the tool-path readers (only ddfcam::Error may escape).
#include <ddfcam/error.h>
#include <ddfcam/io/programs/apt_reader.h>
#include <ddfcam/io/programs/fanuc_ls_reader.h>
#include <ddfcam/io/programs/path_file.h>
#include <ddfcam/io/programs/ros_toolpath_reader.h>
#include <ddfcam/io/programs/tool_path_csv.h>

#include "fuzz_inputs.h"

#include <gtest/gtest.h>

#include <cctype>
#include <chrono>
#include <filesystem>
#include <fstream>
#include <functional>
#include <iostream>
#include <sstream>
#include <typeinfo>

namespace ddfcam::test {
namespace {

const std::string kSource = "fuzzed.txt";

using Reader = std::function<planning::ClProgram(std::string_view, const std::string&)>;

/// One reader under test: its format, how to call it, and shared files whose heads seed it.
struct ReaderCase {
  std::string name;
  FuzzFormat format;
  Reader read;
  std::vector<std::string> sharedFiles;  ///< relative to DDFCAM_SHARED_DATA_DIR/paths
};

std::ostream& operator<<(std::ostream& out, const ReaderCase& c) {
  return out << c.name;
}

std::vector<ReaderCase> readerCases() {
  std::vector<ReaderCase> cases = {
      {"csv",
       FuzzFormat::Csv,
       [](std::string_view text, const std::string& name) {
         return io::decodeToolPathCsv(text, name);
       },
       {"crs-robotic-sanding/part_2_job_0_degrees.xyzijk.csv"}},
      {"apt",
       FuzzFormat::Apt,
       [](std::string_view text, const std::string& name) { return io::decodeApt(text, name); },
       {"mech491-nx-clsf/APT_Variable_Axis.txt", "mech491-nx-clsf/APT_Zig_Zag_Smoothed.txt",
        "mech491-nx-clsf/APT_SimpleMillPlane_ZIG.txt", "nist-proe-clfile/traj1.ncl"}},
      {"ros_yaml",
       FuzzFormat::RosYaml,
       [](std::string_view text, const std::string& name) {
         return io::decodeRosToolpathYaml(text, name);
       },
       {"crs-robotic-sanding/part_2_job_0_degrees.yaml"}},
      {"fanuc_ls",
       FuzzFormat::FanucLs,
       [](std::string_view text, const std::string& name) { return io::decodeFanucLs(text, name); },
       {"crs-robotic-sanding/surface_cartesian.ls"}},
  };
  return cases;
}

std::string readText(const std::filesystem::path& file) {
  std::ifstream in(file, std::ios::binary);
  std::ostringstream text;
  text << in.rdbuf();
  return text.str();
}

/// The first @p lines lines of @p text (shared files are cut to keep each input cheap).
std::string head(const std::string& text, int lines) {
  std::size_t at = 0;
  for (int l = 0; l < lines && at != std::string::npos; ++l) {
    at = text.find('\n', at);
    if (at != std::string::npos) ++at;
  }
  return text.substr(0, at);
}

/// Mutation bases: the hand-written seeds plus the heads of the shared files that exist.
std::vector<std::string> basesFor(const ReaderCase& reader) {
  std::vector<std::string> bases = builtinSeeds(reader.format);
  const std::filesystem::path dir = std::filesystem::path(DDFCAM_SHARED_DATA_DIR) / "paths";
  for (const std::string& file : reader.sharedFiles)
    if (std::filesystem::exists(dir / file)) bases.push_back(head(readText(dir / file), 60));
  return bases;
}

/// Tallies of one fuzzing run, printed so a reader's behaviour under fuzzing is visible.
struct FuzzTally {
  int inputs = 0;
  int accepted = 0;
  int rejected = 0;
  int rejectedWithLine = 0;
  int failures = 0;
  double slowestSeconds = 0.0;
};

/// Reads @p text; records contract breaches as test failures (at most a few, with the input).
void readOne(const ReaderCase& reader, const std::string& text, FuzzTally& tally) {
  const auto start = std::chrono::steady_clock::now();
  std::optional<std::string> broken;
  try {
    const planning::ClProgram program = reader.read(text, kSource);
    ++tally.accepted;
    broken = programViolation(program, text);
  } catch (const Error& e) {
    ++tally.rejected;
    if (lineNumberIn(e.what())) ++tally.rejectedWithLine;
    broken = messageViolation(e.what(), text, kSource);
  } catch (const std::exception& e) {
    broken = std::string("foreign exception ") + typeid(e).name() + ": " + e.what();
  }
  const double seconds =
      std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
  tally.slowestSeconds = std::max(tally.slowestSeconds, seconds);
  if (seconds > 1.0) broken = "took " + std::to_string(seconds) + " s";
  ++tally.inputs;
  if (broken && ++tally.failures <= 5)
    ADD_FAILURE() << reader.name << ": " << *broken << "\ninput: \"" << escaped(text) << "\"";
}

class ReaderFuzz : public ::testing::TestWithParam<ReaderCase> {};

TEST_P(ReaderFuzz, HandWrittenSeedsParse) {
  const ReaderCase& reader = GetParam();
  for (const std::string& seed : builtinSeeds(reader.format)) {
    try {
      const planning::ClProgram program = reader.read(seed, kSource);
      EXPECT_FALSE(program.points.empty()) << escaped(seed);
      const auto broken = programViolation(program, seed);
      EXPECT_FALSE(broken) << *broken << "\n" << escaped(seed);
    } catch (const Error& e) {
      ADD_FAILURE() << e.what() << "\nseed: \"" << escaped(seed) << "\"";
    }
  }
}

TEST_P(ReaderFuzz, MutatedInputsOnlyThrowErrorsWithValidLines) {
  constexpr int kInputs = 30000;
  const ReaderCase& reader = GetParam();
  const std::vector<std::string> bases = basesFor(reader);
  // Now and then a text of another format, so readers also see foreign but plausible input.
  std::vector<std::string> foreign;
  for (const auto format :
       {FuzzFormat::Csv, FuzzFormat::Apt, FuzzFormat::RosYaml, FuzzFormat::FanucLs})
    if (format != reader.format)
      for (std::string& seed : builtinSeeds(format)) foreign.push_back(std::move(seed));
  TextMutator mutator(0xddfca3 + static_cast<std::uint64_t>(reader.format),
                      fuzzTokens(reader.format));
  std::mt19937_64 pick(42);
  FuzzTally tally;
  const auto start = std::chrono::steady_clock::now();
  for (const std::string& base : bases) readOne(reader, base, tally);
  while (tally.inputs < kInputs) {
    const bool alien = pick() % 50 == 0;
    const std::string& base =
        alien ? foreign[pick() % foreign.size()] : bases[pick() % bases.size()];
    const std::string& other = bases[pick() % bases.size()];
    readOne(reader, mutator.mutate(base, other), tally);
  }
  const double seconds =
      std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
  std::cout << "[ fuzz     ] " << reader.name << ": " << tally.inputs << " inputs in " << seconds
            << " s, " << tally.accepted << " read, " << tally.rejected << " rejected ("
            << tally.rejectedWithLine << " naming a line), slowest " << tally.slowestSeconds
            << " s, " << tally.failures << " contract breaches\n";
  EXPECT_EQ(tally.failures, 0);
  // Most rejections concern one line; a reader that never names one breaks the contract.
  EXPECT_GT(tally.rejectedWithLine, tally.rejected / 2);
}

/// True if line @p line of a seed of @p format holds a coordinate whose value the reader must
/// parse (a non-number there must be reported on that line).
bool holdsCoordinate(FuzzFormat format, std::string_view line, int number) {
  switch (format) {
    case FuzzFormat::Csv:
      return number > 1 && !line.empty() && std::isdigit(static_cast<unsigned char>(line[0]));
    case FuzzFormat::Apt:
      return line.substr(0, 4) == "GOTO";
    case FuzzFormat::RosYaml:
      return line.find("x: ") != std::string_view::npos;
    case FuzzFormat::FanucLs:
      return line.find("X =") != std::string_view::npos;
  }
  return false;
}

/// @p line with its last number (before any continuation '$') replaced by "1.2.3".
std::string spoilLastNumber(std::string line) {
  const std::size_t end = line.find_last_of("0123456789");
  std::size_t start = end;
  while (start > 0 &&
         std::string_view("0123456789.-+eE").find(line[start - 1]) != std::string_view::npos)
    --start;
  return line.replace(start, end + 1 - start, "1.2.3");
}

TEST_P(ReaderFuzz, NonNumberIsReportedOnItsLine) {
  const ReaderCase& reader = GetParam();
  const std::string seed = builtinSeeds(reader.format).front();
  std::vector<std::string> lines;
  for (std::size_t at = 0; at < seed.size();) {
    const std::size_t end = std::min(seed.find('\n', at), seed.size());
    lines.push_back(seed.substr(at, end - at));
    at = end + 1;
  }
  int spoiled = 0;
  for (std::size_t l = 0; l < lines.size(); ++l) {
    const int number = static_cast<int>(l) + 1;
    if (!holdsCoordinate(reader.format, lines[l], number)) continue;
    std::string text;
    for (std::size_t k = 0; k < lines.size(); ++k)
      text += (k == l ? spoilLastNumber(lines[k]) : lines[k]) + "\n";
    ++spoiled;
    try {
      reader.read(text, kSource);
      ADD_FAILURE() << reader.name << ": '1.2.3' on line " << number << " was accepted";
    } catch (const Error& e) {
      EXPECT_EQ(lineNumberIn(e.what()), number) << e.what();
      EXPECT_FALSE(messageViolation(e.what(), text, kSource));
    }
  }
  EXPECT_GE(spoiled, 2);
}

INSTANTIATE_TEST_SUITE_P(Readers, ReaderFuzz, ::testing::ValuesIn(readerCases()),
                         [](const auto& info) { return info.param.name; });

/// Mutated texts of every format under every extension: detection never throws, and reading
/// the file throws nothing but ddfcam::Error.
TEST(PathFileFuzz, DetectionAndDispatchOnlyThrowErrors) {
  constexpr int kDetections = 20000;
  constexpr int kFiles = 400;  // each one written to disk, so fewer
  const std::vector<std::string> extensions = {".csv", ".txt", ".apt", ".cls", ".ncl", ".yaml",
                                               ".yml", ".ls",  ".ngc", ".dat", ""};
  std::vector<std::string> bases;
  for (const auto format :
       {FuzzFormat::Csv, FuzzFormat::Apt, FuzzFormat::RosYaml, FuzzFormat::FanucLs})
    for (std::string& seed : builtinSeeds(format)) bases.push_back(std::move(seed));
  TextMutator mutator(0x9a7f11e, fuzzTokens(FuzzFormat::Apt));
  std::mt19937_64 pick(7);
  const std::filesystem::path dir =
      std::filesystem::temp_directory_path() / ("ddfcam_reader_fuzz_" + std::to_string(pick()));
  std::filesystem::create_directories(dir);
  int failures = 0;
  for (int i = 0; i < kDetections + kFiles && failures < 5; ++i) {
    const std::string text =
        mutator.mutate(bases[pick() % bases.size()], bases[pick() % bases.size()]);
    const std::filesystem::path file = dir / ("input" + extensions[pick() % extensions.size()]);
    try {
      if (i < kDetections) {
        io::detectPathFormat(file, std::string_view(text).substr(0, 4096));
        continue;
      }
      std::ofstream(file, std::ios::binary | std::ios::trunc) << text;
      io::readPathFile(file);
    } catch (const Error& e) {
      if (i < kDetections) ++failures, ADD_FAILURE() << "detectPathFormat threw " << e.what();
    } catch (const std::exception& e) {
      ++failures;
      ADD_FAILURE() << typeid(e).name() << ": " << e.what() << "\n"
                    << file << ": \"" << escaped(text) << "\"";
    }
  }
  std::filesystem::remove_all(dir);
  EXPECT_EQ(failures, 0);
}

}  // namespace
}  // namespace ddfcam::test
