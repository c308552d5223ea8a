// SPDX-License-Identifier: MIT
#include <ddfcam/error.h>
#include <ddfcam/io/common/checksum.h>
#include <ddfcam/io/mesh/ddf_file.h>
#include <ddfcam/io/project/project_file.h>
#include <ddfcam/log.h>
#include <ddfcam/planning/model/demo_project.h>

#include <gmock/gmock.h>
#include <gtest/gtest.h>

#include <algorithm>
#include <array>
#include <cstring>
#include <filesystem>
#include <utility>
#include <vector>

#include "../io_test_support.h"
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

void expectSamePlan(const planning::RegionPlan& a, const planning::RegionPlan& b) {
  EXPECT_EQ(a.tool, b.tool);
  EXPECT_EQ(a.flowSource, b.flowSource);
  EXPECT_TRUE(sameBits(a.fixedDirection.data(), b.fixedDirection.data(), 24));
  ASSERT_EQ(a.strokes.size(), b.strokes.size());
  for (std::size_t s = 0; s < a.strokes.size(); ++s)
    EXPECT_TRUE(sameVector(a.strokes[s], b.strokes[s])) << "stroke " << s;
  EXPECT_EQ(a.smoothField, b.smoothField);
  EXPECT_TRUE(sameBits(&a.smoothnessWeight, &b.smoothnessWeight, 8));
  EXPECT_EQ(a.spacingMode, b.spacingMode);
  EXPECT_TRUE(sameBits(&a.spacingMm, &b.spacingMm, 8));
  EXPECT_TRUE(sameBits(&a.scallopToleranceMm, &b.scallopToleranceMm, 8));
  EXPECT_EQ(a.feedSign, b.feedSign);
  EXPECT_EQ(a.linking, b.linking);
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
    EXPECT_EQ(a.fields[i].heightsDigest, b.fields[i].heightsDigest) << "field " << i;
  }
  ASSERT_EQ(a.regions.size(), b.regions.size());
  for (std::size_t i = 0; i < a.regions.size(); ++i) {
    EXPECT_EQ(a.regions[i].name, b.regions[i].name);
    EXPECT_EQ(a.regions[i].faces, b.regions[i].faces);
    EXPECT_TRUE(sameBits(a.regions[i].color.data(), b.regions[i].color.data(), 12));
    expectSamePlan(a.regions[i].plan, b.regions[i].plan);
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
  expected += std::string("\x04\0\0\0", 4) + std::string("\x01\0\0\0", 4);
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
  EXPECT_EQ(tags,
            (std::vector<std::string>{"PROJ", "PART", "DSGN", "TOOL", "TOOL", "PATH", "PATH",
                                      "FELD", "FELD", "REGN", "REGN", "STAT", "STAT", "SURF"}));
  EXPECT_EQ(chunks[1].second, encodeDdf(*project.part));
  const std::string& name = project.surfaces[0].name;
  EXPECT_EQ(chunks[13].second.substr(4 + name.size()), encodeDdf(project.surfaces[0].ddf));
  EXPECT_EQ(chunks[13].second.substr(4, name.size()), name);
  const planning::ToolPath& path = project.paths[0];
  EXPECT_EQ(chunks[5].second.size(),
            4 + path.name.size() + 4 + 8 + 8 + 19 * 8 * path.poses.size() + 8 + 4 * 3);
  // The first pose's matrix follows the header of the path, column-major, bit for bit.
  const std::size_t matrixAt = 4 + path.name.size() + 4 + 8 + 8;
  EXPECT_TRUE(
      sameBits(chunks[5].second.data() + matrixAt, path.poses[0].pose.matrix().data(), 128));
}

