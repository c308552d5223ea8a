// SPDX-License-Identifier: MIT
// ddfcam tests: every reproducer under tests/fuzz/regressions/<reader>/ keeps the reader contract.
#include <ddfcam/error.h>
#include <ddfcam/io/programs/apt_reader.h>
#include <ddfcam/io/programs/fanuc_ls_reader.h>
#include <ddfcam/io/programs/path_file.h>
#include <ddfcam/io/programs/ros_toolpath_reader.h>
#include <ddfcam/io/programs/tool_path_csv.h>

#include "fuzz_inputs.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <cctype>
#include <chrono>
#include <filesystem>
#include <fstream>
#include <functional>
#include <map>
#include <sstream>
#include <typeinfo>

namespace ddfcam::test {
namespace {

namespace fs = std::filesystem;

using Reader = std::function<planning::ClProgram(std::string_view, const std::string&)>;

const fs::path kRegressions = fs::path(DDFCAM_SOURCE_DIR) / "tests" / "fuzz" / "regressions";

/// The reader of each regressions/<directory>; a directory missing here fails the test.
const std::map<std::string, Reader>& readers() {
  static const std::map<std::string, Reader> map = {
      {"apt", [](std::string_view t, const std::string& n) { return io::decodeApt(t, n); }},
      {"csv", [](std::string_view t, const std::string& n) { return io::decodeToolPathCsv(t, n); }},
      {"ros_yaml",
       [](std::string_view t, const std::string& n) { return io::decodeRosToolpathYaml(t, n); }},
      {"fanuc_ls",
       [](std::string_view t, const std::string& n) { return io::decodeFanucLs(t, n); }},
      // The file keeps its own extension; readPathFile() detects the format from it.
      {"path_file",
       [](std::string_view, const std::string& n) { return io::readPathFile(n).program; }},
  };
  return map;
}

/// One reproducer: regressions/<reader>/<file>.
struct Reproducer {
  std::string reader;
  fs::path file;
};

std::ostream& operator<<(std::ostream& out, const Reproducer& r) {
  return out << r.reader << "/" << r.file.filename().string();
}

/// Every file under regressions/<directory>/, walked when the tests are listed, so new
/// reproducers become test cases without an edit here.
std::vector<Reproducer> reproducers() {
  std::vector<Reproducer> out;
  if (!fs::is_directory(kRegressions)) return out;
  for (const fs::directory_entry& dir : fs::directory_iterator(kRegressions)) {
    if (!dir.is_directory()) continue;
    for (const fs::directory_entry& file : fs::recursive_directory_iterator(dir.path()))
      if (file.is_regular_file()) out.push_back({dir.path().filename().string(), file.path()});
  }
  std::sort(out.begin(), out.end(),
            [](const Reproducer& a, const Reproducer& b) { return a.file < b.file; });
  return out;
}

std::string readText(const fs::path& file) {
  std::ifstream in(file, std::ios::binary);
  std::ostringstream text;
  text << in.rdbuf();
  return text.str();
}

std::string testName(const Reproducer& r) {
  std::string name = r.reader + "_" + r.file.filename().string();
  for (char& c : name)
    if (!std::isalnum(static_cast<unsigned char>(c))) c = '_';
  return name;
}

class ReaderRegressions : public ::testing::TestWithParam<Reproducer> {};

TEST_P(ReaderRegressions, KeepsTheReaderContract) {
  const Reproducer& r = GetParam();
  const auto reader = readers().find(r.reader);
  ASSERT_NE(reader, readers().end()) << "no reader for regressions/" << r.reader << "/";
  const std::string text = readText(r.file);
  const std::string name = r.file.string();
  const auto start = std::chrono::steady_clock::now();
  try {
    const planning::ClProgram program = reader->second(text, name);
    EXPECT_FALSE(program.points.empty());
    const auto broken = programViolation(program, text);
    EXPECT_FALSE(broken) << *broken;
  } catch (const Error& e) {
    EXPECT_FALSE(messageViolation(e.what(), text, name)) << *messageViolation(e.what(), text, name);
  } catch (const std::exception& e) {
    ADD_FAILURE() << "foreign exception " << typeid(e).name() << ": " << e.what();
  }
  const double seconds =
      std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
  EXPECT_LT(seconds, 1.0);
}

INSTANTIATE_TEST_SUITE_P(Files, ReaderRegressions, ::testing::ValuesIn(reproducers()),
                         [](const auto& info) { return testName(info.param); });
GTEST_ALLOW_UNINSTANTIATED_PARAMETERIZED_TEST(ReaderRegressions);

TEST(ReaderRegressions, DirectoryHoldsReproducersOfEveryReader) {
  std::map<std::string, int> counts;
  for (const Reproducer& r : reproducers()) ++counts[r.reader];
  for (const char* reader : {"apt", "csv", "ros_yaml", "fanuc_ls"})
    EXPECT_GT(counts[reader], 0) << "no reproducers in " << (kRegressions / reader);
}

/// The error of @p reader on regressions/@p file; fails the test if the file is read.
std::string errorOf(const std::string& reader, const std::string& file) {
  const fs::path path = kRegressions / reader / file;
  try {
    readers().at(reader)(readText(path), path.string());
  } catch (const Error& e) {
    return e.what();
  }
  ADD_FAILURE() << path << " was read without an error";
  return {};
}

// The findings that must be rejected, each on the line that holds the offending value.
TEST(ReaderRegressions, OverflowsAreRejectedOnTheirLine) {
  EXPECT_EQ(lineNumberIn(errorOf("apt", "inch_position_overflow.apt")), 2);
  EXPECT_EQ(lineNumberIn(errorOf("apt", "feed_overflow.apt")), 1);
  EXPECT_EQ(lineNumberIn(errorOf("apt", "cutter_inch_overflow.apt")), 2);
  EXPECT_EQ(lineNumberIn(errorOf("apt", "circle_inch_centre_overflow.apt")), 3);
  EXPECT_EQ(lineNumberIn(errorOf("csv", "metre_position_overflow.csv")), 2);
  EXPECT_EQ(lineNumberIn(errorOf("csv", "feed_overflow.csv")), 2);
  EXPECT_EQ(lineNumberIn(errorOf("ros_yaml", "position_overflow.yaml")), 4);
  EXPECT_EQ(lineNumberIn(errorOf("fanuc_ls", "feed_overflow.ls")), 3);
  EXPECT_EQ(lineNumberIn(errorOf("fanuc_ls", "position_beyond_range.ls")), 8);
}

TEST(ReaderRegressions, NegativeCsvFeedIsRejectedLikeAptAndFanuc) {
  const std::string message = errorOf("csv", "negative_feed.csv");
  EXPECT_EQ(lineNumberIn(message), 2);
  EXPECT_NE(message.find("negative feed"), std::string::npos) << message;
}

TEST(ReaderRegressions, HugeCircleIsRefusedOnItsLine) {
  const std::string message = errorOf("apt", "circle_amplification.apt");
  EXPECT_EQ(lineNumberIn(message), 2);  // the first CIRCLE record
  EXPECT_NE(message.find("radius"), std::string::npos) << message;
}

TEST(ReaderRegressions, ArcPointsOfAProgramAreCapped) {
  // 80 full circles of radius 1e6 mm at 0.005 mm: 2 acos(1 - 5e-9) rad per chord gives
  // 31,416 chords (31,415 points) each, so the 32nd circle, on line 2 + 2 * 31, crosses the
  // cap of 1,000,000 interpolated points per program.
  const std::string message = errorOf("apt", "arc_point_budget.apt");
  EXPECT_EQ(lineNumberIn(message), 64);
  EXPECT_NE(message.find("CIRCLE"), std::string::npos) << message;
}

TEST(ReaderRegressions, OverflowingAxisNormsAreNormalisedSafely) {
  const planning::ClProgram apt = io::decodeApt(
      readText(kRegressions / "apt/axis_norm_overflow.apt"), "axis_norm_overflow.apt");
  ASSERT_EQ(apt.points.size(), 1u);
  ASSERT_TRUE(apt.points[0].axis);
  EXPECT_NEAR((*apt.points[0].axis - ddf::Vec3(0, -1, 0)).norm(), 0.0, 1e-12);
  const planning::ClProgram csv = io::decodeToolPathCsv(
      readText(kRegressions / "csv/axis_norm_overflow.csv"), "axis_norm_overflow.csv");
  ASSERT_EQ(csv.points.size(), 1u);
  ASSERT_TRUE(csv.points[0].axis);
  EXPECT_NEAR((*csv.points[0].axis - ddf::Vec3(1, 1, 0).normalized()).norm(), 0.0, 1e-12);
}

}  // namespace
}  // namespace ddfcam::test
