// SPDX-License-Identifier: MIT
// The live display's triangulation on a real part: the turbine blade (in mm, the input mesh as
// support, m = 10) cut by boxes, triangulated incrementally within delta = 0.01 mm: every raster
// point within delta of its face's triangles (brute force), no cracks, and at least 10x fewer
// triangles than the raster mesh (label data; skips without the shared data).
#include <ddfcam/ddf/crust_hash.h>
#include <ddfcam/ddf/depth_buffer.h>
#include <ddfcam/ddf/incremental_triangulation.h>
#include <ddfcam/ddf/mesh_conversion.h>
#include <ddfcam/ddf/raster_mesh.h>
#include <ddfcam/ddf/support_mesh.h>

#include <gtest/gtest.h>
#include <OpenMesh/Core/IO/MeshIO.hh>

#include <filesystem>
#include <iostream>
#include <random>
#include <set>
#include <utility>

#include "../support/support_triangles.h"
#include "surface_fixtures.h"

namespace ddfcam::ddf {
namespace {

TEST(IncrementalTriangulationShared, TurbineBladeWithinDeltaWithTenTimesFewerTriangles) {
  const auto path =
      std::filesystem::path(DDFCAM_SHARED_DATA_DIR) / "meshes" / "turbine-blade-jigsaw.stl";
  SupportMesh read;
  if (!std::filesystem::exists(path) || !OpenMesh::IO::read_mesh(read, path.string()))
    GTEST_SKIP() << "shared mesh data not present";
  const TriangleMesh blade = test::supportTriangles(read, 1000.0);  // metres
  ConversionParams params;
  params.resolution = 10;
  DisplacementField field = convertMeshToDdf(blade, params).ddf;
  const CrustHash hash(field);
  constexpr double kDeltaMm = 0.01;
  IncrementalTriangulation live(field, kDeltaMm);
  // Boxes 3 mm across pressed 0.4 mm into the surface at random support faces.
  std::mt19937 rng(17);
  std::uniform_int_distribution<int> anyFace(0, field.faceCount() - 1);
  std::size_t touched = 0;
  for (int cut = 0; cut < 40; ++cut) {
    const int f = anyFace(rng);
    const Vec3 p = field.surfacePoint(f, 3, 3);
    const Vec3 v = field.vector(field.faceVertices(f)[0]).normalized();
    const Vec3 centre = p + (1.5 - 0.4) * v;
    const CutStats stats = cutByMesh(field, hash,
                                     test::boxMesh(centre - Vec3::Constant(1.5),
                                                   centre + Vec3::Constant(1.5)),
                                     Eigen::Isometry3d::Identity());
    live.update(stats.touchedFaces);
    touched += stats.touchedFaces.size();
  }
  ASSERT_GT(touched, 400u);  // the boxes reached the surface
  double worst = 0.0;
  EXPECT_TRUE(test::withinFaceBounds(field, live,
                                     std::vector<float>(field.faceCount(), kDeltaMm), &worst));
  const AdaptiveTriangulation snap = live.snapshot();
  const std::size_t raster = static_cast<std::size_t>(field.faceCount()) * 81;
  std::cout << "blade (" << field.faceCount() << " faces, m = 10): " << snap.mesh.triangles.size()
            << " triangles within " << kDeltaMm << " mm against " << raster
            << " of the raster mesh (" << static_cast<double>(raster) / snap.mesh.triangles.size()
            << "x fewer); brute-force largest distance " << worst << " mm\n";
  EXPECT_LE(10 * snap.mesh.triangles.size(), raster);
  EXPECT_LE(worst, kDeltaMm + 1e-9);
  // No cracks and no T-vertices: closed and manifold with the support's Euler characteristic
  // (every edge in exactly two triangles, oppositely oriented).
  const TriangleMesh support = extractSupportMesh(field);
  std::set<std::pair<int, int>> edges;
  for (const auto& t : support.triangles)
    for (int c = 0; c < 3; ++c) edges.insert(std::minmax(t[c], t[(c + 1) % 3]));
  const int euler = static_cast<int>(support.vertices.size()) - static_cast<int>(edges.size()) +
                    static_cast<int>(support.triangles.size());
  ASSERT_TRUE(test::isClosedManifold(support, euler));
  EXPECT_TRUE(test::isClosedManifold(snap.mesh, euler));
}

}  // namespace
}  // namespace ddfcam::ddf
