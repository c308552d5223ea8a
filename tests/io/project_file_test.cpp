// SPDX-License-Identifier: MIT
#include <ddfcam/error.h>
#include <ddfcam/io/checksum.h>
#include <ddfcam/io/ddf_file.h>
#include <ddfcam/io/project_file.h>
#include <ddfcam/planning/demo_project.h>

#include <gmock/gmock.h>
#include <gtest/gtest.h>

#include <utility>
#include <vector>

#include "io_test_support.h"
#include "project_test_support.h"

namespace ddfcam::io {
namespace {

using test::sameBits;
using ::testing::HasSubstr;

template <class T>
bool sameVector(const std::vector<T>& a, const std::vector<T>& b) {
  return a.size() == b.size() && sameBits(a.data(), b.data(), a.size() * sizeof(T));
}

void expectSamePath(const planning::ToolPath& a, const planning::ToolPath& b) {
  EXPECT_EQ(a.name, b.name);
  EXPECT_EQ(a.tool, b.tool);
  EXPECT_TRUE(sameBits(&a.feedMmPerMin, &b.feedMmPerMin, 8));
  EXPECT_EQ(a.passStarts, b.passStarts);
  ASSERT_EQ(a.poses.size(), b.poses.size());
  for (std::size_t p = 0; p < a.poses.size(); ++p) {
    EXPECT_TRUE(sameBits(a.poses[p].pose.matrix().data(), b.poses[p].pose.matrix().data(), 128))
        << "pose " << p;
    EXPECT_TRUE(sameBits(a.poses[p].contact.data(), b.poses[p].contact.data(), 24)) << p;
  }
}

/// Independent of planning::projectsEqual: every member compared here, bit for bit.
void expectSameProject(const planning::Project& a, const planning::Project& b) {
  EXPECT_EQ(a.partName, b.partName);
  EXPECT_EQ(a.sourcePath, b.sourcePath);
  ASSERT_EQ(a.part.has_value(), b.part.has_value());
  if (a.part) test::expectBitwiseEqual(*a.part, *b.part);
  ASSERT_EQ(a.designMesh.has_value(), b.designMesh.has_value());
  if (a.designMesh) {
    EXPECT_EQ(a.designMesh->triangles, b.designMesh->triangles);
    EXPECT_TRUE(sameVector(a.designMesh->vertices, b.designMesh->vertices));
  }
  ASSERT_EQ(a.fields.size(), b.fields.size());
  for (std::size_t i = 0; i < a.fields.size(); ++i) {
    EXPECT_EQ(a.fields[i].name, b.fields[i].name);
    EXPECT_EQ(a.fields[i].unit, b.fields[i].unit);
    EXPECT_EQ(a.fields[i].isSigned, b.fields[i].isSigned);
    EXPECT_TRUE(sameVector(a.fields[i].values, b.fields[i].values)) << "field " << i;
  }
  ASSERT_EQ(a.regions.size(), b.regions.size());
  for (std::size_t i = 0; i < a.regions.size(); ++i) {
    EXPECT_EQ(a.regions[i].name, b.regions[i].name);
    EXPECT_EQ(a.regions[i].faces, b.regions[i].faces);
    EXPECT_TRUE(sameBits(a.regions[i].color.data(), b.regions[i].color.data(), 12));
  }
  ASSERT_EQ(a.tools.size(), b.tools.size());
  for (std::size_t i = 0; i < a.tools.size(); ++i) EXPECT_EQ(a.tools[i], b.tools[i]) << i;
  ASSERT_EQ(a.paths.size(), b.paths.size());
  for (std::size_t i = 0; i < a.paths.size(); ++i) expectSamePath(a.paths[i], b.paths[i]);
  ASSERT_EQ(a.states.size(), b.states.size());
  for (std::size_t i = 0; i < a.states.size(); ++i) {
    EXPECT_EQ(a.states[i].name, b.states[i].name);
    EXPECT_TRUE(sameVector(a.states[i].heights, b.states[i].heights)) << "state " << i;
  }
  ASSERT_EQ(a.surfaces.size(), b.surfaces.size());
  for (std::size_t i = 0; i < a.surfaces.size(); ++i) {
    EXPECT_EQ(a.surfaces[i].name, b.surfaces[i].name);
    test::expectBitwiseEqual(a.surfaces[i].ddf, b.surfaces[i].ddf);
  }
}

/// The chunks of a .ddfproj as (tag, payload), parsed here from the documented table alone.
std::vector<std::pair<std::string, std::string>> chunksOf(const std::string& bytes) {
  std::vector<std::pair<std::string, std::string>> chunks;
  std::size_t at = 24;
  while (at + 4 < bytes.size()) {
    std::uint64_t length = 0;
    for (int i = 0; i < 8; ++i)
      length |= std::uint64_t{static_cast<unsigned char>(bytes[at + 4 + i])} << (8 * i);
    chunks.emplace_back(bytes.substr(at, 4), bytes.substr(at + 12, length));
    at += 12 + length;
  }
  return chunks;
}

TEST(ProjectFile, RichProjectRoundTripsExactly) {
  const planning::Project project = test::makeRichProject();
  const planning::Project back = decodeProject(encodeProject(project), "rich.ddfproj");
  EXPECT_TRUE(planning::projectsEqual(project, back));
  expectSameProject(project, back);
  // The sample must really hold the awkward values it is meant to carry through.
  EXPECT_TRUE(std::isnan(back.fields[0].values[3]));
  EXPECT_TRUE(std::signbit(back.part->allHeights()[0]));
}

TEST(ProjectFile, FileRoundTripAndReencodingAreExact) {
  test::ScratchDir dir;
  const planning::Project project = test::makeRichProject();
  const auto path = dir / "Projekt \u00fc.ddfproj";
  writeProject(project, path);
  const planning::Project back = readProject(path);
  expectSameProject(project, back);
  EXPECT_EQ(encodeProject(back), test::readBytes(path));
}

TEST(ProjectFile, DemoProjectRoundTripsExactly) {
  const planning::Project demo = planning::demoProject();
  const planning::Project back = decodeProject(encodeProject(demo), "demo.ddfproj");
  EXPECT_TRUE(planning::projectsEqual(demo, back));
  expectSameProject(demo, back);
}

TEST(ProjectFile, EmptyProjectRoundTrips) {
  const planning::Project empty;
  const std::string bytes = encodeProject(empty);
  const planning::Project back = decodeProject(bytes, "empty.ddfproj");
  EXPECT_TRUE(planning::projectsEqual(empty, back));
  expectSameProject(empty, back);
  EXPECT_EQ(chunksOf(bytes).size(), 1u);
}

TEST(ProjectFile, SmallestFileMatchesTheDocumentedLayout) {
  planning::Project project;
  project.partName = "ab";
  std::string expected("DDFPRJ\x1a\n", 8);
  expected += std::string("\x01\0\0\0", 4) + std::string("\x01\0\0\0", 4);
  expected += std::string("\x32\0\0\0\0\0\0\0", 8);  // 50 bytes in all
  expected += "PROJ" + std::string("\x0a\0\0\0\0\0\0\0", 8);
  expected += std::string("\x02\0\0\0", 4) + "ab" + std::string(4, '\0');
  const std::uint32_t crc = crc32(std::as_bytes(std::span(expected.data(), expected.size())));
  for (int i = 0; i < 4; ++i) expected += static_cast<char>((crc >> (8 * i)) & 0xFF);
  EXPECT_EQ(encodeProject(project), expected);
}

TEST(ProjectFile, ChunksFollowTheDocumentedTable) {
  const planning::Project project = test::makeRichProject();
  const auto chunks = chunksOf(encodeProject(project));
  std::vector<std::string> tags;
  for (const auto& chunk : chunks) tags.push_back(chunk.first);
  EXPECT_EQ(tags, (std::vector<std::string>{"PROJ", "PART", "DSGN", "TOOL", "TOOL", "PATH", "PATH",
                                            "FELD", "FELD", "REGN", "STAT", "STAT", "SURF"}));
  EXPECT_EQ(chunks[1].second, encodeDdf(*project.part));
  const std::string& name = project.surfaces[0].name;
  EXPECT_EQ(chunks[12].second.substr(4 + name.size()), encodeDdf(project.surfaces[0].ddf));
  EXPECT_EQ(chunks[12].second.substr(4, name.size()), name);
  const planning::ToolPath& path = project.paths[0];
  EXPECT_EQ(chunks[5].second.size(),
            4 + path.name.size() + 4 + 8 + 8 + 19 * 8 * path.poses.size() + 8 + 4 * 3);
  // The first pose's matrix follows the header of the path, column-major, bit for bit.
  const std::size_t matrixAt = 4 + path.name.size() + 4 + 8 + 8;
  EXPECT_TRUE(
      sameBits(chunks[5].second.data() + matrixAt, path.poses[0].pose.matrix().data(), 128));
}

TEST(ProjectFile, InvalidProjectIsNotEncodedOrWritten) {
  test::ScratchDir dir;
  planning::Project project = test::makeSmallProject();
  project.paths[0].tool = 3;
  EXPECT_THROW(encodeProject(project), InvalidInput);
  EXPECT_THROW(writeProject(project, dir / "bad.ddfproj"), InvalidInput);
  EXPECT_TRUE(std::filesystem::is_empty(dir.path()));
}

TEST(ProjectFile, FailedWriteIntoAMissingDirectoryLeavesNoFile) {
  test::ScratchDir dir;
  const auto path = dir / "missing" / "p.ddfproj";
  EXPECT_THAT(test::ioErrorMessage([&] { writeProject(test::makeSmallProject(), path); }),
              HasSubstr("p.ddfproj"));
  EXPECT_FALSE(std::filesystem::exists(path));
  EXPECT_TRUE(std::filesystem::is_empty(dir.path()));
}

TEST(ProjectFile, OverwriteLeavesEitherTheOldOrTheNewFile) {
  test::ScratchDir dir;
  const auto path = dir / "p.ddfproj";
  const planning::Project oldProject = test::makeSmallProject();
  writeProject(oldProject, path);
  const std::string oldBytes = test::readBytes(path);
  // A write that fails (invalid project) keeps the old file byte for byte.
  planning::Project invalid = test::makeRichProject();
  invalid.fields[0].values.pop_back();
  EXPECT_THROW(writeProject(invalid, path), InvalidInput);
  EXPECT_EQ(test::readBytes(path), oldBytes);
  // A write that succeeds replaces it completely, with no temporary file left behind.
  const planning::Project newProject = test::makeRichProject();
  writeProject(newProject, path);
  expectSameProject(newProject, readProject(path));
  EXPECT_EQ(std::distance(std::filesystem::directory_iterator(dir.path()),
                          std::filesystem::directory_iterator()),
            1);
}

}  // namespace
}  // namespace ddfcam::io