// A field's heights digest travels in an optional "hdig" chunk after the fields: i32 index,
// u64 digest; fields without one write nothing, so their projects are saved as before.
TEST(ProjectFile, HeightsDigestsOfFieldsRoundTripInOptionalChunks) {
  planning::Project project = test::makeRichProject();
  const std::string before = encodeProject(project);
  const std::uint64_t digest = 0x0123456789abcdefULL;
  project.fields[1].heightsDigest = digest;
  const std::string bytes = encodeProject(project);
  const auto chunks = chunksOf(bytes);
  std::vector<std::string> tags;
  for (const auto& chunk : chunks) tags.push_back(chunk.first);
  const auto at = std::find(tags.begin(), tags.end(), "hdig");
  ASSERT_NE(at, tags.end());
  EXPECT_EQ(*(at - 1), "FELD");
  EXPECT_EQ(std::count(tags.begin(), tags.end(), "hdig"), 1);
  std::string expected;
  for (int i = 0; i < 4; ++i) expected += static_cast<char>(i == 0 ? 1 : 0);
  for (int i = 0; i < 8; ++i) expected += static_cast<char>((digest >> (8 * i)) & 0xFF);
  EXPECT_EQ(chunks[static_cast<std::size_t>(at - tags.begin())].second, expected);
  const planning::Project back = decodeProject(bytes, "digest.ddfproj");
  EXPECT_FALSE(back.fields[0].heightsDigest.has_value());
  EXPECT_EQ(back.fields[1].heightsDigest, digest);
  EXPECT_EQ(encodeProject(back), bytes);
  EXPECT_NE(before, bytes);
}

TEST(ProjectFile, ADigestOfAFieldThatDoesNotPrecedeItIsRejected) {
  planning::Project project = test::makeRichProject();
  project.fields[0].heightsDigest = 5;
  std::string bytes = encodeProject(project);
  // Point the digest at field 7 (the project has two) and fix the checksum the way the file
  // layout documents it (CRC-32 of everything before the last 4 bytes).
  const std::size_t at = bytes.find("hdig");
  ASSERT_NE(at, std::string::npos);
  bytes[at + 12] = 7;
  bytes.resize(bytes.size() - 4);
  const std::uint32_t crc = crc32(std::as_bytes(std::span(bytes.data(), bytes.size())));
  for (int i = 0; i < 4; ++i) bytes += static_cast<char>((crc >> (8 * i)) & 0xFF);
  try {
    (void)decodeProject(bytes, "bad.ddfproj");
    FAIL() << "accepted a digest of a missing field";
  } catch (const IoError& e) {
    EXPECT_THAT(e.what(), HasSubstr("heights digest of field 7"));
  }
}

TEST(ProjectFile, RegionPayloadsFollowTheDocumentedLayout) {
  const planning::Project project = test::makeRichProject();
  const auto chunks = chunksOf(encodeProject(project));
  for (int r = 0; r < 2; ++r) {
    const planning::Region& region = project.regions[r];
    const std::string& payload = chunks[9 + r].second;
    std::size_t strokeBytes = 8;
    for (const auto& stroke : region.plan.strokes) strokeBytes += 8 + 24 * stroke.size();
    const std::size_t planAt = 4 + region.name.size() + 12 + 8 + 4 * region.faces.size();
    EXPECT_EQ(payload.size(), planAt + 4 + 4 + 24 + 1 + 8 + 4 + 8 + 8 + 4 + 4 + strokeBytes);
    // tool, flow source, then the fixed direction's three doubles, bit for bit.
    EXPECT_TRUE(sameBits(payload.data() + planAt, &region.plan.tool, 4));
    EXPECT_TRUE(sameBits(payload.data() + planAt + 8, region.plan.fixedDirection.data(), 24));
  }
  // The first region's last stroke holds one point, the last 24 bytes of the payload.
  const std::string& first = chunks[9].second;
  EXPECT_TRUE(sameBits(first.data() + first.size() - 24,
                       project.regions[0].plan.strokes.back()[0].data(), 24));
}

