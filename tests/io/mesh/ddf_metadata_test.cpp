// SPDX-License-Identifier: MIT
#include <ddfcam/error.h>
#include <ddfcam/io/common/checksum.h>
#include <ddfcam/io/mesh/ddf_file.h>

#include <gmock/gmock.h>
#include <gtest/gtest.h>

#include "../../support/test_meshes.h"
#include "../io_test_support.h"

namespace ddfcam::io {
namespace {

using ::testing::HasSubstr;

ddf::DisplacementField octahedronField() {
  const auto mesh = test::octahedronMesh(2.0);
  ddf::DisplacementField field(mesh, test::radialVectors(mesh, 0.5), 4);
  for (std::size_t i = 0; i < field.allHeights().size(); ++i)
    field.allHeights()[i] = static_cast<float>(i % 7) / 8.0f - 0.4f;
  return field;
}

DdfMetadata cadMetadata() {
  DdfMetadata m;
  m.sourceUnit = ddfcam::LengthUnit::Inch;
  m.cadFaceNames = {"face 0 (plane)", "face 1 (B-spline)", "Fl\xc3\xa4che 2"};
  m.cadFaceOfSupportFace = {0, 0, 1, 1, 2, 2, -1, 1};
  return m;
}

std::uint32_t u32At(const std::string& bytes, std::size_t at) {
  std::uint32_t v = 0;
  for (int i = 3; i >= 0; --i) v = (v << 8) | static_cast<unsigned char>(bytes[at + i]);
  return v;
}

void putU32At(std::string& bytes, std::size_t at, std::uint32_t value) {
  for (int i = 0; i < 4; ++i) bytes[at + i] = static_cast<char>((value >> (8 * i)) & 0xFF);
}

std::string resealed(std::string bytes) {
  const std::size_t body = bytes.size() - 4;
  putU32At(bytes, body, crc32(std::as_bytes(std::span(bytes.data(), body))));
  return bytes;
}

void expectSameMetadata(const DdfMetadata& a, const DdfMetadata& b) {
  EXPECT_EQ(a.sourceUnit, b.sourceUnit);
  EXPECT_EQ(a.cadFaceOfSupportFace, b.cadFaceOfSupportFace);
  EXPECT_EQ(a.cadFaceNames, b.cadFaceNames);
}

TEST(DdfMetadata, FileRoundTripKeepsUnitAndCadFaces) {
  test::ScratchDir dir;
  const auto field = octahedronField();
  writeDdf(field, dir / "part.ddf", cadMetadata());
  DdfMetadata back;
  test::expectBitwiseEqual(readDdf(dir / "part.ddf", &back), field);
  EXPECT_TRUE(back.stored);
  expectSameMetadata(back, cadMetadata());
  // Readers that do not ask for the metadata get the same field.
  test::expectBitwiseEqual(readDdf(dir / "part.ddf"), field);
}

TEST(DdfMetadata, SectionHasTheDocumentedLayout) {
  const auto field = octahedronField();
  const std::string plain = encodeDdf(field);
  DdfMetadata unitOnly;
  unitOnly.sourceUnit = ddfcam::LengthUnit::Metre;
  const std::string bytes = encodeDdf(field, unitOnly);
  // Version 2 in the header; body as version 1; then L = 32: unit 2, no names, no faces, no
  // design mesh (0 vertices, 0 triangles).
  EXPECT_EQ(u32At(plain, 8), 1u);
  EXPECT_EQ(u32At(bytes, 8), 2u);
  const std::size_t body = plain.size() - 4;
  EXPECT_EQ(bytes.substr(12, body - 12), plain.substr(12, body - 12));
  ASSERT_EQ(bytes.size(), plain.size() + 4 + 32);
  EXPECT_EQ(u32At(bytes, body), 32u);
  EXPECT_EQ(u32At(bytes, body + 4), 2u);
  EXPECT_EQ(u32At(bytes, body + 8), 0u);
  EXPECT_EQ(bytes.substr(body + 12, 24), std::string(24, '\0'));
  EXPECT_EQ(u32At(bytes, bytes.size() - 4),
            crc32(std::as_bytes(std::span(bytes.data(), bytes.size() - 4))));
}

TEST(DdfMetadata, DesignMeshRoundTripsAndSectionsWithoutItStillRead) {
  const auto field = octahedronField();
  DdfMetadata withMesh = cadMetadata();
  withMesh.designMesh = test::boxMesh(ddf::Vec3(-1, -2, -3), ddf::Vec3(0.1, 0.2, 1.0 / 3.0));
  DdfMetadata back;
  test::expectBitwiseEqual(decodeDdf(encodeDdf(field, withMesh), "memory", &back), field);
  expectSameMetadata(back, withMesh);
  ASSERT_TRUE(back.designMesh.has_value());
  EXPECT_EQ(back.designMesh->vertices, withMesh.designMesh->vertices);  // bit-identical
  EXPECT_EQ(back.designMesh->triangles, withMesh.designMesh->triangles);
  // A section as written before the design mesh member (it ends after the CAD faces).
  std::string bytes = encodeDdf(field, cadMetadata());
  const std::size_t body = encodeDdf(field).size() - 4;
  bytes.erase(bytes.size() - 4 - 16, 16);
  putU32At(bytes, body, u32At(bytes, body) - 16);
  back = DdfMetadata{};
  test::expectBitwiseEqual(decodeDdf(resealed(bytes), "memory", &back), field);
  expectSameMetadata(back, cadMetadata());
  EXPECT_FALSE(back.designMesh.has_value());
  // A triangle naming a vertex the mesh does not have is named.
  std::string bad = encodeDdf(field, withMesh);
  putU32At(bad, bad.size() - 8, 99);
  EXPECT_THAT(test::ioErrorMessage([&] { decodeDdf(resealed(bad), "p.ddf"); }),
              HasSubstr("p.ddf: metadata section: design mesh vertex 99 of 8"));
}

TEST(DdfMetadata, OldFilesReadWithDefaultMetadata) {
  // The committed version-1 file and a field written without metadata have no section.
  DdfMetadata read = cadMetadata();
  readDdf(std::filesystem::path(DDFCAM_TEST_DATA_DIR) / "octahedron_m4_v1.ddf", &read);
  EXPECT_FALSE(read.stored);
  expectSameMetadata(read, DdfMetadata{});
  read = cadMetadata();
  decodeDdf(encodeDdf(octahedronField()), "memory", &read);
  EXPECT_FALSE(read.stored);
  EXPECT_EQ(read.sourceUnit, ddfcam::LengthUnit::Millimetre);
}

TEST(DdfMetadata, LaterMembersOfTheSectionAreIgnored) {
  const auto field = octahedronField();
  std::string bytes = encodeDdf(field, cadMetadata());
  const std::size_t body = encodeDdf(field).size() - 4;
  const std::uint32_t length = u32At(bytes, body);
  bytes.insert(bytes.size() - 4, "future");
  putU32At(bytes, body, length + 6);
  DdfMetadata back;
  test::expectBitwiseEqual(decodeDdf(resealed(bytes), "memory", &back), field);
  expectSameMetadata(back, cadMetadata());
}

TEST(DdfMetadata, DamagedSectionIsNamed) {
  const auto field = octahedronField();
  const std::string bytes = encodeDdf(field, cadMetadata());
  const std::size_t body = encodeDdf(field).size() - 4;
  std::string unit = bytes;
  putU32At(unit, body + 4, 9);
  EXPECT_THAT(test::ioErrorMessage([&] { decodeDdf(resealed(unit), "p.ddf"); }),
              HasSubstr("p.ddf: metadata section: unknown source unit code 9"));
  std::string shortSection = bytes;
  putU32At(shortSection, body, 20);
  shortSection.erase(body + 4 + 20, u32At(bytes, body) - 20);
  EXPECT_THAT(test::ioErrorMessage([&] { decodeDdf(resealed(shortSection), "p.ddf"); }),
              HasSubstr("metadata section: truncated"));
  std::string longer = bytes;
  putU32At(longer, body, u32At(bytes, body) + 100);
  EXPECT_THAT(test::ioErrorMessage([&] { decodeDdf(resealed(longer), "p.ddf"); }),
              HasSubstr("truncated .ddf file"));
  std::string face = bytes;
  // The last support face (before the empty design mesh member) names CAD face 7 of 3.
  putU32At(face, bytes.size() - 4 - 16 - 4, 7);
  EXPECT_THAT(test::ioErrorMessage([&] { decodeDdf(resealed(face), "p.ddf"); }),
              HasSubstr("support face 7 names CAD face 7 of 3"));
}

TEST(DdfMetadata, TruncationAtEveryByteIsReported) {
  const std::string bytes = encodeDdf(octahedronField(), cadMetadata());
  for (std::size_t size = 1; size < bytes.size(); ++size)
    EXPECT_THAT(test::ioErrorMessage([&] { decodeDdf(bytes.substr(0, size), "p.ddf"); }),
                HasSubstr("truncated"))
        << "size " << size;
}

TEST(DdfMetadata, InconsistentMetadataIsRefusedBeforeWriting) {
  test::ScratchDir dir;
  DdfMetadata wrongCount = cadMetadata();
  wrongCount.cadFaceOfSupportFace.pop_back();
  EXPECT_THROW(writeDdf(octahedronField(), dir / "x.ddf", wrongCount), InvalidInput);
  DdfMetadata wrongName = cadMetadata();
  wrongName.cadFaceOfSupportFace[0] = 3;
  EXPECT_THROW(encodeDdf(octahedronField(), wrongName), InvalidInput);
  EXPECT_FALSE(std::filesystem::exists(dir / "x.ddf"));
}

}  // namespace
}  // namespace ddfcam::io
