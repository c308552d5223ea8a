// SPDX-License-Identifier: MIT
#include <ddfcam/error.h>
#include <ddfcam/io/common/checksum.h>
#include <ddfcam/io/mesh/ddf_file.h>

#include <gmock/gmock.h>
#include <gtest/gtest.h>

#include <cstring>
#include <random>

#include "../../support/test_meshes.h"
#include "../io_test_support.h"
#include "mesh/ddf_layout.h"

namespace ddfcam::io {
namespace {

/// Octahedron DDF with random heights including the awkward float values.
ddf::DisplacementField sampleField(int m = 6) {
  const auto mesh = test::octahedronMesh(std::sqrt(3.0));
  ddf::DisplacementField field(mesh, test::radialVectors(mesh, 0.3), m);
  std::mt19937 rng(17);
  std::uniform_real_distribution<float> u(-1.f, 1.f);
  for (float& h : field.allHeights()) h = u(rng);
  field.allHeights()[0] = -0.0f;
  field.allHeights()[1] = std::numeric_limits<float>::denorm_min();
  field.allHeights()[2] = std::numeric_limits<float>::quiet_NaN();
  return field;
}

using test::expectBitwiseEqual;

TEST(DdfFile, Crc32MatchesTheStandardCheckValue) {
  const std::string check = "123456789";
  EXPECT_EQ(crc32(std::as_bytes(std::span(check.data(), check.size()))), 0xCBF43926u);
  Crc32 split;
  split.update(std::as_bytes(std::span(check.data(), 4)));
  split.update(std::as_bytes(std::span(check.data() + 4, 5)));
  EXPECT_EQ(split.value(), 0xCBF43926u);
}

TEST(DdfFile, FileRoundTripIsBitwiseExact) {
  test::ScratchDir dir;
  const auto field = sampleField();
  writeDdf(field, dir / "part.ddf");
  expectBitwiseEqual(readDdf(dir / "part.ddf"), field);
  // Overwriting works and leaves no temporary files behind.
  writeDdf(field, dir / "part.ddf");
  EXPECT_EQ(std::distance(std::filesystem::directory_iterator(dir.path()), {}), 1);
}

TEST(DdfFile, EncodingIsStableAndHasTheDocumentedLayout) {
  const auto field = sampleField(4);
  const std::string bytes = encodeDdf(field);
  const std::size_t V = 6, F = 8, perFace = 10;
  ASSERT_EQ(bytes.size(), 40 + 48 * V + 12 * F + 4 * F * perFace + 4);
  EXPECT_EQ(bytes.substr(0, 8), std::string("DDFCAM\x1a\n", 8));
  EXPECT_EQ(bytes.substr(8, 8), std::string("\x01\x00\x00\x00\x04\x03\x02\x01", 8));
  EXPECT_EQ(static_cast<unsigned char>(bytes[16]), V);
  EXPECT_EQ(static_cast<unsigned char>(bytes[24]), F);
  EXPECT_EQ(static_cast<unsigned char>(bytes[32]), 4u);
  // First position x, little-endian f64, decoded here by hand.
  std::uint64_t bits = 0;
  for (int i = 7; i >= 0; --i) bits = (bits << 8) | static_cast<unsigned char>(bytes[40 + i]);
  EXPECT_EQ(std::bit_cast<double>(bits), field.position(0).x());
  // Face 0 in the field's local order.
  const std::size_t faces = 40 + 48 * V;
  for (int c = 0; c < 3; ++c)
    EXPECT_EQ(static_cast<unsigned char>(bytes[faces + 4 * c]), field.faceVertices(0)[c]);
  EXPECT_EQ(encodeDdf(decodeDdf(bytes, "memory")), bytes);
}

TEST(DdfFile, SupportRebuiltFromFacesKeepsTheLocalVertexOrder) {
  // OpenMesh starts a new face's first halfedge at its last vertex, so a DDF built from
  // triangle (a, b, c) has local order (c, a, b): a rotation, same orientation. The reader must
  // still hand back exactly the stored order, since the heights are stored in it.
  const std::vector<ddf::Vec3> points = {{0, 0, 0},   {1.5, 0, 0},     {3, 0, 0.2},
                                         {0, 0.7, 0}, {1.5, 0.7, 0.1}, {3, 0.7, 0}};
  const std::vector<std::array<int, 3>> triangles = {{0, 1, 4}, {0, 4, 3}, {1, 2, 5}, {1, 5, 4}};
  const auto support = ddf::makeSupportMesh(points, triangles);
  ddf::DisplacementField field(support, test::constantVectors(support, {0.1, 0.0, 1.0}), 5);
  for (std::size_t i = 0; i < field.allHeights().size(); ++i)
    field.allHeights()[i] = static_cast<float>(i) * 1e-3f;
  for (int f = 0; f < field.faceCount(); ++f) {
    const auto& t = triangles[f];
    EXPECT_EQ(field.faceVertices(f), (std::array<int, 3>{t[2], t[0], t[1]})) << "face " << f;
  }
  const auto back = decodeDdf(encodeDdf(field), "memory");
  expectBitwiseEqual(back, field);
  for (int f = 0; f < field.faceCount(); ++f)
    for (int k = 0; k < 5; ++k)
      for (int i = 0; i + k < 5; ++i)
        EXPECT_EQ(back.surfacePoint(f, i, k), field.surfacePoint(f, i, k));
}

TEST(DdfFile, ReorderHeightsKeepsEveryPointOnItsVertexWeights) {
  const ddf::Raster raster{7};
  const std::array<int, 3> stored{10, 20, 30};
  std::vector<float> heights(raster.pointCount());
  // Oracle: the height encodes the point's weights on vertices 10, 20, 30.
  const int n = raster.steps();
  const auto code = [](int w10, int w20, int w30) { return float(100 * w10 + 10 * w20 + w30); };
  for (int k = 0; k <= n; ++k)
    for (int i = 0; i + k <= n; ++i) heights[raster.index(i, k)] = code(i, n - i - k, k);
  for (const std::array<int, 3> actual : {std::array{30, 10, 20}, std::array{20, 30, 10}}) {
    std::vector<float> out(raster.pointCount(), -1.f);
    detail::reorderHeights(stored, actual, raster, heights, out);
    for (int k = 0; k <= n; ++k)
      for (int i = 0; i + k <= n; ++i) {
        const int weights[3] = {i, n - i - k, k};  // on actual[0..2]
        int w10 = 0, w20 = 0, w30 = 0;
        for (int s = 0; s < 3; ++s)
          (actual[s] == 10 ? w10 : actual[s] == 20 ? w20 : w30) = weights[s];
        EXPECT_EQ(out[raster.index(i, k)], code(w10, w20, w30));
      }
  }
  std::vector<float> out(raster.pointCount());
  EXPECT_THROW(detail::reorderHeights(stored, {10, 20, 31}, raster, heights, out), IoError);
}

TEST(DdfFile, ReadsTheCommittedVersion1File) {
  // Guards format compatibility: this file was written by format version 1 (see
  // tests/data/README.md) and must keep reading the same in every later build.
  const auto path = std::filesystem::path(DDFCAM_TEST_DATA_DIR) / "octahedron_m4_v1.ddf";
  const auto field = readDdf(path);
  ASSERT_EQ(field.vertexCount(), 6);
  ASSERT_EQ(field.faceCount(), 8);
  ASSERT_EQ(field.resolution(), 4);
  const ddf::Vec3 axes[6] = {{1, 0, 0}, {-1, 0, 0}, {0, 1, 0}, {0, -1, 0}, {0, 0, 1}, {0, 0, -1}};
  for (int v = 0; v < 6; ++v) {
    EXPECT_EQ(field.position(v), 2.0 * axes[v]);
    EXPECT_EQ(field.vector(v), 0.5 * axes[v]);
  }
  for (int f = 0; f < 8; ++f)
    for (int k = 0; k < 4; ++k)
      for (int i = 0; i + k < 4; ++i)
        EXPECT_EQ(field.height(f, i, k), (f + 1) / 16.0f - i / 8.0f + k / 32.0f);
  EXPECT_EQ(encodeDdf(field), test::readBytes(path));
}

TEST(DdfFile, WriteFailureLeavesNoFileBehind) {
  test::ScratchDir dir;
  const std::string message =
      test::ioErrorMessage([&] { writeDdf(sampleField(), dir / "missing_dir" / "x.ddf"); });
  EXPECT_THAT(message, ::testing::HasSubstr("x.ddf"));
  EXPECT_EQ(std::distance(std::filesystem::directory_iterator(dir.path()), {}), 0);
}

}  // namespace
}  // namespace ddfcam::io
