// SPDX-License-Identifier: MIT
#include <ddfcam/io/mesh/mesh_io.h>

#include <gtest/gtest.h>

#include <filesystem>
#include <set>

namespace ddfcam::io {
namespace {

struct SharedMesh {
  const char* file;
  std::size_t vertices;   ///< V in shared/data/README.md (after welding for STL)
  std::size_t triangles;  ///< T in shared/data/README.md
};

void PrintTo(const SharedMesh& m, std::ostream* os) {
  *os << m.file;
}

class SharedMeshes : public ::testing::TestWithParam<SharedMesh> {};

TEST_P(SharedMeshes, CountsMatchTheDataReadme) {
  const std::filesystem::path root = DDFCAM_SHARED_DATA_DIR;
  const auto path = root / "meshes" / GetParam().file;
  if (!std::filesystem::exists(path)) GTEST_SKIP() << "shared data not found at " << path;
  const ddf::TriangleMesh mesh = readMesh(path);
  EXPECT_EQ(mesh.triangles.size(), GetParam().triangles);
  EXPECT_EQ(mesh.vertices.size(), GetParam().vertices);
  // Independent count of the distinct corner positions (what an STL "vertex count" means).
  std::set<std::array<double, 3>> corners;
  for (const auto& t : mesh.triangles)
    for (const int v : t) {
      ASSERT_GE(v, 0);
      ASSERT_LT(v, static_cast<int>(mesh.vertices.size()));
      const auto& p = mesh.vertices[v];
      corners.insert({p.x(), p.y(), p.z()});
    }
  EXPECT_LE(corners.size(), mesh.vertices.size());
  if (meshFormatOf(path) == MeshFormat::Stl) {
    EXPECT_EQ(corners.size(), GetParam().vertices);
  }
}

INSTANTIATE_TEST_SUITE_P(
    MeshIo, SharedMeshes,
    ::testing::Values(
        SharedMesh{"bun_zipper_res2.ply", 8171, 16301}, SharedMesh{"libigl-bunny.off", 3485, 6966},
        SharedMesh{"turbine-blade-jigsaw.stl", 6655, 13306}, SharedMesh{"fandisk.obj", 6475, 12946},
        SharedMesh{"featuretype.stl", 2010, 3476}, SharedMesh{"1002_tray_bottom.stl", 2216, 4520},
        SharedMesh{"springback-deepdrawn/target_AF_bs.stl", 20790, 41010},
        SharedMesh{"springback-deepdrawn/mesh_ausgerichtet1.stl", 20797, 41013}),
    [](const auto& info) {
      std::string name = std::filesystem::path(info.param.file).stem().string();
      for (char& c : name)
        if (!std::isalnum(static_cast<unsigned char>(c))) c = '_';
      return name;
    });

}  // namespace
}  // namespace ddfcam::io
