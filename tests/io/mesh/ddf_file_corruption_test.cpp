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

/// The smallest interesting field: two triangles, m = 3 (6 heights each); 296 bytes.
std::string smallFile() {
  const auto mesh = test::gridMesh(1, 1, 2.0, 1.0);
  ddf::DisplacementField field(mesh, test::constantVectors(mesh), 3, 0.25f);
  return encodeDdf(field);
}

std::string decodeError(const std::string& bytes) {
  return test::ioErrorMessage([&] { decodeDdf(bytes, "part.ddf"); });
}

/// Replaces the trailing CRC so that a deliberately edited body passes the checksum.
std::string resealed(std::string bytes) {
  const std::size_t body = bytes.size() - 4;
  const std::uint32_t crc = crc32(std::as_bytes(std::span(bytes.data(), body)));
  for (int i = 0; i < 4; ++i) bytes[body + i] = static_cast<char>((crc >> (8 * i)) & 0xFF);
  return bytes;
}

void putU32At(std::string& bytes, std::size_t offset, std::uint32_t value) {
  for (int i = 0; i < 4; ++i) bytes[offset + i] = static_cast<char>((value >> (8 * i)) & 0xFF);
}

TEST(DdfFileCorruption, TruncationAtEveryByteIsReported) {
  const std::string bytes = smallFile();
  ASSERT_EQ(bytes.size(), 40u + 4 * 48 + 2 * 12 + 2 * 6 * 4 + 4);
  EXPECT_THAT(decodeError(""), HasSubstr("part.ddf: file is empty"));
  for (std::size_t size = 1; size < bytes.size(); ++size)
    EXPECT_THAT(decodeError(bytes.substr(0, size)), HasSubstr("truncated")) << "size " << size;
}

TEST(DdfFileCorruption, EveryFlippedByteIsDetected) {
  const std::string bytes = smallFile();
  for (std::size_t at = 0; at < bytes.size(); ++at)
    for (const unsigned char mask : {0x01, 0x80, 0xFF}) {
      std::string bad = bytes;
      bad[at] = static_cast<char>(bad[at] ^ mask);
      EXPECT_THAT(decodeError(bad), HasSubstr("part.ddf: ")) << "byte " << at;
    }
  std::string body = bytes;
  body[100] ^= 0x10;
  EXPECT_THAT(decodeError(body), HasSubstr("checksum mismatch"));
  std::string crc = bytes;
  crc.back() ^= 0x01;
  EXPECT_THAT(decodeError(crc), HasSubstr("checksum mismatch"));
}

TEST(DdfFileCorruption, HeaderProblemsAreNamed) {
  const std::string bytes = smallFile();
  std::string magic = bytes;
  magic[0] = 'X';
  EXPECT_THAT(decodeError(magic), HasSubstr("not a .ddf file (wrong magic)"));
  EXPECT_THAT(decodeError("solid cube\n facet normal 0 0 1\n"), HasSubstr("wrong magic"));
  std::string newer = bytes;
  putU32At(newer, 8, 3);
  EXPECT_THAT(decodeError(resealed(newer)),
              HasSubstr("unsupported .ddf format version 3: this build reads versions up to 2"));
  std::string bigEndian = bytes;
  putU32At(bigEndian, 12, 0x04030201u);
  EXPECT_THAT(decodeError(resealed(bigEndian)), HasSubstr("big-endian"));
  std::string resolution = bytes;
  putU32At(resolution, 32, 1);
  EXPECT_THAT(decodeError(resealed(resolution)), HasSubstr("raster resolution m = 1"));
  std::string trailing = bytes + "x";
  EXPECT_THAT(decodeError(trailing), HasSubstr("trailing data"));
  std::string huge = bytes;
  for (int i = 16; i < 24; ++i) huge[i] = '\xff';
  EXPECT_THAT(decodeError(huge), HasSubstr("implausible counts"));
}

TEST(DdfFileCorruption, InvalidContentWithAValidChecksumIsRejected) {
  const std::string bytes = smallFile();
  const std::size_t faces = 40 + 4 * 48;
  std::string range = bytes;
  putU32At(range, faces + 4, 9);
  EXPECT_THAT(decodeError(resealed(range)), HasSubstr("face 0 refers to vertex 9 of 4"));
  std::string repeated = bytes;
  putU32At(repeated, faces + 12, 0);
  putU32At(repeated, faces + 16, 0);
  EXPECT_THAT(decodeError(resealed(repeated)), HasSubstr("face 1 repeats a vertex"));
  // Both faces with the same orientation on the shared diagonal: OpenMesh refuses the second.
  std::string flipped = bytes;
  for (int c = 0; c < 3; ++c) putU32At(flipped, faces + 12 + 4 * c, bytes[faces + 4 * c]);
  const std::string message = decodeError(resealed(flipped));
  EXPECT_THAT(message, HasSubstr("support mesh is invalid"));
  EXPECT_THAT(message, HasSubstr("support triangle 1"));
  std::string nan = bytes;
  for (int i = 0; i < 8; ++i) nan[40 + i] = i == 7 ? '\x7f' : i == 6 ? '\xf8' : '\0';
  EXPECT_THAT(decodeError(resealed(nan)), HasSubstr("position of vertex 0 is not finite"));
}

TEST(DdfFileCorruption, MissingAndEmptyFiles) {
  test::ScratchDir dir;
  EXPECT_THAT(test::ioErrorMessage([&] { readDdf(dir / "none.ddf"); }),
              HasSubstr("none.ddf does not exist"));
  test::writeBytes(dir / "empty.ddf", "");
  EXPECT_THAT(test::ioErrorMessage([&] { readDdf(dir / "empty.ddf"); }),
              HasSubstr("empty.ddf: file is empty"));
}

}  // namespace
}  // namespace ddfcam::io
