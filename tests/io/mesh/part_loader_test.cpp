// SPDX-License-Identifier: MIT
#include <ddfcam/error.h>
#include <ddfcam/io/mesh/ddf_file.h>
#include <ddfcam/io/mesh/part_loader.h>

#include <gmock/gmock.h>
#include <gtest/gtest.h>

#include "../../support/test_meshes.h"
#include "../io_test_support.h"

namespace ddfcam::io {
namespace {

using ::testing::HasSubstr;
using ::testing::StartsWith;

std::filesystem::path dataFile(const std::string& name) {
  return std::filesystem::path(DDFCAM_TEST_DATA_DIR) / name;
}

TEST(PartLoader, DdfFilesAreReadAsTheyAre) {
  test::ScratchDir dir;
  const auto mesh = test::octahedronMesh();
  ddf::DisplacementField field(mesh, test::radialVectors(mesh, 0.25), 4, 0.5f);
  writeDdf(field, dir / "part.DDF");
  LoadPartReport report;
  report.converted = true;
  const auto loaded = loadPart(dir / "part.DDF", {}, &report);
  EXPECT_FALSE(report.converted);
  EXPECT_EQ(encodeDdf(loaded), encodeDdf(field));
}

TEST(PartLoader, MeshFilesBecomeTheSupportWithZeroHeights) {
  LoadPartParams params;
  params.conversion.resolution = 4;
  std::vector<double> fractions;
  params.progress = [&](double f) {
    fractions.push_back(f);
    return true;
  };
  LoadPartReport report;
  const auto field = loadPart(dataFile("bowl_patch.off"), params, &report);
  EXPECT_TRUE(report.converted);
  EXPECT_EQ(report.meshVertices, 49);
  EXPECT_EQ(report.meshTriangles, 72);
  EXPECT_EQ(field.faceCount(), 72);
  EXPECT_EQ(field.vertexCount(), 49);
  EXPECT_EQ(field.resolution(), 4);
  // Heights are filled from the mesh itself, which is the support: zero up to rounding.
  for (const float h : field.allHeights()) EXPECT_NEAR(h, 0.0f, 1e-6f);
  // Vertex positions come straight from the file: z = 0.02 ((x-5)^2 + (y-5)^2) to 6 decimals.
  for (int v = 0; v < field.vertexCount(); ++v) {
    const ddf::Vec3& p = field.position(v);
    EXPECT_NEAR(p.z(), 0.02 * ((p.x() - 5) * (p.x() - 5) + (p.y() - 5) * (p.y() - 5)), 2e-6);
  }
  ASSERT_FALSE(fractions.empty());
  EXPECT_EQ(fractions.front(), 0.0);
  EXPECT_EQ(fractions.back(), 1.0);
  EXPECT_TRUE(std::is_sorted(fractions.begin(), fractions.end()));
}

TEST(PartLoader, NonManifoldMeshesLoseOnlyTheRejectedFaces) {
  test::ScratchDir dir;
  // Three triangles on edge 0-1: the third repeats the first one's edge direction.
  test::writeBytes(dir / "fin.obj",
                   "v 0 0 0\nv 1 0 0\nv 0 1 0\nv 0 -1 0\nv 0.5 0 1\nf 1 2 3\nf 2 1 4\nf 1 2 5\n");
  LoadPartReport report;
  const auto field = loadPart(dir / "fin.obj", {}, &report);
  EXPECT_EQ(report.meshTriangles, 3);
  EXPECT_EQ(report.conversion.droppedFaces, 1);
  EXPECT_EQ(field.faceCount(), 2);
}

TEST(PartLoader, ErrorsCarryTheFileAndTheCause) {
  test::ScratchDir dir;
  const auto missing = dir / "absent.ply";
  const std::string message = test::ioErrorMessage([&] { loadPart(missing); });
  EXPECT_THAT(message, StartsWith("loading " + missing.string() + "\n"));
  EXPECT_THAT(message, HasSubstr("does not exist"));
  EXPECT_THAT(test::ioErrorMessage([&] { loadPart(dir / "part.sat"); }),
              HasSubstr("expected .ddf, .stl, .obj, .ply, .off, .step, .stp, .iges or .igs"));
  test::writeBytes(dir / "bad.ddf", "not a ddf");
  EXPECT_THAT(test::ioErrorMessage([&] { loadPart(dir / "bad.ddf"); }), HasSubstr("wrong magic"));
}

TEST(PartLoader, CancellationIsNotWrapped) {
  LoadPartParams params;
  params.progress = [](double f) { return f < 0.5; };
  EXPECT_THROW(loadPart(dataFile("bowl_patch.off"), params), Cancelled);
}

}  // namespace
}  // namespace ddfcam::io