/// @p project with what format @p version could not store reset to the defaults: version 1
/// regions have the default plan, version 1 and 2 tools the default sizes.
planning::Project asReadFromVersion(planning::Project project, std::uint32_t version) {
  if (version < 2)
    for (planning::Region& region : project.regions) region.plan = {};
  if (version < 3)
    for (planning::Tool& tool : project.tools)
      tool = {.name = tool.name,
              .kind = tool.kind,
              .radiusMm = tool.radiusMm,
              .widthMm = tool.widthMm,
              .segments = tool.segments};
  return project;
}

/// The .ddfproj of @p project as format @p version (1 or 2) wrote it: "TOOL" payloads end
/// after the segments, for version 1 "REGN" payloads end after the faces, the header gives
/// the version. Built here from the documented layout.
std::string asOldVersion(const planning::Project& project, std::uint32_t version) {
  const std::string v3 = encodeProject(project);
  std::string out = v3.substr(0, 24);
  test::putLeAt(out, 8, version, 4);
  for (auto [tag, payload] : chunksOf(v3)) {
    std::uint32_t nameBytes = 0;
    std::memcpy(&nameBytes, payload.data(), 4);  // little-endian host assumed by the test
    if (tag == "REGN" && version < 2) {
      std::uint64_t faces = 0;
      std::memcpy(&faces, payload.data() + 4 + nameBytes + 12, 8);
      payload.resize(4 + nameBytes + 12 + 8 + 4 * faces);
    }
    if (tag == "TOOL") {
      EXPECT_EQ(payload.size(), 4 + nameBytes + 4 + 8 + 8 + 4 + 7 * 8);
      payload.resize(4 + nameBytes + 4 + 8 + 8 + 4);
    }
    out += tag;
    std::string length(8, '\0');
    test::putLeAt(length, 0, payload.size(), 8);
    out += length + payload;
  }
  out += std::string(4, '\0');
  return test::resized(std::move(out));
}

TEST(ProjectFile, OlderVersionsLoadWithDefaultPlansAndToolSizes) {
  const planning::Project project = test::makeRichProject();
  for (const std::uint32_t version : {1u, 2u}) {
    ProjectReadReport report;
    const planning::Project back =
        decodeProject(asOldVersion(project, version), "old.ddfproj", &report);
    EXPECT_EQ(report.formatVersion, version);
    EXPECT_TRUE(report.skippedChunks.empty());
    const planning::Project expected = asReadFromVersion(project, version);
    expectSameProject(expected, back);
    EXPECT_TRUE(planning::projectsEqual(expected, back));
    EXPECT_EQ(back.tools[0].chordToleranceMm, 0.005);  // planning::Tool's documented default
    EXPECT_EQ(back.tools[0].segments, 50);             // as stored
    // Saving again writes version 4.
    EXPECT_EQ(encodeProject(back).substr(8, 4), std::string("\x04\0\0\0", 4));
  }
}

TEST(ProjectFile, ToolsOfEveryKindRoundTripWithAllSizes) {
  planning::Project project = test::makeSmallProject();
  project.tools = test::toolsOfEveryKind();
  project.paths[0].tool = 5;
  ProjectReadReport report;
  const planning::Project back = decodeProject(encodeProject(project), "kinds", &report);
  EXPECT_EQ(report.formatVersion, 4u);
  expectSameProject(project, back);
  EXPECT_TRUE(planning::projectsEqual(project, back));
}

