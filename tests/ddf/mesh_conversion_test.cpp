// SPDX-License-Identifier: MIT
#include <ddfcam/ddf/mesh_conversion.h>
#include <ddfcam/ddf/validation.h>
#include <ddfcam/error.h>
#include <ddfcam/log.h>

#include <gtest/gtest.h>

#include <cmath>
#include <filesystem>
#include <mutex>

#include "../support/support_triangles.h"
#include "../support/test_meshes.h"

namespace ddfcam::ddf {
namespace {

// Distance from p to triangle (a, b, c) by the region test of Ericson, Real-Time Collision
// Detection, sec. 5.1.5 (written out here as an oracle independent of the library).
double pointTriangleDistance(const Vec3& p, const Vec3& a, const Vec3& b, const Vec3& c) {
  const Vec3 ab = b - a, ac = c - a, ap = p - a;
  const double d1 = ab.dot(ap), d2 = ac.dot(ap);
  if (d1 <= 0 && d2 <= 0) return (p - a).norm();
  const Vec3 bp = p - b;
  const double d3 = ab.dot(bp), d4 = ac.dot(bp);
  if (d3 >= 0 && d4 <= d3) return (p - b).norm();
  const double vc = d1 * d4 - d3 * d2;
  if (vc <= 0 && d1 >= 0 && d3 <= 0) return (p - (a + ab * (d1 / (d1 - d3)))).norm();
  const Vec3 cp = p - c;
  const double d5 = ab.dot(cp), d6 = ac.dot(cp);
  if (d6 >= 0 && d5 <= d6) return (p - c).norm();
  const double vb = d5 * d2 - d1 * d6;
  if (vb <= 0 && d2 >= 0 && d6 <= 0) return (p - (a + ac * (d2 / (d2 - d6)))).norm();
  const double va = d3 * d6 - d5 * d4;
  if (va <= 0 && (d4 - d3) >= 0 && (d5 - d6) >= 0)
    return (p - (b + (c - b) * ((d4 - d3) / ((d4 - d3) + (d5 - d6))))).norm();
  const double denom = 1.0 / (va + vb + vc);
  return (p - (a + ab * (vb * denom) + ac * (vc * denom))).norm();
}

/// Every triangle with its own three vertices, as an STL file stores them.
TriangleMesh unwelded(const TriangleMesh& mesh) {
  TriangleMesh out;
  for (const auto& t : mesh.triangles) {
    const int base = static_cast<int>(out.vertices.size());
    for (int v : t) out.vertices.push_back(mesh.vertices[v]);
    out.triangles.push_back({base, base + 1, base + 2});
  }
  return out;
}

/// Collects warnings while alive.
class LogCapture {
 public:
  LogCapture()
      : previous_(setLogSink([this](LogLevel level, const std::string& message) {
          std::lock_guard lock(mutex_);
          if (level == LogLevel::Warning) warnings_.push_back(message);
        })) {}
  ~LogCapture() { setLogSink(previous_); }
  std::vector<std::string> warnings() {
    std::lock_guard lock(mutex_);
    return warnings_;
  }

