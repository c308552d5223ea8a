// SPDX-License-Identifier: MIT
#include <ddfcam/io/mesh/mesh_io.h>

#include <gtest/gtest.h>

#include <cstring>
#include <random>
#include <set>

#include "../io_test_support.h"

namespace ddfcam::io {
namespace {

using ddf::TriangleMesh;

/// Octahedron with irrational-looking coordinates (no short decimal form) and one extra,
/// unreferenced vertex, so exact round trips are a real test.
TriangleMesh awkwardMesh() {
  std::mt19937 rng(11);
  std::uniform_real_distribution<double> jitter(-1e-3, 1e-3);
  TriangleMesh mesh;
  const double r = std::sqrt(2.0) * 10.0;
  for (const Eigen::Vector3d& p :
       {Eigen::Vector3d(r, 0, 0), Eigen::Vector3d(-r, 0, 0), Eigen::Vector3d(0, r, 0),
        Eigen::Vector3d(0, -r, 0), Eigen::Vector3d(0, 0, r), Eigen::Vector3d(0, 0, -r)})
    mesh.vertices.push_back(p + Eigen::Vector3d(jitter(rng), jitter(rng), 1.0 / 3.0));
  mesh.triangles = {{0, 2, 4}, {2, 1, 4}, {1, 3, 4}, {3, 0, 4},
                    {2, 0, 5}, {1, 2, 5}, {3, 1, 5}, {0, 3, 5}};
  return mesh;
}

bool bitwiseEqual(const Eigen::Vector3d& a, const Eigen::Vector3d& b) {
  return std::memcmp(a.data(), b.data(), sizeof(double) * 3) == 0;
}

/// @p value rounded to float; volatile keeps GCC 12 -O3 from folding the round trip away.
double throughFloat(double value) {
  volatile float rounded = static_cast<float>(value);
  return rounded;
}

class ExactRoundTrip : public ::testing::TestWithParam<std::string> {};

TEST_P(ExactRoundTrip, VerticesAndTrianglesComeBackBitwise) {
  test::ScratchDir dir;
  const TriangleMesh mesh = awkwardMesh();
  const auto path = dir / ("mesh." + GetParam());
  writeMesh(mesh, path);
  const TriangleMesh back = readMesh(path);
  ASSERT_EQ(back.vertices.size(), mesh.vertices.size());
  for (std::size_t v = 0; v < mesh.vertices.size(); ++v)
    EXPECT_TRUE(bitwiseEqual(back.vertices[v], mesh.vertices[v])) << "vertex " << v;
  EXPECT_EQ(back.triangles, mesh.triangles);
}

INSTANTIATE_TEST_SUITE_P(MeshIo, ExactRoundTrip, ::testing::Values("obj", "ply", "off", "OBJ"));

TEST(MeshIo, BinaryStlRoundTripKeepsTrianglesAtFloatPrecisionAndWelds) {
  test::ScratchDir dir;
  const TriangleMesh mesh = awkwardMesh();
  writeMesh(mesh, dir / "mesh.stl");
  EXPECT_EQ(std::filesystem::file_size(dir / "mesh.stl"), 84u + 50u * mesh.triangles.size());
  const TriangleMesh back = readMesh(dir / "mesh.stl");
  ASSERT_EQ(back.triangles.size(), mesh.triangles.size());
  EXPECT_EQ(back.vertices.size(), 6u);  // the unreferenced vertex is gone, corners welded
  for (std::size_t t = 0; t < mesh.triangles.size(); ++t)
    for (int c = 0; c < 3; ++c) {
      const Eigen::Vector3d& original = mesh.vertices[mesh.triangles[t][c]];
      Eigen::Vector3d expected;
      for (int i = 0; i < 3; ++i) expected[i] = throughFloat(original[i]);
      EXPECT_TRUE(bitwiseEqual(back.vertices[back.triangles[t][c]], expected));
    }
}

TEST(MeshIo, WriteReportsFormatByExtension) {
  EXPECT_EQ(meshFormatOf("a/b.StL"), MeshFormat::Stl);
  EXPECT_EQ(meshFormatOf("x.ply"), MeshFormat::Ply);
  EXPECT_EQ(meshFormatOf("x.off"), MeshFormat::Off);
  EXPECT_EQ(meshFormatOf("x.obj"), MeshFormat::Obj);
  EXPECT_FALSE(meshFormatOf("x.ddf").has_value());
  EXPECT_FALSE(meshFormatOf("stl").has_value());
}

TEST(MeshIo, ReadsAsciiStlAndWeldsSharedCorners) {
  test::ScratchDir dir;
  test::writeBytes(dir / "quad.stl",
                   "solid quad\n facet normal 0 0 1\n  outer loop\n   vertex 0 0 0\n"
                   "   vertex 1 0 0\n   vertex 1 1 0\n  endloop\n endfacet\n"
                   " facet normal 0 0 1\n  outer loop\n   vertex 0 0 0\n   vertex 1 1 0\n"
                   "   vertex 0 1 -0\n  endloop\n endfacet\nendsolid quad\n");
  const TriangleMesh mesh = readMesh(dir / "quad.stl");
  ASSERT_EQ(mesh.triangles.size(), 2u);
  EXPECT_EQ(mesh.vertices.size(), 4u);
  EXPECT_EQ(mesh.triangles[0][0], mesh.triangles[1][0]);
  EXPECT_EQ(mesh.triangles[0][2], mesh.triangles[1][1]);
  EXPECT_EQ(mesh.vertices[mesh.triangles[1][2]], Eigen::Vector3d(0, 1, 0));
}

TEST(MeshIo, KeepsNonManifoldAndDegenerateFaces) {
  // Three triangles on edge 0-1 (non-manifold) plus a duplicate and a degenerate one: an
  // OpenMesh reader would drop some of them; a triangle soup must keep all five.
  test::ScratchDir dir;
  test::writeBytes(dir / "fin.obj",
                   "v 0 0 0\nv 1 0 0\nv 0 1 0\nv 0 -1 0\nv 0 0 1\n"
                   "f 1 2 3\nf 2 1 4\nf 1 2 5\nf 1 2 3\nf 1 1 2\n");
  const TriangleMesh mesh = readMesh(dir / "fin.obj");
  ASSERT_EQ(mesh.triangles.size(), 5u);
  EXPECT_EQ(mesh.triangles[1], (std::array<int, 3>{1, 0, 3}));
  EXPECT_EQ(mesh.triangles[4], (std::array<int, 3>{0, 0, 1}));
}

TEST(MeshIo, ObjPolygonsFanAndCornerSyntaxes) {
  test::ScratchDir dir;
  test::writeBytes(dir / "poly.obj",
                   "# comment\nmtllib x.mtl\no thing\nv 0 0 0\nv 1 0 0\nv 1 1 0 1.0\nv 0 1 0\n"
                   "vt 0 0\nvn 0 0 1\ng group\nusemtl red\ns off\n"
                   "f 1/1/1 2/1/1 3//1 4/1\nf -4 -2 -1\n");
  const TriangleMesh mesh = readMesh(dir / "poly.obj");
  EXPECT_EQ(mesh.vertices.size(), 4u);
  ASSERT_EQ(mesh.triangles.size(), 3u);
  EXPECT_EQ(mesh.triangles[0], (std::array<int, 3>{0, 1, 2}));
  EXPECT_EQ(mesh.triangles[1], (std::array<int, 3>{0, 2, 3}));
  EXPECT_EQ(mesh.triangles[2], (std::array<int, 3>{0, 2, 3}));
}

TEST(MeshIo, OffVariantsCommentsAndQuads) {
  test::ScratchDir dir;
  test::writeBytes(dir / "quad.off",
                   "COFF # colours follow the coordinates\n\n4 1 0\n0 0 0 255 0 0 255\n"
                   "2 0 0 255 0 0 255\n# a comment line\n2 2 0 0 0 0 255\n0 2 0 0 0 0 255\n"
                   "4 0 1 2 3 0.5 0.5 0.5\n");
  const TriangleMesh mesh = readMesh(dir / "quad.off");
  ASSERT_EQ(mesh.triangles.size(), 2u);
  EXPECT_EQ(mesh.vertices[2], Eigen::Vector3d(2, 2, 0));
  test::writeBytes(dir / "inline.off", "OFF 3 1 0\n0 0 0\n1 0 0\n0 1 0\n3 0 1 2\n");
  EXPECT_EQ(readMesh(dir / "inline.off").triangles.size(), 1u);
}

TEST(MeshIo, PlyAsciiWithExtraPropertiesAndElements) {
  test::ScratchDir dir;
  test::writeBytes(dir / "extra.ply",
                   "ply\nformat ascii 1.0\ncomment test\nelement vertex 4\nproperty float "
                   "confidence\nproperty float x\nproperty float y\nproperty float z\n"
                   "property list uchar int extra\nelement face 1\nproperty uchar flags\n"
                   "property list uchar uint vertex_indices\nelement edge 1\nproperty int v1\n"
                   "property int v2\nend_header\n0.5 0 0 0 2 7 8\n0.5 1 0 0 0\n0.5 1 1 0 1 3\n"
                   "0.5 0 1 0.25 0\n9 4 0 1 2 3\n0 1\n");
  const TriangleMesh mesh = readMesh(dir / "extra.ply");
  ASSERT_EQ(mesh.vertices.size(), 4u);
  EXPECT_EQ(mesh.vertices[3], Eigen::Vector3d(0, 1, 0.25));
  ASSERT_EQ(mesh.triangles.size(), 2u);
  EXPECT_EQ(mesh.triangles[1], (std::array<int, 3>{0, 2, 3}));
}

TEST(MeshIo, PlyBinaryBigEndian) {
  // Written by hand, byte by byte: 3 float vertices and one face with int16 count list.
  std::string bytes =
      "ply\nformat binary_big_endian 1.0\nelement vertex 3\nproperty float x\nproperty float "
      "y\nproperty float z\nelement face 1\nproperty list short int vertex_indices\nend_header\n";
  const auto putBe32 = [&](std::uint32_t v) {
    for (int s = 24; s >= 0; s -= 8) bytes += static_cast<char>((v >> s) & 0xFF);
  };
  const float coords[9] = {0.f, 0.f, 0.f, 1.5f, 0.f, 0.f, 0.f, -2.25f, 0.f};
  for (const float c : coords) putBe32(std::bit_cast<std::uint32_t>(c));
  bytes += std::string("\x00\x03", 2);
  for (const std::uint32_t v : {2u, 1u, 0u}) putBe32(v);
  test::ScratchDir dir;
  test::writeBytes(dir / "be.ply", bytes);
  const TriangleMesh mesh = readMesh(dir / "be.ply");
  ASSERT_EQ(mesh.vertices.size(), 3u);
  EXPECT_EQ(mesh.vertices[1], Eigen::Vector3d(1.5, 0, 0));
  EXPECT_EQ(mesh.vertices[2], Eigen::Vector3d(0, -2.25, 0));
  ASSERT_EQ(mesh.triangles.size(), 1u);
  EXPECT_EQ(mesh.triangles[0], (std::array<int, 3>{2, 1, 0}));
}

TEST(MeshIo, WeldMergesExactlyTheBitIdenticalCorners) {
  std::mt19937 rng(3);
  std::uniform_int_distribution<int> pick(0, 9);
  TriangleMesh soup;
  for (int t = 0; t < 200; ++t) {
    for (int c = 0; c < 3; ++c) soup.vertices.emplace_back(pick(rng) * 0.1, pick(rng) % 3, 0.0);
    soup.triangles.push_back({3 * t, 3 * t + 1, 3 * t + 2});
  }
  std::set<std::array<double, 3>> distinct;  // independent oracle
  for (const auto& v : soup.vertices) distinct.insert({v.x(), v.y(), v.z()});
  const TriangleMesh welded = weldVertices(soup);
  EXPECT_EQ(welded.vertices.size(), distinct.size());
  ASSERT_EQ(welded.triangles.size(), soup.triangles.size());
  for (std::size_t t = 0; t < soup.triangles.size(); ++t)
    for (int c = 0; c < 3; ++c)
      EXPECT_EQ(welded.vertices[welded.triangles[t][c]], soup.vertices[soup.triangles[t][c]]);
}

}  // namespace
}  // namespace ddfcam::io
