// SPDX-License-Identifier: MIT
#include <ddfcam/error.h>
#include <ddfcam/io/project/project_file.h>

#include <gmock/gmock.h>
#include <gtest/gtest.h>

#include <filesystem>
#include <string>
#include <utility>
#include <vector>

#include "../io_test_support.h"
#include "project_test_support.h"

namespace ddfcam::io {
namespace {

using ::testing::HasSubstr;

/// The rich sample project as if converted from an inch STEP file with three CAD faces.
planning::Project cadProject() {
  planning::Project project = test::makeRichProject();
  project.sourceUnit = ddfcam::LengthUnit::Inch;
  project.cadFaceNames = {"face 0 (plane)", "face 1 (cylinder)", "face 2 (B-spline)"};
  for (int f = 0; f < project.part->faceCount(); ++f)
    project.cadFaceOfSupportFace.push_back(f % 4 == 3 ? -1 : f % 3);
  return project;
}

/// (tag, payload) of every chunk, parsed from the documented table alone.
std::vector<std::pair<std::string, std::string>> chunksOf(const std::string& bytes) {
  std::vector<std::pair<std::string, std::string>> chunks;
  for (std::size_t at = 24; at + 4 < bytes.size();) {
    std::uint64_t length = 0;
    for (int i = 0; i < 8; ++i)
      length |= std::uint64_t{static_cast<unsigned char>(bytes[at + 4 + i])} << (8 * i);
    chunks.emplace_back(bytes.substr(at, 4), bytes.substr(at + 12, length));
    at += 12 + length;
  }
  return chunks;
}

std::uint64_t leAt(const std::string& bytes, std::size_t at, int count) {
  std::uint64_t v = 0;
  for (int i = count - 1; i >= 0; --i) v = (v << 8) | static_cast<unsigned char>(bytes[at + i]);
  return v;
}

/// Offset of the payload of the @p n-th chunk in @p bytes.
std::size_t payloadAt(const std::string& bytes, std::size_t n) {
  std::size_t at = 24;
  for (std::size_t i = 0; i < n; ++i) at += 12 + leAt(bytes, at + 4, 8);
  return at + 12;
}

TEST(ProjectSourceChunk, UnitAndCadFacesRoundTrip) {
  test::ScratchDir dir;
  const planning::Project project = cadProject();
  writeProject(project, dir / "cad.ddfproj");
  const planning::Project back = readProject(dir / "cad.ddfproj");
  EXPECT_TRUE(planning::projectsEqual(project, back));
  EXPECT_EQ(back.sourceUnit, ddfcam::LengthUnit::Inch);
  EXPECT_EQ(back.cadFaceNames, project.cadFaceNames);
  EXPECT_EQ(back.cadFaceOfSupportFace, project.cadFaceOfSupportFace);
  EXPECT_EQ(encodeProject(back), test::readBytes(dir / "cad.ddfproj"));
}

TEST(ProjectSourceChunk, PayloadFollowsTheDocumentedLayout) {
  const planning::Project project = cadProject();
  const auto chunks = chunksOf(encodeProject(project));
  ASSERT_GE(chunks.size(), 3u);
  EXPECT_EQ(chunks[2].first, "prov");  // after the part, optional (lower-case)
  const std::string& p = chunks[2].second;
  EXPECT_EQ(leAt(p, 0, 4), 3u);  // inch
  EXPECT_EQ(leAt(p, 4, 8), 3u);  // three names
  std::size_t at = 12;
  for (const std::string& name : project.cadFaceNames) {
    EXPECT_EQ(leAt(p, at, 4), name.size());
    EXPECT_EQ(p.substr(at + 4, name.size()), name);
    at += 4 + name.size();
  }
  const std::size_t faces = project.cadFaceOfSupportFace.size();
  ASSERT_EQ(p.size(), at + 8 + 4 * faces);
  EXPECT_EQ(leAt(p, at, 8), faces);
  for (std::size_t f = 0; f < faces; ++f)
    EXPECT_EQ(static_cast<std::int32_t>(leAt(p, at + 8 + 4 * f, 4)),
              project.cadFaceOfSupportFace[f]);
}

TEST(ProjectSourceChunk, ProjectsInMillimetresWithoutCadFacesAreSavedAsBefore) {
  // No "prov" chunk, so older builds read these files without a warning.
  for (const auto& chunk : chunksOf(encodeProject(test::makeRichProject())))
    EXPECT_NE(chunk.first, "prov");
  planning::Project metres = test::makeSmallProject();
  metres.sourceUnit = ddfcam::LengthUnit::Metre;
  const planning::Project back = decodeProject(encodeProject(metres), "m.ddfproj");
  EXPECT_EQ(back.sourceUnit, ddfcam::LengthUnit::Metre);
  EXPECT_TRUE(back.cadFaceOfSupportFace.empty());
}

TEST(ProjectSourceChunk, OldProjectsLoadInMillimetresWithoutCadFaces) {
  const auto path = std::filesystem::path(DDFCAM_TEST_DATA_DIR) / "two_regions_v1.ddfproj";
  const planning::Project project = readProject(path);
  EXPECT_EQ(project.sourceUnit, ddfcam::LengthUnit::Millimetre);
  EXPECT_TRUE(project.cadFaceOfSupportFace.empty());
  EXPECT_TRUE(project.cadFaceNames.empty());
}

TEST(ProjectSourceChunk, InconsistentCadFacesAreRefused) {
  planning::Project tooFew = cadProject();
  tooFew.cadFaceOfSupportFace.pop_back();
  EXPECT_THROW(encodeProject(tooFew), InvalidInput);
  planning::Project badName = cadProject();
  badName.cadFaceOfSupportFace[1] = 3;
  EXPECT_THROW(encodeProject(badName), InvalidInput);
  // The same mismatches in a file are load errors naming the file.
  std::string bytes = encodeProject(cadProject());
  const std::size_t faces = payloadAt(bytes, 2) + chunksOf(bytes)[2].second.size() - 4;
  test::putLeAt(bytes, faces, 7, 4);  // the last support face names CAD face 7 of 3
  EXPECT_THAT(test::ioErrorMessage([&] { decodeProject(test::resealed(bytes), "cad.ddfproj"); }),
              HasSubstr("cad.ddfproj"));
  std::string unit = encodeProject(cadProject());
  test::putLeAt(unit, payloadAt(unit, 2), 9, 4);
  EXPECT_THAT(test::ioErrorMessage([&] { decodeProject(test::resealed(unit), "cad.ddfproj"); }),
              HasSubstr("chunk 3 ('prov'): unknown source unit code 9"));
}

}  // namespace
}  // namespace ddfcam::io
