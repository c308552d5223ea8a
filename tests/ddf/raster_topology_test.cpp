// SPDX-License-Identifier: MIT
#include <ddfcam/ddf/raster_topology.h>

#include <gtest/gtest.h>

#include <set>

#include "../support/test_meshes.h"

namespace ddfcam::ddf {
namespace {

// Every stored copy maps to an id, ids are dense, and forEachCopy inverts id().
void checkNumbering(const SupportMesh& mesh, int m) {
  const RasterTopology topo(mesh, m);
  const Raster& r = topo.raster();
  std::vector<int> copies(topo.pointCount(), 0);
  for (int f = 0; f < static_cast<int>(mesh.n_faces()); ++f)
    for (int k = 0; k <= r.steps(); ++k)
      for (int i = 0; i < r.rowLength(k); ++i) {
        const PointId p = topo.id(f, i, k);
        ASSERT_LT(p, topo.pointCount());
        ++copies[p];
        bool found = false;
        topo.forEachCopy(p, [&](PointCopy c) {
          if (c.face == f && c.local == r.index(i, k)) found = true;
        });
        EXPECT_TRUE(found) << "face " << f << " point (" << i << "," << k << ")";
      }
  for (std::size_t p = 0; p < copies.size(); ++p) {
    int expected = 0;
    topo.forEachCopy(static_cast<PointId>(p), [&](PointCopy) { ++expected; });
    EXPECT_EQ(copies[p], expected) << "point " << p;
    EXPECT_GT(copies[p], 0) << "point " << p << " has no copy";
  }
}

TEST(RasterTopology, NumberingIsDenseAndInvertibleOnGrid) {
  for (int m : {2, 3, 4, 7}) checkNumbering(test::gridMesh(3, 2), m);
}

TEST(RasterTopology, NumberingIsDenseAndInvertibleOnClosedMesh) {
  for (int m : {2, 3, 5, 9}) checkNumbering(test::octahedronMesh(), m);
}

TEST(RasterTopology, PointCountMatchesEulerCounting) {
  const auto mesh = test::octahedronMesh();
  const int m = 6, n = m - 1;
  const RasterTopology topo(mesh, m);
  // V + E (n - 1) + F (n - 1)(n - 2) / 2 for V = 6, E = 12, F = 8.
  EXPECT_EQ(topo.pointCount(), 6u + 12u * (n - 1) + 8u * (n - 1) * (n - 2) / 2);
}

TEST(RasterTopology, NeighbourhoodsCrossEdgesAndVertices) {
  const auto mesh = test::octahedronMesh();
  const RasterTopology topo(mesh, 5);
  std::vector<PointId> nb;
  for (std::size_t p = 0; p < topo.pointCount(); ++p) {
    topo.neighbors(static_cast<PointId>(p), nb);
    // On a closed mesh every edge and interior point has 6 lattice neighbours; a vertex point
    // has as many as its valence (4 on the octahedron).
    const std::size_t expected = p < mesh.n_vertices() ? 4u : 6u;
    EXPECT_EQ(nb.size(), expected) << "point " << p;
    // Neighbourhood is symmetric.
    std::vector<PointId> back;
    for (PointId q : nb) {
      topo.neighbors(q, back);
      EXPECT_TRUE(std::find(back.begin(), back.end(), p) != back.end());
    }
  }
}

TEST(RasterTopology, NeighboursAreGeometricallyAdjacent) {
  // On the unit grid with m = 5 every neighbour is one raster step (0.25 or 0.25 sqrt 2) away.
  const auto mesh = test::gridMesh(2, 2);
  const DisplacementField ddf(mesh, test::constantVectors(mesh), 5);
  const RasterTopology& topo = ddf.topology();
  std::vector<Vec3> position(topo.pointCount());
  for (int f = 0; f < ddf.faceCount(); ++f)
    for (int k = 0; k < 5; ++k)
      for (int i = 0; i < 5 - k; ++i) position[topo.id(f, i, k)] = ddf.surfacePoint(f, i, k);
  std::vector<PointId> nb;
  for (std::size_t p = 0; p < topo.pointCount(); ++p) {
    topo.neighbors(static_cast<PointId>(p), nb);
    for (PointId q : nb) {
      const double d = (position[p] - position[q]).norm();
      EXPECT_TRUE(std::abs(d - 0.25) < 1e-12 || std::abs(d - 0.25 * std::sqrt(2.0)) < 1e-12)
          << p << " -> " << q << " at " << d;
    }
  }
}

}  // namespace
}  // namespace ddfcam::ddf
