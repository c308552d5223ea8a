// SPDX-License-Identifier: MIT
#include <ddfcam/error.h>
#include <ddfcam/io/mesh/mesh_io.h>

#include <gmock/gmock.h>
#include <gtest/gtest.h>

#include <random>

#include "../io_test_support.h"

namespace ddfcam::io {
namespace {

using ::testing::HasSubstr;

std::string readError(const std::filesystem::path& path) {
  return test::ioErrorMessage([&] { readMesh(path); });
}

TEST(MeshIoErrors, MissingFileAndUnknownExtension) {
  test::ScratchDir dir;
  const std::string missing = readError(dir / "nothing.stl");
  EXPECT_THAT(missing, HasSubstr("nothing.stl"));
  EXPECT_THAT(missing, HasSubstr("does not exist"));
  test::writeBytes(dir / "mesh.xyz", "1 2 3\n");
  EXPECT_THAT(readError(dir / "mesh.xyz"), HasSubstr("unknown mesh file extension '.xyz'"));
  ddf::TriangleMesh one{{{0, 0, 0}, {1, 0, 0}, {0, 1, 0}}, {{0, 1, 2}}};
  EXPECT_THROW(writeMesh(one, dir / "mesh.xyz"), IoError);
  EXPECT_THROW(writeMesh(one, dir / "no_such_dir" / "mesh.obj"), IoError);
  one.triangles.push_back({0, 1, 3});
  EXPECT_THROW(writeMesh(one, dir / "mesh.obj"), InvalidInput);
}

TEST(MeshIoErrors, EmptyFilesOfEveryFormat) {
  test::ScratchDir dir;
  for (const char* ext : {"stl", "obj", "ply", "off"}) {
    const auto path = dir / (std::string("empty.") + ext);
    test::writeBytes(path, "");
    const std::string message = readError(path);
    EXPECT_THAT(message, HasSubstr(path.string()));
    EXPECT_THAT(message, HasSubstr("empty"));
  }
}

TEST(MeshIoErrors, GarbageOfEveryFormatNamesTheFile) {
  test::ScratchDir dir;
  std::mt19937 rng(5);
  for (int size : {1, 50, 83, 84, 200, 5000}) {
    std::string garbage(size, '\0');
    for (char& c : garbage) c = static_cast<char>(rng());
    for (const char* ext : {"stl", "obj", "ply", "off"}) {
      const auto path = dir / ("garbage" + std::to_string(size) + "." + ext);
      test::writeBytes(path, garbage);
      EXPECT_THAT(readError(path), HasSubstr(path.string())) << ext << " " << size;
    }
  }
}

TEST(MeshIoErrors, TextErrorsNameTheLine) {
  test::ScratchDir dir;
  test::writeBytes(dir / "bad.obj", "v 0 0 0\nv 1 0 0\nv 0 1 zero\nf 1 2 3\n");
  EXPECT_THAT(readError(dir / "bad.obj"), HasSubstr("bad.obj:3: expected a number, found 'zero'"));
  test::writeBytes(dir / "range.obj", "v 0 0 0\nv 1 0 0\nv 0 1 0\nf 1 2 4\n");
  EXPECT_THAT(readError(dir / "range.obj"), HasSubstr("range.obj:4: face refers to vertex 4"));
  test::writeBytes(dir / "short.off", "OFF\n3 1 0\n0 0 0\n1 0 0\n");
  EXPECT_THAT(readError(dir / "short.off"), HasSubstr("file ends before vertex 2"));
  test::writeBytes(dir / "face.off", "OFF\n3 1 0\n0 0 0\n1 0 0\n0 1 0\n3 0 1 7\n");
  EXPECT_THAT(readError(dir / "face.off"), HasSubstr("face.off:6: face 0 refers to vertex 7 of 3"));
  test::writeBytes(dir / "facet.stl",
                   "solid s\nfacet normal 0 0 1\nouter loop\nvertex 0 0 0\nvertex 1 0 0\n"
                   "endloop\nendfacet\nendsolid\n");
  EXPECT_THAT(readError(dir / "facet.stl"), HasSubstr("facet.stl:7: facet ends with 2 vertices"));
  test::writeBytes(dir / "bad.ply",
                   "ply\nformat ascii 1.0\nelement vertex 3\nproperty float x\nproperty float y\n"
                   "property float z\nelement face 1\nproperty list uchar int vertex_indices\n"
                   "end_header\n0 0 0\n1 0 0\n0 1\n3 0 1 2\n");
  EXPECT_THAT(readError(dir / "bad.ply"), HasSubstr("bad.ply:12: vertex 2: too few values"));
  test::writeBytes(dir / "prose.obj", "hello world\nthis is text\n");
  EXPECT_THAT(readError(dir / "prose.obj"), HasSubstr("unknown OBJ statement 'hello' on line 1"));
  test::writeBytes(dir / "nofaces.obj", "v 0 0 0\n");
  EXPECT_THAT(readError(dir / "nofaces.obj"), HasSubstr("contains no triangles"));
}

TEST(MeshIoErrors, TruncatedBinaryFilesAreRejected) {
  test::ScratchDir dir;
  const ddf::TriangleMesh mesh{{{0, 0, 0}, {1, 0, 0}, {0, 1, 0}, {1, 1, 1}},
                               {{0, 1, 2}, {1, 3, 2}}};
  for (const char* ext : {"stl", "ply"}) {
    const auto path = dir / (std::string("whole.") + ext);
    writeMesh(mesh, path);
    const std::string bytes = test::readBytes(path);
    for (std::size_t size = 1; size < bytes.size(); ++size) {
      const auto cut = dir / (std::string("cut.") + ext);
      test::writeBytes(cut, bytes.substr(0, size));
      EXPECT_THAT(readError(cut), HasSubstr(cut.string())) << ext << " cut at " << size;
    }
  }
}

}  // namespace
}  // namespace ddfcam::io
