// SPDX-License-Identifier: MIT
// Tests of the raster surface mesh and the support mesh against analytic surfaces.
#include <ddfcam/ddf/raster_mesh.h>

#include <gtest/gtest.h>

#include <cmath>
#include <limits>

#include "surface_fixtures.h"

namespace ddfcam::ddf {
namespace {

TEST(RasterMesh, CountsFollowTheRaster) {
  for (int m : {2, 3, 7}) {
    const auto field = test::sphereDdf(m);
    const RasterMesh rm = extractRasterMesh(field);
    EXPECT_EQ(rm.mesh.vertices.size(), field.topology().pointCount()) << "m " << m;
    EXPECT_EQ(rm.mesh.triangles.size(), static_cast<std::size_t>(8 * (m - 1) * (m - 1)));
    ASSERT_EQ(rm.vertexPoint.size(), rm.mesh.vertices.size());
    for (std::size_t v = 0; v < rm.vertexPoint.size(); ++v) EXPECT_EQ(rm.vertexPoint[v], v);
  }
}

// The sphere DDF puts every q on the unit sphere: the raster mesh is an inscribed closed
// polyhedron whose volume grows towards 4/3 pi with m.
TEST(RasterMesh, SphereDdfGivesInscribedClosedPolyhedron) {
  double previous = 0.0;
  for (int m : {3, 6, 11, 21}) {
    const RasterMesh rm = extractRasterMesh(test::sphereDdf(m));
    for (const auto& v : rm.mesh.vertices) ASSERT_NEAR(v.norm(), 1.0, 1e-6);
    EXPECT_TRUE(test::isClosedManifold(rm.mesh, 2)) << "m " << m;
    const double volume = rm.mesh.signedVolume();
    EXPECT_GT(volume, previous);
    EXPECT_LT(volume, 4.0 / 3.0 * M_PI);
    previous = volume;
  }
  EXPECT_NEAR(previous, 4.0 / 3.0 * M_PI, 0.05);
}

// Copies that disagree are welded onto the copy of the lowest-index face.
TEST(RasterMesh, SharedPointsTakeTheLowestFaceCopy) {
  const auto field = test::bumpyOctahedronDdf(6, 1e-3);
  const RasterMesh rm = extractRasterMesh(field);
  EXPECT_TRUE(test::isClosedManifold(rm.mesh, 2));
  const auto& topo = field.topology();
  for (std::size_t v = 0; v < rm.vertexPoint.size(); ++v) {
    PointCopy lowest{std::numeric_limits<int>::max(), 0};
    topo.forEachCopy(rm.vertexPoint[v], [&](PointCopy c) {
      if (c.face < lowest.face) lowest = c;
    });
    const RasterCoord rc = topo.coord(lowest);
    EXPECT_EQ(rm.mesh.vertices[v], field.surfacePoint(lowest.face, rc.i, rc.k)) << "vertex " << v;
  }
}

// A flat field over a planar grid: every triangle faces +z like its support face, and the
// triangles of a face tile it exactly.
TEST(RasterMesh, TrianglesAreOrientedLikeAndTileTheirSupportFace) {
  const auto mesh = test::gridMesh(3, 2, 1.5, 1.0);
  DisplacementField field(mesh, test::constantVectors(mesh, {0, 0, 0.2}), 5, 0.5f);
  const RasterMesh rm = extractRasterMesh(field);
  const std::size_t perFace = 16;
  for (int f = 0; f < field.faceCount(); ++f) {
    double area = 0.0;
    for (std::size_t t = f * perFace; t < (f + 1) * perFace; ++t) {
      const auto& tri = rm.mesh.triangles[t];
      const Vec3 normal = (rm.mesh.vertices[tri[1]] - rm.mesh.vertices[tri[0]])
                              .cross(rm.mesh.vertices[tri[2]] - rm.mesh.vertices[tri[0]]);
      EXPECT_GT(normal.z(), 0.0) << "face " << f << " triangle " << t;
      area += 0.5 * normal.norm();
      for (int c : tri) EXPECT_DOUBLE_EQ(rm.mesh.vertices[c].z(), 0.1);
    }
    EXPECT_NEAR(area, 0.75, 1e-12) << "face " << f;
  }
}

TEST(RasterMesh, EmptyFieldGivesEmptyMesh) {
  const RasterMesh rm = extractRasterMesh(DisplacementField{});
  EXPECT_TRUE(rm.mesh.vertices.empty());
  EXPECT_TRUE(rm.mesh.triangles.empty());
  EXPECT_TRUE(extractSupportMesh(DisplacementField{}).triangles.empty());
}

TEST(RasterMesh, SupportMeshKeepsVerticesAndFaces) {
  const auto mesh = test::octahedronMesh(2.0);
  const DisplacementField field(mesh, test::radialVectors(mesh), 4);
  const TriangleMesh support = extractSupportMesh(field);
  ASSERT_EQ(support.vertices.size(), 6u);
  ASSERT_EQ(support.triangles.size(), 8u);
  for (int v = 0; v < 6; ++v)
    EXPECT_EQ(support.vertices[v], toEigen(mesh.point(mesh.vertex_handle(v))));
  EXPECT_TRUE(test::isClosedManifold(support, 2));
  EXPECT_NEAR(support.signedVolume(), 4.0 / 3.0 * 8.0, 1e-12);  // octahedron r = 2
}

}  // namespace
}  // namespace ddfcam::ddf
