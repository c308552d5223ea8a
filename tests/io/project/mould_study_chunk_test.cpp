// SPDX-License-Identifier: MIT
// Tests of the "MOLD" chunk of the .ddfproj format: round trips, version 3, damaged payloads.
#include <ddfcam/error.h>
#include <ddfcam/io/project/project_file.h>

#include <gmock/gmock.h>
#include <gtest/gtest.h>

#include <cstring>
#include <string>

#include "../../support/mould_study_sample.h"
#include "../io_test_support.h"
#include "project_test_support.h"

namespace ddfcam::io {
namespace {

using ::testing::HasSubstr;

/// Offset of the payload of the chunk with @p tag (first one), or npos.
std::size_t payloadOffset(const std::string& bytes, const std::string& tag,
                          std::uint64_t* length = nullptr) {
  std::size_t at = 24;
  while (at + 12 <= bytes.size() - 4) {
    std::uint64_t size = 0;
    for (int i = 7; i >= 0; --i) size = (size << 8) | static_cast<unsigned char>(bytes[at + 4 + i]);
    if (bytes.compare(at, 4, tag) == 0) {
      if (length) *length = size;
      return at + 12;
    }
    at += 12 + size;
  }
  return std::string::npos;
}

TEST(MouldStudyChunk, StudyRoundTripsBitExactly) {
  planning::Project project = test::makeRichProject();
  project.mould = test::sampleMouldStudy();
  ProjectReadReport report;
  const planning::Project back = decodeProject(encodeProject(project), "mould.ddfproj", &report);
  EXPECT_EQ(report.formatVersion, 4u);
  ASSERT_TRUE(back.mould.has_value());
  EXPECT_TRUE(planning::mouldStudiesEqual(*project.mould, *back.mould));
  EXPECT_TRUE(planning::projectsEqual(project, back));
  // Spot checks independent of mouldStudiesEqual.
  EXPECT_EQ(back.mould->formed->fields[0].name, "strain");
  EXPECT_TRUE(std::signbit(back.mould->formed->fields[0].values[1]));
  EXPECT_TRUE(std::isnan(back.mould->result->deviation.values[7]));
  EXPECT_EQ(back.mould->result->sequence.stages.size(), 2u);
  EXPECT_EQ(back.mould->compensation->iterations[1].pointsOutsideCrust, 2u);
}

TEST(MouldStudyChunk, MinimalStudiesRoundTrip) {
  planning::Project project;
  project.partName = "mould only";
  project.mould = planning::MouldStudy{};
  EXPECT_TRUE(planning::projectsEqual(project, decodeProject(encodeProject(project), "a")));
  planning::MouldStudy study = test::sampleMouldStudy();
  study.formed.reset();
  study.result.reset();
  project.mould = study;
  EXPECT_TRUE(planning::projectsEqual(project, decodeProject(encodeProject(project), "b")));
  study = test::sampleMouldStudy();
  study.compensation.reset();
  project.mould = study;
  EXPECT_TRUE(planning::projectsEqual(project, decodeProject(encodeProject(project), "c")));
}

TEST(MouldStudyChunk, Version3FileStillReads) {
  const planning::Project project = test::makeRichProject();
  std::string bytes = encodeProject(project);
  test::putLeAt(bytes, 8, 3, 4);
  ProjectReadReport report;
  const planning::Project back = decodeProject(test::resealed(bytes), "v3.ddfproj", &report);
  EXPECT_EQ(report.formatVersion, 3u);
  EXPECT_FALSE(back.mould.has_value());
  EXPECT_TRUE(planning::projectsEqual(project, back));
  // Saving again writes version 4.
  EXPECT_EQ(encodeProject(back).substr(8, 4), std::string("\x04\0\0\0", 4));
}

TEST(MouldStudyChunk, MouldChunkInVersion3IsUnknown) {
  planning::Project project;
  project.mould = test::sampleMouldStudy();
  std::string bytes = encodeProject(project);
  test::putLeAt(bytes, 8, 3, 4);
  EXPECT_THAT(test::ioErrorMessage([&] { decodeProject(test::resealed(bytes), "old"); }),
              HasSubstr("chunk 2 ('MOLD'): unknown chunk type in format version 3"));
}

TEST(MouldStudyChunk, DamagedPayloadNamesTheChunk) {
  planning::Project project;
  project.mould = test::sampleMouldStudy();
  const std::string bytes = encodeProject(project);
  std::uint64_t length = 0;
  const std::size_t at = payloadOffset(bytes, "MOLD", &length);
  ASSERT_NE(at, std::string::npos);

  // The flag after the mould surface: name, path, mesh (16 + 4 x 24 + 2 x 12), 1 field.
  const planning::LoadedSurface& mould = project.mould->mould;
  const std::size_t mouldSurface = (4 + mould.name.size()) + (4 + mould.sourcePath.size()) + 16 +
                                   96 + 24 + 8 + (4 + 9) + (4 + 2) + 1 + 8 + 16;
  std::string flag = bytes;
  ASSERT_EQ(flag[at + mouldSurface], '\1');
  flag[at + mouldSurface] = '\7';
  std::string message = test::ioErrorMessage([&] { decodeProject(test::resealed(flag), "f"); });
  EXPECT_THAT(message, HasSubstr("chunk 2 ('MOLD')"));
  EXPECT_THAT(message, HasSubstr("formed-surface flag must be 0 or 1, found 7"));

  // A byte inside the first stage's embedded .ddf (its own checksum catches it).
  std::string stage = bytes;
  const std::size_t ddfAt = stage.find(std::string("DDFCAM\x1a\n", 8), at);
  ASSERT_NE(ddfAt, std::string::npos);
  stage[ddfAt + 40] ^= 0x5a;
  message = test::ioErrorMessage([&] { decodeProject(test::resealed(stage), "m"); });
  EXPECT_THAT(message, HasSubstr("chunk 2 ('MOLD')"));
  EXPECT_THAT(message, HasSubstr("the DDF of deformation stage 0 is not a valid .ddf encoding"));

  // A payload cut short.
  std::string cut = bytes.substr(0, at + length - 5) + bytes.substr(at + length);
  test::putLeAt(cut, at - 8, length - 5, 8);
  message = test::ioErrorMessage([&] { decodeProject(test::resized(cut), "c"); });
  EXPECT_THAT(message, HasSubstr("chunk 2 ('MOLD')"));
  EXPECT_THAT(message, HasSubstr("the payload ends in the"));
}

TEST(MouldStudyChunk, InvalidStudyIsNotEncoded) {
  planning::Project project;
  project.mould = test::sampleMouldStudy();
  project.mould->result->deviation.values.pop_back();
  EXPECT_THROW(encodeProject(project), InvalidInput);
}

}  // namespace
}  // namespace ddfcam::io
