// SPDX-License-Identifier: MIT
#include <ddfcam/io/mesh/mesh_io.h>
#include <ddfcam/io/mesh/mesh_units.h>
#include <ddfcam/length_unit.h>

#include <gtest/gtest.h>

#include <cmath>

#include "../io_test_support.h"

namespace ddfcam::io {
namespace {

ddf::TriangleMesh tetrahedronInMetres() {
  ddf::TriangleMesh mesh;
  mesh.vertices = {{0.0, 0.0, 0.0}, {0.3, 0.0, 0.0}, {0.0, 0.04, 0.0}, {0.0, 0.0, 0.125}};
  mesh.triangles = {{0, 2, 1}, {0, 1, 3}, {0, 3, 2}, {1, 2, 3}};
  return mesh;
}

TEST(MeshUnits, ScalingMultipliesEveryCoordinateByTheUnitFactor) {
  const ddf::TriangleMesh metres = tetrahedronInMetres();
  for (const ddfcam::LengthUnit unit :
       {ddfcam::LengthUnit::Millimetre, ddfcam::LengthUnit::Centimetre, ddfcam::LengthUnit::Metre,
        ddfcam::LengthUnit::Inch}) {
    const ddf::TriangleMesh mm = scaledToMm(metres, unit);
    EXPECT_EQ(mm.triangles, metres.triangles);
    for (std::size_t v = 0; v < metres.vertices.size(); ++v)
      EXPECT_EQ(mm.vertices[v], metres.vertices[v] * millimetresPer(unit));
  }
  EXPECT_DOUBLE_EQ(boundingBoxDiagonal(metres), std::sqrt(0.09 + 0.0016 + 0.015625));
  EXPECT_EQ(boundingBoxDiagonal(ddf::TriangleMesh{}), 0.0);
}

TEST(MeshUnits, FilesReadInTheirUnitComeOutInMillimetres) {
  test::ScratchDir dir;
  writeMesh(tetrahedronInMetres(), dir / "part.obj");
  const ddf::TriangleMesh mm = readMeshInUnit(dir / "part.obj", ddfcam::LengthUnit::Metre);
  ASSERT_EQ(mm.vertices.size(), 4u);
  EXPECT_EQ(mm.vertices[1], Eigen::Vector3d(300.0, 0.0, 0.0));
  EXPECT_EQ(mm.vertices[3], Eigen::Vector3d(0.0, 0.0, 125.0));
  const planning::LoadedSurface surface =
      readSurfaceFileInUnit(dir / "part.obj", ddfcam::LengthUnit::Inch);
  EXPECT_EQ(surface.name, "part.obj");
  EXPECT_EQ(surface.mesh.vertices[1], Eigen::Vector3d(0.3 * 25.4, 0.0, 0.0));
}

}  // namespace
}  // namespace ddfcam::io
