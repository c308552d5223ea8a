// SPDX-License-Identifier: MIT
// The optional "line" chunk: raw lines and linking of planned paths, saved, loaded and checked.
#include <ddfcam/error.h>
#include <ddfcam/io/project/project_file.h>

#include <gmock/gmock.h>
#include <gtest/gtest.h>

#include <bit>
#include <cstdint>
#include <string>
#include <utility>
#include <vector>

#include "../io_test_support.h"
#include "project_test_support.h"

namespace ddfcam::io {
namespace {

using ::testing::HasSubstr;

/// A located point with coordinates that need every bit (thirds, a signed zero).
ddf::SurfaceLocation location(int face, double t) {
  ddf::SurfaceLocation p;
  p.face = face;
  p.bary = {1.0 / 3.0 + t, -0.0, 2.0 / 3.0 - t};
  p.h = 0.1 * t - 1e-300;
  p.point = {t, 1.0 / 7.0, -t * t};
  return p;
}

planning::Streamline line(int face, int points, std::size_t seed) {
  planning::Streamline l;
  for (int i = 0; i < points; ++i) l.points.push_back(location(face, 0.01 * i));
  l.stop = planning::Streamline::NearExistingPath;
  l.backwardStop = planning::Streamline::RegionBoundary;
  l.seedIndex = seed;
  l.lengthMm = 1.0 / 3.0 + points;
  return l;
}

/// The small project whose path was planned: two raw lines, linked with 12.375 mm idle; a
/// second path linked without raw lines, a third neither.
planning::Project plannedProject() {
  planning::Project project = test::makeSmallProject();
  planning::ToolPath& path = project.paths.front();
  path.rawLines = {line(0, 3, 1), line(1, 5, 0)};
  path.linkedIdleMm = 12.375;
  planning::ToolPath linked = path;
  linked.name = "linked only";
  linked.rawLines.clear();
  linked.linkedIdleMm = -0.0;
  planning::ToolPath plain = linked;
  plain.name = "plain";
  plain.linkedIdleMm.reset();
  project.paths.push_back(linked);
  project.paths.push_back(plain);
  return project;
}

/// (tag, offset of the chunk, chunk size with its 12-byte head) of every chunk, from the
/// documented envelope alone.
struct Chunk {
  std::string tag;
  std::size_t at = 0;
  std::size_t bytes = 0;
};

std::uint64_t leAt(const std::string& bytes, std::size_t at, int count) {
  std::uint64_t v = 0;
  for (int i = count - 1; i >= 0; --i) v = (v << 8) | static_cast<unsigned char>(bytes[at + i]);
  return v;
}

std::vector<Chunk> chunksOf(const std::string& bytes) {
  std::vector<Chunk> chunks;
  for (std::size_t at = 24; at + 4 < bytes.size();) {
    const std::size_t size = 12 + leAt(bytes, at + 4, 8);
    chunks.push_back({bytes.substr(at, 4), at, size});
    at += size;
  }
  return chunks;
}

std::vector<Chunk> lineChunks(const std::string& bytes) {
  std::vector<Chunk> out;
  for (const Chunk& c : chunksOf(bytes))
    if (c.tag == "line") out.push_back(c);
  return out;
}

/// @p bytes without its "line" chunks, as a build from before them wrote the file.
std::string withoutLineChunks(std::string bytes) {
  const std::vector<Chunk> lines = lineChunks(bytes);
  for (auto c = lines.rbegin(); c != lines.rend(); ++c) bytes.erase(c->at, c->bytes);
  test::putLeAt(bytes, 12, leAt(bytes, 12, 4) - lines.size(), 4);
  return test::resized(std::move(bytes));
}

double f64At(const std::string& bytes, std::size_t at) {
  return std::bit_cast<double>(leAt(bytes, at, 8));
}

TEST(PathLinesChunk, RawLinesAndLinkingRoundTrip) {
  test::ScratchDir dir;
  const planning::Project project = plannedProject();
  writeProject(project, dir / "planned.ddfproj");
  const planning::Project back = readProject(dir / "planned.ddfproj");
  EXPECT_TRUE(planning::projectsEqual(project, back));
  ASSERT_EQ(back.paths.size(), 3u);
  EXPECT_EQ(back.paths[0].rawLines, project.paths[0].rawLines);
  EXPECT_EQ(back.paths[0].linkedIdleMm, 12.375);
  EXPECT_TRUE(back.paths[1].rawLines.empty());
  ASSERT_TRUE(back.paths[1].linkedIdleMm.has_value());
  EXPECT_TRUE(std::signbit(*back.paths[1].linkedIdleMm));  // -0.0 kept bit for bit
  EXPECT_FALSE(back.paths[2].linkedIdleMm.has_value());
  EXPECT_EQ(encodeProject(back), test::readBytes(dir / "planned.ddfproj"));
}

TEST(PathLinesChunk, RawLinesDifferenceIsSeenByProjectsEqual) {
  const planning::Project project = plannedProject();
  planning::Project moved = project;
  moved.paths[0].rawLines[1].points[2].bary.y() = 0.0;  // -0.0 before
  EXPECT_FALSE(planning::projectsEqual(project, moved));
  planning::Project unlinked = project;
  unlinked.paths[0].linkedIdleMm.reset();
  EXPECT_FALSE(planning::projectsEqual(project, unlinked));
}

TEST(PathLinesChunk, RenamedPathKeepsItsLines) {
  planning::Project project = plannedProject();
  project.paths[0].name = "renamed \u2192 path";
  const planning::Project back = decodeProject(encodeProject(project), "renamed.ddfproj");
  EXPECT_EQ(back.paths[0].name, "renamed \u2192 path");
  EXPECT_EQ(back.paths[0].rawLines, project.paths[0].rawLines);
  EXPECT_EQ(back.paths[0].linkedIdleMm, 12.375);
}

TEST(PathLinesChunk, PayloadFollowsTheDocumentedLayout) {
  const planning::Project project = plannedProject();
  const std::string bytes = encodeProject(project);
  const std::vector<Chunk> lines = lineChunks(bytes);
  ASSERT_EQ(lines.size(), 2u);  // the third path has neither
  const std::string p = bytes.substr(lines[0].at + 12, lines[0].bytes - 12);
  EXPECT_EQ(leAt(p, 0, 4), 0u);  // path index
  EXPECT_EQ(leAt(p, 4, 1), 1u);  // linked
  EXPECT_EQ(f64At(p, 5), 12.375);
  EXPECT_EQ(leAt(p, 13, 8), 2u);  // two lines
  std::size_t at = 21;
  for (const planning::Streamline& l : project.paths[0].rawLines) {
    EXPECT_EQ(leAt(p, at, 4), static_cast<std::uint64_t>(l.stop));
    EXPECT_EQ(leAt(p, at + 4, 4), static_cast<std::uint64_t>(l.backwardStop));
    EXPECT_EQ(leAt(p, at + 8, 8), l.seedIndex);
    EXPECT_EQ(f64At(p, at + 16), l.lengthMm);
    ASSERT_EQ(leAt(p, at + 24, 8), l.points.size());
    at += 32;
    for (const ddf::SurfaceLocation& q : l.points) {
      EXPECT_EQ(static_cast<int>(leAt(p, at, 4)), q.face);
      for (int k = 0; k < 3; ++k)
        EXPECT_EQ(leAt(p, at + 4 + 8 * k, 8), std::bit_cast<std::uint64_t>(q.bary[k]));
      EXPECT_EQ(f64At(p, at + 28), q.h);
      for (int k = 0; k < 3; ++k) EXPECT_EQ(f64At(p, at + 36 + 8 * k), q.point[k]);
      at += 60;
    }
  }
  EXPECT_EQ(at, p.size());
  const std::string second = bytes.substr(lines[1].at + 12, lines[1].bytes - 12);
  EXPECT_EQ(second.size(), 21u);
  EXPECT_EQ(leAt(second, 0, 4), 1u);
  EXPECT_EQ(leAt(second, 13, 8), 0u);
}

TEST(PathLinesChunk, PathsWithoutThemAreSavedAsBefore) {
  for (const Chunk& chunk : chunksOf(encodeProject(test::makeRichProject())))
    EXPECT_NE(chunk.tag, "line");
}

TEST(PathLinesChunk, FilesWithoutThemStillLoad) {
  // The same file as an older build wrote it: the paths load without lines and linking.
  const planning::Project project = plannedProject();
  const std::string old = withoutLineChunks(encodeProject(project));
  ASSERT_TRUE(lineChunks(old).empty());
  ProjectReadReport report;
  const planning::Project back = decodeProject(old, "old.ddfproj", &report);
  EXPECT_TRUE(report.skippedChunks.empty());
  planning::Project expected = project;
  for (planning::ToolPath& path : expected.paths) {
    path.rawLines.clear();
    path.linkedIdleMm.reset();
  }
  EXPECT_TRUE(planning::projectsEqual(back, expected));
  EXPECT_EQ(encodeProject(expected), old);
  const auto v1 = std::filesystem::path(DDFCAM_TEST_DATA_DIR) / "two_regions_v1.ddfproj";
  for (const planning::ToolPath& path : readProject(v1).paths) {
    EXPECT_TRUE(path.rawLines.empty());
    EXPECT_FALSE(path.linkedIdleMm.has_value());
  }
}

TEST(PathLinesChunk, LinesOffThePartAreRefused) {
  planning::Project offPart = plannedProject();
  offPart.paths[0].rawLines[1].points[0].face = offPart.part->faceCount();
  EXPECT_THROW(encodeProject(offPart), InvalidInput);
  planning::Project badSeed = plannedProject();
  badSeed.paths[0].rawLines[0].seedIndex = 3;
  EXPECT_THROW(encodeProject(badSeed), InvalidInput);
  planning::Project badIdle = plannedProject();
  badIdle.paths[1].linkedIdleMm = -1.0;
  EXPECT_THROW(encodeProject(badIdle), InvalidInput);
  // The same in a file: a load error naming the file, the project's check nested.
  std::string bytes = encodeProject(plannedProject());
  const Chunk first = lineChunks(bytes).front();
  test::putLeAt(bytes, first.at + 12 + 21 + 32, 99, 4);  // first point of the first line
  EXPECT_THAT(test::ioErrorMessage([&] { decodeProject(test::resealed(bytes), "bad.ddfproj"); }),
              HasSubstr("bad.ddfproj"));
}

TEST(PathLinesChunk, ChunkNamingAMissingOrRepeatedPathIsAnError) {
  std::string bytes = encodeProject(plannedProject());
  const std::vector<Chunk> lines = lineChunks(bytes);
  std::string missing = bytes;
  test::putLeAt(missing, lines[1].at + 12, 3, 4);  // three paths: index 3 does not exist
  EXPECT_THAT(test::ioErrorMessage([&] { decodeProject(test::resealed(missing), "p.ddfproj"); }),
              HasSubstr("path index 3 out of range"));
  std::string repeated = bytes;
  test::putLeAt(repeated, lines[1].at + 12, 0, 4);  // both chunks name path 0
  EXPECT_THAT(test::ioErrorMessage([&] { decodeProject(test::resealed(repeated), "p.ddfproj"); }),
              HasSubstr("a second 'line' chunk for path 0"));
}

}  // namespace
}  // namespace ddfcam::io
