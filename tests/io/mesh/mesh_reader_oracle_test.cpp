// SPDX-License-Identifier: MIT
// Mesh readers against files written by other programs (VTK, OpenMesh) or by hand, with known
// facts.
#include <ddfcam/io/mesh/mesh_io.h>

#include <gtest/gtest.h>

#include <cctype>
#include <cmath>
#include <filesystem>
#include <string>

namespace ddfcam::io {
namespace {

/// Facts of one file in tests/data/mesh_oracles (see its README for where they come from).
struct OracleFacts {
  const char* file;
  int vertices;        ///< vertices in the file
  int faces;           ///< faces (STL: facets) in the file
  int triangles;       ///< triangles once each n-gon is split into n - 2
  int weldedVertices;  ///< STL only: distinct corners (-1 for other formats)
  Eigen::Vector3d min;
  Eigen::Vector3d max;
  double areaMm2;
  double volumeMm3;
  double relTolerance;  ///< for area and volume
};

/// Area and volume of files holding float coordinates: VTK and OpenMesh computed the facts
/// from the same floats, printed to 9 digits, so a few float epsilons cover every rounding.
constexpr double kFloatRel = 1e-6;
/// Hand-written files hold short decimals, read as doubles; the facts are exact.
constexpr double kExactRel = 1e-12;
constexpr double kBoundsMm = 1e-6;

// Numbers printed by scripts/make-mesh-oracles.cpp (VTK 9.1.0, OpenMesh 9.0): counts of the data
// handed to the writer, the rest from the file read back by the writing program's own reader.
// clang-format off
const OracleFacts kWritten[] = {
    {"sphere_vtk_binary.stl", 34, 64, 64, 34,
     {-2.98640728, -5.98640728, -3.47808766}, {4.98640728, 1.9864074, 4.47808743},
     181.515801, 218.311379, kFloatRel},
    {"sphere_vtk_binary_le.ply", 34, 64, 64, -1,
     {-2.98640728, -5.98640728, -3.47808766}, {4.98640728, 1.9864074, 4.47808743},
     181.515801, 218.311379, kFloatRel},
    {"sphere_vtk.obj", 34, 64, 64, -1,
     {-2.98640728, -5.98640728, -3.47808766}, {4.98640728, 1.9864074, 4.47808743},
     181.515801, 218.311379, kFloatRel},
    {"cube_vtk_ascii.stl", 24, 12, 12, 8,
     {-1.43523192, -1.62915313, -3.49627042}, {2.43523192, 3.62915325, 1.4962703},
     52.0000018, 24.0000012, kFloatRel},
    {"cube_vtk_binary_be.ply", 24, 6, 12, -1,
     {-1.43523192, -1.62915313, -3.49627042}, {2.43523192, 3.62915325, 1.4962703},
     52.0000018, 24.0000012, kFloatRel},
    {"cylinder_vtk.obj", 32, 10, 28, -1,
     {-3.95442319, -2.45442319, -0.5}, {1.95442331, 3.45442319, 4.5},
     142.755706, 127.279213, kFloatRel},
    {"cylinder_vtk_ascii.ply", 32, 10, 28, -1,
     {-3.95442319, -2.45442319, -0.5}, {1.95442331, 3.45442319, 4.5},
     142.755706, 127.279213, kFloatRel},
    {"icosahedron_openmesh.off", 12, 20, 20, -1,
     {-2.17705107, -2.92705107, -1.42705107}, {2.67705107, 1.92705107, 3.42705107},
     77.9422903, 58.9057692, kFloatRel},
    {"icosahedron_openmesh.obj", 12, 20, 20, -1,
     {-2.17705107, -2.92705107, -1.42705107}, {2.67705107, 1.92705107, 3.42705107},
     77.9422903, 58.9057692, kFloatRel},
    {"icosahedron_openmesh_binary_be.ply", 12, 20, 20, -1,
     {-2.17705107, -2.92705107, -1.42705107}, {2.67705107, 1.92705107, 3.42705107},
     77.9422903, 58.9057692, kFloatRel},
    {"icosahedron_openmesh_ascii.stl", 12, 20, 20, 12,
     {-2.17705107, -2.92705107, -1.42705107}, {2.67705107, 1.92705107, 3.42705107},
     77.9422903, 58.9057692, kFloatRel},
};

// Hand-computed (README): box 1 x 2 x 3 (area 22, volume 6) plus one unused vertex; square
// pyramid, base 2 x 2, height 3 (area 4 + 4 sqrt(10), volume 4); corner tetrahedron, legs
// 2, 3, 4 (area 13 + sqrt(61), volume 4); house, cube of edge 2 with a roof of height 1
// (area 22 + 4 sqrt(2), volume 10).
const OracleFacts kHandWritten[] = {
    {"hand_box.obj", 9, 6, 12, -1, {0, 0, 0}, {1, 2, 3}, 22.0, 6.0, kExactRel},
    {"hand_pyramid.ply", 5, 5, 6, -1, {0, 0, 0}, {2, 2, 3},
     4.0 + 4.0 * std::sqrt(10.0), 4.0, kExactRel},
    {"hand_tetra.stl", 12, 4, 4, 4, {-1.5, 0.25, 0.001}, {0.5, 3.25, 4.001},
     13.0 + std::sqrt(61.0), 4.0, kExactRel},
    {"hand_house.off", 10, 7, 16, -1, {0, 0, 0}, {2, 2, 3},
     22.0 + 4.0 * std::sqrt(2.0), 10.0, kExactRel},
};
// clang-format on

struct Measures {
  Eigen::Vector3d min = Eigen::Vector3d::Constant(INFINITY);
  Eigen::Vector3d max = Eigen::Vector3d::Constant(-INFINITY);
  double areaMm2 = 0.0;
  double signedVolumeMm3 = 0.0;
};

/// Bounds of the triangles' corners (as VTK bounds a poly data), area and divergence volume.
Measures measure(const ddf::TriangleMesh& mesh) {
  Measures m;
  for (const auto& t : mesh.triangles) {
    const Eigen::Vector3d& a = mesh.vertices.at(t[0]);
    const Eigen::Vector3d& b = mesh.vertices.at(t[1]);
    const Eigen::Vector3d& c = mesh.vertices.at(t[2]);
    for (const Eigen::Vector3d* p : {&a, &b, &c}) {
      m.min = m.min.cwiseMin(*p);
      m.max = m.max.cwiseMax(*p);
    }
    m.areaMm2 += 0.5 * (b - a).cross(c - a).norm();
    m.signedVolumeMm3 += a.dot(b.cross(c)) / 6.0;
  }
  return m;
}

class MeshReaderOracle : public ::testing::TestWithParam<OracleFacts> {};

TEST_P(MeshReaderOracle, MatchesTheRecordedFacts) {
  const OracleFacts& facts = GetParam();
  const auto path = std::filesystem::path(DDFCAM_TEST_DATA_DIR) / "mesh_oracles" / facts.file;
  const ddf::TriangleMesh mesh = readMesh(path);
  // STL corners are welded by the reader (bit-identical coordinates); other formats keep the
  // file's vertex list as it is.
  const int expectedVertices = facts.weldedVertices >= 0 ? facts.weldedVertices : facts.vertices;
  EXPECT_EQ(static_cast<int>(mesh.vertices.size()), expectedVertices);
  ASSERT_EQ(static_cast<int>(mesh.triangles.size()), facts.triangles);
  const Measures m = measure(mesh);
  for (int i = 0; i < 3; ++i) {
    EXPECT_NEAR(m.min[i], facts.min[i], kBoundsMm) << "min " << i;
    EXPECT_NEAR(m.max[i], facts.max[i], kBoundsMm) << "max " << i;
  }
  EXPECT_NEAR(m.areaMm2, facts.areaMm2, facts.relTolerance * facts.areaMm2);
  // Positive: every file is closed and oriented outwards, and the readers keep corner order.
  EXPECT_NEAR(m.signedVolumeMm3, facts.volumeMm3, facts.relTolerance * facts.volumeMm3);
}

std::string testName(const ::testing::TestParamInfo<OracleFacts>& info) {
  std::string name = info.param.file;
  for (char& c : name)
    if (!std::isalnum(static_cast<unsigned char>(c))) c = '_';
  return name;
}

INSTANTIATE_TEST_SUITE_P(WrittenByVtkOrOpenMesh, MeshReaderOracle, ::testing::ValuesIn(kWritten),
                         testName);
INSTANTIATE_TEST_SUITE_P(HandWritten, MeshReaderOracle, ::testing::ValuesIn(kHandWritten),
                         testName);

/// Analytic values of the generator's shapes, which the written facts must also meet (float
/// coordinates, so to kFloatRel): the box 2 x 3 x 4, the octagonal prism r = 3, h = 5 and
/// the icosahedron of edge 3.
TEST(MeshReaderOracle, WrittenShapesMeetTheirAnalyticValues) {
  const double octagonMm2 = 2.0 * std::sqrt(2.0) * 9.0;
  const double sideMm = 6.0 * std::sin(M_PI / 8.0);
  const struct {
    const char* file;
    double areaMm2;
    double volumeMm3;
  } shapes[] = {
      {"cube_vtk_ascii.stl", 52.0, 24.0},
      {"cube_vtk_binary_be.ply", 52.0, 24.0},
      {"cylinder_vtk.obj", 2.0 * octagonMm2 + 8.0 * sideMm * 5.0, octagonMm2 * 5.0},
      {"cylinder_vtk_ascii.ply", 2.0 * octagonMm2 + 8.0 * sideMm * 5.0, octagonMm2 * 5.0},
      {"icosahedron_openmesh.off", 5.0 * std::sqrt(3.0) * 9.0,
       5.0 * (3.0 + std::sqrt(5.0)) / 12.0 * 27.0},
      {"icosahedron_openmesh_binary_be.ply", 5.0 * std::sqrt(3.0) * 9.0,
       5.0 * (3.0 + std::sqrt(5.0)) / 12.0 * 27.0},
  };
  for (const auto& shape : shapes) {
    const Measures m = measure(
        readMesh(std::filesystem::path(DDFCAM_TEST_DATA_DIR) / "mesh_oracles" / shape.file));
    EXPECT_NEAR(m.areaMm2, shape.areaMm2, kFloatRel * shape.areaMm2) << shape.file;
    EXPECT_NEAR(m.signedVolumeMm3, shape.volumeMm3, kFloatRel * shape.volumeMm3) << shape.file;
  }
}

}  // namespace
}  // namespace ddfcam::io
