// SPDX-License-Identifier: MIT
#include <ddfcam/ddf/mesh_conversion.h>
#include <ddfcam/ddf/validation.h>
#include <ddfcam/error.h>
#include <ddfcam/log.h>

#include <gtest/gtest.h>

#include <filesystem>
#include <mutex>

#include "../support/test_meshes.h"

namespace ddfcam::ddf {
namespace {

TriangleMesh toTriangleMesh(const SupportMesh& mesh) {
  TriangleMesh out;
  for (const auto vh : mesh.vertices()) out.vertices.push_back(toEigen(mesh.point(vh)));
  for (const auto fh : mesh.faces()) {
    std::array<int, 3> t;
    int k = 0;
    for (const auto vh : mesh.fv_range(fh)) t[k++] = vh.idx();
    out.triangles.push_back(t);
  }
  return out;
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
  const auto input = unwelded(toTriangleMesh(test::octahedronMesh(2.0)));
  const auto result = convertMeshToDdf(input);
  EXPECT_EQ(result.weldedVertices, 24 - 6);
  EXPECT_EQ(result.droppedFaces, 0);
  EXPECT_EQ(result.degenerateFaces, 0);
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
  auto input = toTriangleMesh(test::gridMesh(3, 3));
  // A fin on the interior edge (5, 10): a third face on an edge. A triangle with a repeated
  // vertex.
  input.vertices.push_back({1.5, 1.5, 1.0});
  const int fin = static_cast<int>(input.vertices.size()) - 1;
  input.triangles.push_back({5, 10, fin});
  input.triangles.push_back({1, 1, 2});
  LogCapture capture;
  const auto result = convertMeshToDdf(input);
  EXPECT_EQ(result.droppedFaces, 1);
  EXPECT_EQ(result.degenerateFaces, 1);
  EXPECT_EQ(result.ddf.faceCount(), 18);
  EXPECT_EQ(result.ddf.vertexCount(), 16);  // the fin's apex is not kept
  ASSERT_EQ(capture.warnings().size(), 1u);
  EXPECT_NE(capture.warnings()[0].find("input triangle 18"), std::string::npos);
  EXPECT_TRUE(validate(result.ddf).ok());
}

TEST(MeshConversion, RejectsBadInput) {
  TriangleMesh bad;
  bad.vertices = {{0, 0, 0}, {1, 0, 0}};
  bad.triangles = {{0, 1, 2}};
  EXPECT_THROW(convertMeshToDdf(bad), InvalidInput);
  ConversionParams params;
  params.resolution = 1;
  EXPECT_THROW(convertMeshToDdf(toTriangleMesh(test::gridMesh(1, 1)), params), InvalidInput);
  params.resolution = 4;
  params.progress = [](double) { return false; };
  EXPECT_THROW(convertMeshToDdf(toTriangleMesh(test::gridMesh(1, 1)), params), Cancelled);
}

TEST(MeshConversion, BunnyConvertsToAValidDdf) {
  const std::filesystem::path path = "/work/shared/data/meshes/libigl-bunny.off";
  if (!std::filesystem::exists(path)) GTEST_SKIP() << "shared mesh data not present";
  SupportMesh bunny;
  ASSERT_TRUE(OpenMesh::IO::read_mesh(bunny, path.string()));
  const auto input = toTriangleMesh(bunny);
  ConversionParams params;
  params.resolution = 4;
  const auto result = convertMeshToDdf(input, params);
  EXPECT_EQ(result.droppedFaces, 0);
  EXPECT_EQ(result.ddf.faceCount(),
            static_cast<int>(input.triangles.size()) - result.degenerateFaces);
  EXPECT_TRUE(result.infeasibleVertices.empty());
  EXPECT_GE(result.lengths.minH0, 1.0);
  EXPECT_EQ(result.lengths.remainingConflicts, 0);
  const auto report = validate(result.ddf);
  EXPECT_TRUE(report.ok()) << (report.issues.empty() ? "" : report.issues[0].message);
}

}  // namespace
}  // namespace ddfcam::ddf