TEST(ProjectFile, CommittedVersion1FileStillLoads) {
  // Values from tests/data/README.md, where the file's content is described.
  const auto path = std::filesystem::path(DDFCAM_TEST_DATA_DIR) / "two_regions_v1.ddfproj";
  ProjectReadReport report;
  const planning::Project project = readProject(path, &report);
  EXPECT_EQ(report.formatVersion, 1u);
  EXPECT_EQ(project.partName, "v1 sample");
  ASSERT_TRUE(project.part.has_value());
  EXPECT_EQ(project.part->faceCount(), 4);
  ASSERT_EQ(project.regions.size(), 2u);
  EXPECT_EQ(project.regions[0].name, "left");
  EXPECT_EQ(project.regions[0].faces, (std::vector<int>{0, 1}));
  EXPECT_EQ(project.regions[1].name, "right");
  EXPECT_EQ(project.regions[1].faces, (std::vector<int>{2, 3}));
  EXPECT_EQ(project.regions[1].color, (std::array<float, 3>{0.0f, 0.25f, 1.0f}));
  for (const planning::Region& region : project.regions)
    expectSamePlan(region.plan, planning::RegionPlan{});
  ASSERT_EQ(project.tools.size(), 1u);
  EXPECT_EQ(project.tools[0].radiusMm, 5.0);
  ASSERT_EQ(project.paths.size(), 1u);
  EXPECT_EQ(project.paths[0].feedMmPerMin, 1500.0);
  EXPECT_EQ(project.paths[0].poses[0].contact, Eigen::Vector3d(0.5, 0.25, 0.0));
  EXPECT_EQ(project.fields[0].values, std::vector<float>(24, 0.5f));
  EXPECT_EQ(project.states[0].heights, std::vector<float>(24, 0.25f));
  EXPECT_TRUE(planning::projectsEqual(project, decodeProject(encodeProject(project), "again")));
}

/// @p bytes with a chunk (@p tag, @p payload) inserted before the @p n-th chunk, resealed.
std::string withChunk(const std::string& bytes, std::size_t n, const std::string& tag,
                      const std::string& payload) {
  std::size_t at = 24;
  for (std::size_t i = 0; i < n; ++i) {
    std::uint64_t length = 0;
    std::memcpy(&length, bytes.data() + at + 4, 8);
    at += 12 + length;
  }
  std::string chunk = tag + std::string(8, '\0') + payload;
  test::putLeAt(chunk, 4, payload.size(), 8);
  std::string out = bytes;
  out.insert(at, chunk);
  const std::uint32_t count = static_cast<unsigned char>(out[12]) + 1u;  // small files only
  test::putLeAt(out, 12, count, 4);
  return test::resized(std::move(out));
}

TEST(ProjectFile, UnknownOptionalChunksAreSkippedAndReported) {
  const planning::Project project = test::makeRichProject();
  const std::string bytes = encodeProject(project);
  std::string withNotes = withChunk(bytes, 3, "note", "written by a later ddfcam");
  withNotes = withChunk(withNotes, chunksOf(withNotes).size(), "thmb", std::string(40, '\xff'));
  std::vector<std::string> logged;
  const LogSink previous = setLogSink([&](LogLevel level, const std::string& message) {
    if (level == LogLevel::Warning) logged.push_back(message);
  });
  ProjectReadReport report;
  const planning::Project back = decodeProject(withNotes, "later.ddfproj", &report);
  setLogSink(previous);
  expectSameProject(project, back);
  EXPECT_EQ(report.formatVersion, 4u);
  EXPECT_EQ(report.skippedChunks, (std::vector<std::string>{"later.ddfproj: chunk 4 ('note')",
                                                            "later.ddfproj: chunk 16 ('thmb')"}));
  ASSERT_EQ(logged.size(), 2u);
  EXPECT_THAT(logged[0], HasSubstr("chunk 4 ('note'): optional chunk of a newer ddfcam skipped"));
  // The same chunk with an upper-case tag must be understood, so it is an error.
  EXPECT_THAT(test::ioErrorMessage(
                  [&] { decodeProject(withChunk(bytes, 3, "Note", "x"), "later.ddfproj"); }),
              HasSubstr("chunk 4 ('Note'): unknown chunk type in format version 4"));
  // Optional or not, nothing may precede the project header.
  EXPECT_THAT(test::ioErrorMessage([&] { decodeProject(withChunk(bytes, 0, "note", ""), "x"); }),
              HasSubstr("the first chunk must be 'PROJ'"));
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
