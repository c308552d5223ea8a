// SPDX-License-Identifier: MIT
// ddfcam tests: the VTK XML (.vtp/.vtu) reader on hand-written files, surface file dispatch.
#include <ddfcam/error.h>
#include <ddfcam/io/mesh/mesh_io.h>
#include <ddfcam/io/mesh/surface_file.h>
#include <ddfcam/io/mesh/vtk_xml_mesh.h>

#include "../io_test_support.h"

#include <gtest/gtest.h>
#include <zlib.h>

#include <algorithm>
#include <chrono>
#include <cstdint>
#include <cstring>
#include <random>

namespace ddfcam::test {
namespace {

std::string base64(const std::string& bytes) {
  static const char* kAlphabet = "ABCDEFGHIJKLMNOPQRSTUVWXYZabcdefghijklmnopqrstuvwxyz0123456789+/";
  std::string out;
  for (std::size_t i = 0; i < bytes.size(); i += 3) {
    std::uint32_t w = 0;
    const std::size_t n = std::min<std::size_t>(3, bytes.size() - i);
    for (std::size_t k = 0; k < 3; ++k)
      w = (w << 8) | (k < n ? static_cast<unsigned char>(bytes[i + k]) : 0u);
    for (std::size_t k = 0; k < 4; ++k) out += k <= n ? kAlphabet[(w >> (18 - 6 * k)) & 63] : '=';
  }
  return out;
}

template <typename T>
std::string rawBytes(const std::vector<T>& values, bool bigEndian = false) {
  std::string out;
  for (const T v : values) {
    char b[sizeof(T)];
    std::memcpy(b, &v, sizeof(T));
    if (bigEndian) std::reverse(b, b + sizeof(T));
    out.append(b, sizeof(T));
  }
  return out;
}

std::string grid(const std::string& points, const std::string& conn, const std::string& offsets,
                 const std::string& types, int nPoints, int nCells) {
  return "<?xml version=\"1.0\"?>\n<VTKFile type=\"UnstructuredGrid\" version=\"0.1\">\n"
         "<UnstructuredGrid><Piece NumberOfPoints=\"" +
         std::to_string(nPoints) + "\" NumberOfCells=\"" + std::to_string(nCells) +
         "\">\n<Points><DataArray type=\"Float64\" NumberOfComponents=\"3\" format=\"ascii\">" +
         points +
         "</DataArray></Points>\n<Cells>"
         "<DataArray type=\"Int64\" Name=\"connectivity\" format=\"ascii\">" +
         conn + "</DataArray><DataArray type=\"Int64\" Name=\"offsets\" format=\"ascii\">" +
         offsets + "</DataArray><DataArray type=\"UInt8\" Name=\"types\" format=\"ascii\">" +
         types + "</DataArray></Cells>\n</Piece></UnstructuredGrid></VTKFile>\n";
}

const std::string kCube = "0 0 0 1 0 0 1 1 0 0 1 0 0 0 1 1 0 1 1 1 1 0 1 1 ";

TEST(VtkXmlMesh, HexahedronGivesOutwardBoundary) {
  const auto m = io::decodeVtkXmlMesh(grid(kCube, "0 1 2 3 4 5 6 7", "8", "12", 8, 1), "hex.vtu");
  EXPECT_EQ(m.mesh.triangles.size(), 12u);
  EXPECT_NEAR(m.mesh.signedVolume(), 1.0, 1e-12);  // closed and outward
}

TEST(VtkXmlMesh, TwoHexahedraShareTheirCommonFace) {
  const std::string pts = kCube + "2 0 0 2 1 0 2 0 1 2 1 1";
  // Second hex: x from 1 to 2, nodes 1 8 9 2 5 10 11 6.
  const auto m = io::decodeVtkXmlMesh(
      grid(pts, "0 1 2 3 4 5 6 7 1 8 9 2 5 10 11 6", "8 16", "12 12", 12, 2), "two.vtu");
  EXPECT_EQ(m.mesh.triangles.size(), 20u);  // 10 outer quads
  EXPECT_NEAR(m.mesh.signedVolume(), 2.0, 1e-12);
}

TEST(VtkXmlMesh, SolidCellsHaveTheirAnalyticVolume) {
  struct Case {
    const char* conn;
    int type;
    double volume;
  };
  const Case cases[] = {{"0 1 3 4", 10, 1.0 / 6.0},     // tetra
                        {"0 1 3 2 4 5 7 6", 11, 1.0},   // voxel (node order of a pixel)
                        {"0 3 1 4 7 5", 13, 0.5},       // wedge: half the cube
                        {"0 1 2 3 6", 14, 1.0 / 3.0}};  // pyramid to (1,1,1)
  for (const auto& c : cases) {
    const int n = static_cast<int>(std::count(c.conn, c.conn + std::strlen(c.conn), ' ')) + 1;
    const auto m = io::decodeVtkXmlMesh(
        grid(kCube, c.conn, std::to_string(n), std::to_string(c.type), 8, 1), "cell.vtu");
    EXPECT_NEAR(m.mesh.signedVolume(), c.volume, 1e-12) << "type " << c.type;
  }
}

TEST(VtkXmlMesh, SurfaceCellsQuadsAndLinesAreCounted) {
  // quad 9, pixel 8, quadratic triangle 22 (corner nodes), a line 3 and a vertex 1.
  const std::string pts = "0 0 0 1 0 0 1 1 0 0 1 0 0.5 0 0 1 0.5 0 0.5 0.5 0 ";
  const auto m = io::decodeVtkXmlMesh(
      grid(pts, "0 1 2 3 0 1 3 2 0 1 2 4 5 6 0 1 2", "4 8 14 16 17", "9 8 22 3 1", 7, 5), "s.vtu");
  ASSERT_EQ(m.mesh.triangles.size(), 5u);
  EXPECT_EQ(m.ignoredLineCells, 1);
  EXPECT_EQ(m.ignoredVertexCells, 1);
  for (const auto& t : m.mesh.triangles) {
    const auto& v = m.mesh.vertices;
    EXPECT_GT((v[t[1]] - v[t[0]]).cross(v[t[2]] - v[t[0]]).z(), 0.0);  // all counter-clockwise
    for (const int i : t) EXPECT_LT(i, 4);  // mid-edge nodes are not used
  }
}

std::string polyData(const std::string& arrays) {
  return "<VTKFile type=\"PolyData\" version=\"0.1\" byte_order=\"LittleEndian\"><PolyData>"
         "<Piece NumberOfPoints=\"5\" NumberOfPolys=\"2\" NumberOfLines=\"1\">"
         "<Points><DataArray type=\"Float32\" NumberOfComponents=\"3\" format=\"ascii\">"
         "0 0 0  2 0 0  2 2 0  0 2 0  3 1 0</DataArray></Points>"
         "<Lines><DataArray type=\"Int32\" Name=\"connectivity\">0 2</DataArray>"
         "<DataArray type=\"Int32\" Name=\"offsets\">2</DataArray></Lines>"
         "<Polys><DataArray type=\"Int32\" Name=\"connectivity\" format=\"ascii\">0 1 2 3 1 4 2"
         "</DataArray><DataArray type=\"Int32\" Name=\"offsets\" format=\"ascii\">4 7</DataArray>"
         "</Polys>" +
         arrays + "</Piece></PolyData></VTKFile>";
}

TEST(VtkXmlMesh, CellDataFollowsTheTrianglesOfItsCell) {
  const auto m = io::decodeVtkXmlMesh(
      polyData("<PointData><DataArray type=\"Float64\" Name=\"thickness\" format=\"ascii\">"
               "1 2 3 4 5</DataArray></PointData><CellData>"
               "<DataArray type=\"Float32\" Name=\"strain\">9 10 20</DataArray>"
               "<DataArray type=\"Float32\" Name=\"v\" NumberOfComponents=\"3\">0 0 0 3 4 0 0 0 "
               "2</DataArray><DataArray type=\"Float32\" Name=\"t\" NumberOfComponents=\"2\">"
               "1 1 1 1 1 1</DataArray></CellData>"),
      "p.vtp");
  ASSERT_EQ(m.mesh.triangles.size(), 3u);  // quad -> 2, triangle -> 1
  EXPECT_EQ(m.ignoredLineCells, 1);
  ASSERT_EQ(m.fields.size(), 3u);
  EXPECT_EQ(m.fields[0].name, "thickness");
  EXPECT_FALSE(m.fields[0].perCell);
  EXPECT_EQ(m.fields[0].values, (std::vector<float>{1, 2, 3, 4, 5}));
  EXPECT_EQ(m.fields[1].name, "strain");
  EXPECT_TRUE(m.fields[1].perCell);
  // Cell 0 is the line; the quad is cell 1 (two triangles), the triangle cell 2.
  EXPECT_EQ(m.fields[1].values, (std::vector<float>{10, 10, 20}));
  EXPECT_EQ(m.fields[2].name, "|v|");
  EXPECT_EQ(m.fields[2].values, (std::vector<float>{5, 5, 2}));
  ASSERT_EQ(m.warnings.size(), 1u);  // the 2-component array
  EXPECT_NE(m.warnings[0].find("'t'"), std::string::npos);
}

// The same quad as binary base64 and as appended raw data, with UInt64 headers big endian.
std::string binaryQuad(bool appended, bool bigEndian, bool zlib = false) {
  const auto pts = rawBytes<double>({0, 0, 0, 1, 0, 0, 1, 1, 0, 0, 1, 0}, bigEndian);
  const auto conn = rawBytes<std::int64_t>({0, 1, 2, 3}, bigEndian);
  const auto offs = rawBytes<std::int64_t>({4}, bigEndian);
  const auto types = rawBytes<std::uint8_t>({9});
  const auto block = [&](const std::string& b) {
    if (!zlib) return rawBytes<std::uint64_t>({b.size()}, bigEndian) + b;
    std::string packed(compressBound(b.size()), '\0');
    uLongf size = packed.size();
    compress(reinterpret_cast<Bytef*>(packed.data()), &size,
             reinterpret_cast<const Bytef*>(b.data()), b.size());
    packed.resize(size);
    return rawBytes<std::uint64_t>({1, b.size(), b.size(), size}, bigEndian) + packed;
  };
  std::string head =
      std::string("<VTKFile type=\"UnstructuredGrid\" version=\"1.0\" byte_order=\"") +
      (bigEndian ? "BigEndian" : "LittleEndian") + "\" header_type=\"UInt64\"" +
      (zlib ? " compressor=\"vtkZLibDataCompressor\"" : "") +
      "><UnstructuredGrid>"
      "<Piece NumberOfPoints=\"4\" NumberOfCells=\"1\">";
  const std::string arrays[4][3] = {{"Float64", "", pts},
                                    {"Int64", "connectivity", conn},
                                    {"Int64", "offsets", offs},
                                    {"UInt8", "types", types}};
  std::string body, data;
  for (int i = 0; i < 4; ++i) {
    std::string e = "<DataArray type=\"" + arrays[i][0] + "\" Name=\"" + arrays[i][1] + "\"" +
                    (i == 0 ? " NumberOfComponents=\"3\"" : "");
    if (appended) {
      e += " format=\"appended\" offset=\"" + std::to_string(data.size()) + "\"/>";
      data += block(arrays[i][2]);
    } else {
      e += " format=\"binary\">\n  " + base64(block(arrays[i][2])) + "\n</DataArray>";
    }
    body += (i == 1 ? "</Points><Cells>" : i == 0 ? "<Points>" : "") + e;
  }
  body += "</Cells></Piece></UnstructuredGrid>";
  if (appended) body += "<AppendedData encoding=\"raw\">\n _" + data + "\n</AppendedData>";
  return head + body + "</VTKFile>";
}

TEST(VtkXmlMesh, BinaryAndAppendedArraysInBothByteOrders) {
  for (const bool appended : {false, true})
    for (const bool big : {false, true}) {
      const auto m = io::decodeVtkXmlMesh(binaryQuad(appended, big, appended != big), "q.vtu");
      ASSERT_EQ(m.mesh.vertices.size(), 4u);
      EXPECT_EQ(m.mesh.vertices[2], Eigen::Vector3d(1, 1, 0));
      EXPECT_EQ(m.mesh.triangles.size(), 2u) << appended << big;
    }
}

TEST(VtkXmlMesh, ErrorsNameFileAndElement) {
  const auto message = [](const std::string& text) {
    try {
      io::decodeVtkXmlMesh(text, "bad.vtu");
    } catch (const IoError& e) {
      return std::string(e.what());
    }
    return std::string("no error");
  };
  EXPECT_NE(message(grid(kCube, "0 1 2 3 4 5 6 9", "8", "12", 8, 1)).find("connectivity"),
            std::string::npos);
  EXPECT_NE(message(grid(kCube + "7", "0 1 2", "3", "5", 8, 1)).find("Points"), std::string::npos);
  EXPECT_NE(message(grid(kCube, "0 1 2 3", "4", "12", 8, 1)).find("cell 0"), std::string::npos);
  EXPECT_NE(message("<VTKFile type=\"ImageData\"></VTKFile>").find("ImageData"), std::string::npos);
  EXPECT_EQ(message("<VTKFile").rfind("bad.vtu: ", 0), 0u);
  EXPECT_NE(message(grid(kCube, "0 1", "2", "3", 8, 1)).find("no surface"), std::string::npos);
}

TEST(VtkXmlMesh, MutatedFilesOnlyThrowIoErrors) {
  const std::vector<std::string> seeds = {binaryQuad(false, false),
                                          binaryQuad(true, true),
                                          binaryQuad(false, true, true),
                                          binaryQuad(true, false, true),
                                          polyData(""),
                                          grid(kCube, "0 1 2 3 4 5 6 7", "8", "12", 8, 1)};
  std::mt19937_64 rng(0xa1a);
  const auto start = std::chrono::steady_clock::now();
  int runs = 0, accepted = 0;
  while (std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count() < 0.8) {
    std::string text = seeds[rng() % seeds.size()];
    for (int k = 0, n = 1 + rng() % 4; k < n; ++k) {
      const std::size_t at = rng() % text.size();
      switch (rng() % 4) {
        case 0:
          text[at] = static_cast<char>(rng());
          break;
        case 1:
          text.erase(at, 1 + rng() % 8);
          break;
        case 2:
          text.insert(at, std::string(1 + rng() % 3, "0123456789\"<>/=_ -"[rng() % 18]));
          break;
        default:
          text.resize(at);
          break;
      }
      if (text.empty()) text = "<";
    }
    try {
      const auto m = io::decodeVtkXmlMesh(text, "fuzz.vtu");
      for (const auto& t : m.mesh.triangles)
        for (const int v : t) ASSERT_TRUE(v >= 0 && v < static_cast<int>(m.mesh.vertices.size()));
      ++accepted;
    } catch (const IoError&) {
    }
    ++runs;
  }
  EXPECT_GT(runs, 100);
  EXPECT_GT(accepted, 0);
}

TEST(SurfaceFile, DispatchesByExtensionAndKeepsFields) {
  ScratchDir dir;
  const auto vtp = dir.path() / "part.VTP";
  writeBytes(vtp, polyData("<CellData><DataArray type=\"Int8\" Name=\"id\">-1 7 8</DataArray>"
                           "</CellData>"));
  const auto s = io::readSurfaceFile(vtp);
  EXPECT_EQ(s.name, "part.VTP");
  EXPECT_EQ(s.mesh.triangles.size(), 3u);
  ASSERT_EQ(s.fields.size(), 1u);
  EXPECT_EQ(s.fields[0].values, (std::vector<float>{7, 7, 8}));
  const auto stl = dir.path() / "part.stl";
  io::writeMesh(s.mesh, stl);
  EXPECT_EQ(io::readSurfaceFile(stl).mesh.triangles.size(), 3u);
  EXPECT_THROW(io::readSurfaceFile(dir.path() / "part.step"), IoError);
  EXPECT_TRUE(io::isSurfaceFile("a/b.Vtu"));
  EXPECT_EQ(io::surfaceFileDialogFilter(), "Surfaces (*.stl *.obj *.ply *.off *.vtp *.vtu)");
}

}  // namespace
}  // namespace ddfcam::test