 private:
  std::mutex mutex_;
  std::vector<std::string> warnings_;
  LogSink previous_;
};

TEST(MeshConversion, UnweldedOctahedronBecomesAValidClosedDdf) {
  const auto input = unwelded(test::supportTriangles(test::octahedronMesh(2.0)));
  const auto result = convertMeshToDdf(input);
  EXPECT_EQ(result.report.weldedVertices, 24 - 6);
  EXPECT_EQ(result.report.droppedFaces, 0);
  EXPECT_EQ(result.report.degenerateFaces, 0);
  EXPECT_EQ(result.ddf.vertexCount(), 6);
  EXPECT_EQ(result.ddf.faceCount(), 8);
  EXPECT_EQ(result.ddf.resolution(), 10);
  for (float h : result.ddf.allHeights()) EXPECT_EQ(h, 0.0f);
  for (int v = 0; v < 6; ++v)  // pseudo-normals of an octahedron are radial
    EXPECT_NEAR(result.ddf.vector(v).normalized().dot(result.ddf.position(v).normalized()), 1.0,
                1e-12);
  EXPECT_TRUE(validate(result.ddf).ok());
}

TEST(MeshConversion, DropsNonManifoldAndDegenerateTrianglesWithAWarning) {
  auto input = test::supportTriangles(test::gridMesh(3, 3));
  // A fin on the interior edge (5, 10): a third face on an edge. A triangle with a repeated
  // vertex.
  input.vertices.push_back({1.5, 1.5, 1.0});
  const int fin = static_cast<int>(input.vertices.size()) - 1;
  input.triangles.push_back({5, 10, fin});
  input.triangles.push_back({1, 1, 2});
  LogCapture capture;
  const auto result = convertMeshToDdf(input);
  EXPECT_EQ(result.report.droppedFaces, 1);
  EXPECT_EQ(result.report.degenerateFaces, 1);
  EXPECT_EQ(result.ddf.faceCount(), 18);
  EXPECT_EQ(result.ddf.vertexCount(), 16);  // the fin's apex is not kept
  ASSERT_EQ(capture.warnings().size(), 1u);
  EXPECT_NE(capture.warnings()[0].find("input triangle 18"), std::string::npos);
  EXPECT_TRUE(validate(result.ddf).ok());
}

TEST(MeshConversion, RemovesBothFacesOfABackToBackMembraneAndKeepsTheSurfaceClosed) {
  // A triangular bipyramid (two tetrahedra glued on their common face, that face removed:
  // closed, 5 vertices, 6 faces) with its equator triangle added twice, facing opposite ways:
  // a zero-thickness membrane across the inside, each equator edge then on four faces, as in
  // scanner zipper meshes. The oracle is the bipyramid itself: closed, all six faces, none
  // dropped.
  TriangleMesh input;
  const double s = std::sqrt(3.0) / 2.0;
  input.vertices = {{1, 0, 0}, {-0.5, s, 0}, {-0.5, -s, 0}, {0, 0, 1}, {0, 0, -1}};
  input.triangles = {{0, 1, 3}, {1, 2, 3}, {2, 0, 3}, {1, 0, 4}, {2, 1, 4}, {0, 2, 4}};
  input.triangles.push_back({0, 1, 2});
  input.triangles.push_back({2, 1, 0});
  const auto result = convertMeshToDdf(input);
  EXPECT_EQ(result.report.backToBackFaces, 2);
  EXPECT_EQ(result.report.duplicateFaces, 0);
  EXPECT_EQ(result.report.droppedFaces, 0);
  EXPECT_EQ(result.report.boundaryLoops, 0);
  EXPECT_EQ(result.ddf.faceCount(), 6);
  EXPECT_TRUE(validate(result.ddf).ok());
}

TEST(MeshConversion, RemovesBothFacesOfABackToBackFinOnTwoEdgesOfTheSurface) {
  // The bipyramid of the membrane test with a fin instead: the triangle of a rim vertex and
  // both apexes, twice, facing opposite ways. Two of its edges lie on the surface (two faces
  // each), the third (apex to apex) is free, as at the bunny's zipper seams. The oracle is
  // again the closed bipyramid.
  TriangleMesh input;
  const double s = std::sqrt(3.0) / 2.0;
  input.vertices = {{1, 0, 0}, {-0.5, s, 0}, {-0.5, -s, 0}, {0, 0, 1}, {0, 0, -1}};
  input.triangles = {{0, 1, 3}, {1, 2, 3}, {2, 0, 3}, {1, 0, 4}, {2, 1, 4}, {0, 2, 4}};
  input.triangles.push_back({0, 3, 4});
  input.triangles.push_back({0, 4, 3});
  const auto result = convertMeshToDdf(input);
  EXPECT_EQ(result.report.backToBackFaces, 2);
  EXPECT_EQ(result.report.droppedFaces, 0);
  EXPECT_EQ(result.report.boundaryLoops, 0);
  EXPECT_EQ(result.ddf.faceCount(), 6);
  EXPECT_TRUE(validate(result.ddf).ok());
}

TEST(MeshConversion, KeepsOneFaceOfABackToBackPairTheSurfaceNeeds) {
  // A 3 x 3 grid (18 triangles) with one of its own triangles added twice more, once facing
  // the other way and once the same way. Its edges have only one other face each, so the
  // surface needs one face of the pair: the grid comes back whole, without a hole.
  auto input = test::supportTriangles(test::gridMesh(3, 3));
  const auto t = input.triangles[7];
  input.triangles.push_back({t[0], t[2], t[1]});
  input.triangles.push_back({t[1], t[2], t[0]});
  const auto result = convertMeshToDdf(input);
  EXPECT_EQ(result.report.backToBackFaces, 0);
  EXPECT_EQ(result.report.duplicateFaces, 2);
  EXPECT_EQ(result.report.droppedFaces, 0);
  EXPECT_EQ(result.report.boundaryLoops, 1);
  EXPECT_EQ(result.ddf.faceCount(), 18);
  EXPECT_TRUE(validate(result.ddf).ok());
}

TEST(MeshConversion, RejectsBadInput) {
  TriangleMesh bad;
  bad.vertices = {{0, 0, 0}, {1, 0, 0}};
  bad.triangles = {{0, 1, 2}};
  EXPECT_THROW(convertMeshToDdf(bad), InvalidInput);
  ConversionParams params;
  params.resolution = 1;
  EXPECT_THROW(convertMeshToDdf(test::supportTriangles(test::gridMesh(1, 1)), params),
               InvalidInput);
  params.resolution = 4;
  params.progress = [](double) { return false; };
  EXPECT_THROW(convertMeshToDdf(test::supportTriangles(test::gridMesh(1, 1)), params), Cancelled);
}

TEST(MeshConversion, BunnyConvertsToAValidDdf) {
  const std::filesystem::path path =
      std::filesystem::path(DDFCAM_SHARED_DATA_DIR) / "meshes" / "libigl-bunny.off";
  if (!std::filesystem::exists(path)) GTEST_SKIP() << "shared mesh data not present";
  SupportMesh bunny;
  ASSERT_TRUE(OpenMesh::IO::read_mesh(bunny, path.string()));
  const auto input = test::supportTriangles(bunny);
  ConversionParams params;
  params.resolution = 4;
  const auto result = convertMeshToDdf(input, params);
  EXPECT_EQ(result.report.droppedFaces, 0);
  EXPECT_EQ(result.ddf.faceCount(),
            static_cast<int>(input.triangles.size()) - result.report.degenerateFaces);
  EXPECT_TRUE(result.infeasibleVertices.empty());
  EXPECT_GE(result.lengths.minH0, 1.0);
  EXPECT_EQ(result.lengths.remainingConflicts, 0);
  const auto report = validate(result.ddf);
  EXPECT_TRUE(report.ok()) << (report.issues.empty() ? "" : report.issues[0].message);
  EXPECT_GT(result.filledPoints, 0u);
  // One-sided Hausdorff distance from the represented surface to the input, brute force over
  // every input triangle for a deterministic sample of raster points.
  const auto box = input.bounds();
  const double diagonal = (box[1] - box[0]).norm();
  double worst = 0.0;
  const auto& ddf = result.ddf;
  for (int f = 0; f < ddf.faceCount(); f += 7)
    for (int k = 0; k < 4; ++k)
      for (int i = 0; i + k < 4; i += 2) {
        const Vec3 q = ddf.surfacePoint(f, i, k);
        double nearest = 1e300;
        for (const auto& t : input.triangles)
          nearest =
              std::min(nearest, pointTriangleDistance(q, input.vertices[t[0]], input.vertices[t[1]],
                                                      input.vertices[t[2]]));
        worst = std::max(worst, nearest);
      }
  RecordProperty("hausdorff_over_diagonal", std::to_string(worst / diagonal));
  EXPECT_LT(worst, 1e-6 * diagonal) << "represented surface leaves the input mesh";
}

}  // namespace
}  // namespace ddfcam::ddf
