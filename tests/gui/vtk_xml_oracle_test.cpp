// SPDX-License-Identifier: MIT
// ddfcam tests: our VTK XML reader (io, no VTK) against files written by VTK's own XML writers.
#include <ddfcam/io/mesh/vtk_xml_mesh.h>

#include <gtest/gtest.h>

#include <vtkCellArray.h>
#include <vtkCellData.h>
#include <vtkCellType.h>
#include <vtkDataSetSurfaceFilter.h>
#include <vtkDoubleArray.h>
#include <vtkFloatArray.h>
#include <vtkIntArray.h>
#include <vtkNew.h>
#include <vtkPointData.h>
#include <vtkPoints.h>
#include <vtkPolyData.h>
#include <vtkTriangleFilter.h>
#include <vtkUnstructuredGrid.h>
#include <vtkXMLPolyDataWriter.h>
#include <vtkXMLUnstructuredGridWriter.h>

#include <cmath>
#include <filesystem>
#include <map>
#include <string>

namespace ddfcam::test {
namespace {

// One writer configuration: data mode, compression, header type, byte order.
struct WriterMode {
  std::string name;
  int dataMode;  // vtkXMLWriter::Ascii / Binary / Appended
  bool zlib;
  bool encodeAppended;
  bool uint64Header;
  bool bigEndian;
};

const std::vector<WriterMode> kModes = {
    {"ascii", vtkXMLWriter::Ascii, false, false, false, false},
    {"binary", vtkXMLWriter::Binary, false, false, false, false},
    {"binary_zlib", vtkXMLWriter::Binary, true, false, true, false},
    {"binary_big_endian", vtkXMLWriter::Binary, false, false, true, true},
    {"appended_raw", vtkXMLWriter::Appended, false, false, true, false},
    {"appended_base64", vtkXMLWriter::Appended, false, true, false, false},
    {"appended_zlib", vtkXMLWriter::Appended, true, false, false, false},
    {"appended_base64_zlib_big", vtkXMLWriter::Appended, true, true, true, true}};

template <typename Writer>
void configure(Writer* w, const WriterMode& m) {
  w->SetDataMode(m.dataMode);
  if (m.zlib)
    w->SetCompressorTypeToZLib();
  else
    w->SetCompressorTypeToNone();
  w->SetEncodeAppendedData(m.encodeAppended);
  if (m.uint64Header)
    w->SetHeaderTypeToUInt64();
  else
    w->SetHeaderTypeToUInt32();
  if (m.bigEndian)
    w->SetByteOrderToBigEndian();
  else
    w->SetByteOrderToLittleEndian();
  w->SetBlockSize(64);  // several compression blocks even for small arrays
}

std::filesystem::path scratch(const std::string& name) {
  const auto dir = std::filesystem::temp_directory_path() / "ddfcam_vtk_xml_oracle";
  std::filesystem::create_directories(dir);
  return dir / name;
}

Eigen::Vector3d vectorArea(const std::vector<Eigen::Vector3d>& polygon) {
  Eigen::Vector3d a = Eigen::Vector3d::Zero();
  for (std::size_t i = 0; i < polygon.size(); ++i)
    a += 0.5 * polygon[i].cross(polygon[(i + 1) % polygon.size()]);
  return a;
}

// Vertices, lines, triangles, a quad, a convex pentagon and a strip on a wavy sheet.
vtkNew<vtkPolyData> makePolyData() {
  vtkNew<vtkPolyData> pd;
  vtkNew<vtkPoints> pts;
  pts->SetDataTypeToDouble();
  for (int j = 0; j < 4; ++j)
    for (int i = 0; i < 5; ++i)
      pts->InsertNextPoint(10.0 * i + 0.123456789 * j, 7.0 * j, std::sin(0.3 * i + 0.7 * j));
  pd->SetPoints(pts);
  vtkNew<vtkCellArray> verts, lines, polys, strips;
  const vtkIdType v[] = {3};
  verts->InsertNextCell(1, v);
  const vtkIdType l[] = {0, 1, 2};
  lines->InsertNextCell(3, l);
  const vtkIdType tri[] = {0, 1, 6}, quad[] = {1, 2, 7, 6}, pent[] = {2, 3, 4, 9, 8};
  polys->InsertNextCell(3, tri);
  polys->InsertNextCell(4, quad);
  polys->InsertNextCell(5, pent);
  const vtkIdType strip[] = {10, 15, 11, 16, 12, 17, 13};
  strips->InsertNextCell(7, strip);
  pd->SetVerts(verts);
  pd->SetLines(lines);
  pd->SetPolys(polys);
  pd->SetStrips(strips);
  vtkNew<vtkFloatArray> thickness;
  thickness->SetName("thickness");
  vtkNew<vtkDoubleArray> disp;
  disp->SetName("disp");
  disp->SetNumberOfComponents(3);
  for (vtkIdType p = 0; p < pd->GetNumberOfPoints(); ++p) {
    thickness->InsertNextValue(1.0f + 0.01f * p);
    disp->InsertNextTuple3(0.1 * p, -0.2, 0.05 * p * p);
  }
  pd->GetPointData()->AddArray(thickness);
  pd->GetPointData()->AddArray(disp);
  vtkNew<vtkIntArray> cellId;
  cellId->SetName("cellId");
  for (vtkIdType c = 0; c < pd->GetNumberOfCells(); ++c) cellId->InsertNextValue(int(c));
  pd->GetCellData()->AddArray(cellId);
  return pd;
}

void expectSamePolyData(vtkPolyData* pd, const io::VtkXmlMesh& m, const std::string& mode) {
  ASSERT_EQ(m.mesh.vertices.size(), std::size_t(pd->GetNumberOfPoints())) << mode;
  const double tol = mode == "ascii" ? 1e-9 : 0.0;
  for (vtkIdType p = 0; p < pd->GetNumberOfPoints(); ++p) {
    double x[3];
    pd->GetPoint(p, x);
    EXPECT_LE((m.mesh.vertices[p] - Eigen::Vector3d(x[0], x[1], x[2])).norm(), tol) << mode;
  }
  EXPECT_EQ(m.ignoredVertexCells, 1);
  EXPECT_EQ(m.ignoredLineCells, 1);
  EXPECT_EQ(m.mesh.triangles.size(), 1u + 2u + 3u + 5u) << mode;
  std::map<std::string, const planning::MeshField*> fields;
  for (const auto& f : m.fields) fields[f.name] = &f;
  ASSERT_TRUE(fields.count("thickness") && fields.count("|disp|") && fields.count("cellId"));
  for (vtkIdType p = 0; p < pd->GetNumberOfPoints(); ++p) {
    EXPECT_EQ(fields["thickness"]->values[p], 1.0f + 0.01f * p);
    const double* d = pd->GetPointData()->GetArray("disp")->GetTuple3(p);
    EXPECT_FLOAT_EQ(fields["|disp|"]->values[p], float(std::hypot(d[0], d[1], d[2])));
  }
  // Per VTK cell, our triangles (found through the cell-id field) cover its vector area.
  std::map<int, Eigen::Vector3d> area;
  for (std::size_t t = 0; t < m.mesh.triangles.size(); ++t) {
    std::vector<Eigen::Vector3d> tri;
    for (const int v : m.mesh.triangles[t]) tri.push_back(m.mesh.vertices[v]);
    auto& a =
        area.try_emplace(int(fields["cellId"]->values[t]), Eigen::Vector3d::Zero()).first->second;
    a += vectorArea(tri);
  }
  for (vtkIdType c = 2; c < 5; ++c) {  // the polygons (cells 0, 1 are the vertex and line)
    vtkCell* cell = pd->GetCell(c);
    std::vector<Eigen::Vector3d> poly;
    for (vtkIdType k = 0; k < cell->GetNumberOfPoints(); ++k) {
      double x[3];
      pd->GetPoint(cell->GetPointId(k), x);
      poly.emplace_back(x[0], x[1], x[2]);
    }
    EXPECT_LT((area[int(c)] - vectorArea(poly)).norm(), 1e-9) << mode << " cell " << c;
  }
  // The strip: VTK's own triangulation gives the oracle area and orientation.
  vtkNew<vtkTriangleFilter> triangulate;
  triangulate->SetInputData(pd);
  triangulate->PassVertsOff();
  triangulate->PassLinesOff();
  triangulate->Update();
  Eigen::Vector3d vtkTotal = Eigen::Vector3d::Zero(), ours = Eigen::Vector3d::Zero();
  vtkPolyData* out = triangulate->GetOutput();
  for (vtkIdType c = 0; c < out->GetNumberOfCells(); ++c) {
    std::vector<Eigen::Vector3d> tri;
    for (int k = 0; k < 3; ++k) {
      double x[3];
      out->GetPoint(out->GetCell(c)->GetPointId(k), x);
      tri.emplace_back(x[0], x[1], x[2]);
    }
    vtkTotal += vectorArea(tri);
  }
  for (const auto& [cell, a] : area) ours += a;
  EXPECT_EQ(out->GetNumberOfCells(), vtkIdType(m.mesh.triangles.size()));
  EXPECT_LT((ours - vtkTotal).norm(), 1e-9) << mode;
}

TEST(VtkXmlOracle, PolyDataFromEveryWriterModeMatchesVtk) {
  auto pd = makePolyData();
  for (const auto& mode : kModes) {
    const auto path = scratch("sheet_" + mode.name + ".vtp");
    vtkNew<vtkXMLPolyDataWriter> writer;
    configure(writer.GetPointer(), mode);
    writer->SetInputData(pd);
    writer->SetFileName(path.c_str());
    ASSERT_EQ(writer->Write(), 1) << mode.name;
    expectSamePolyData(pd, io::readVtkXmlMesh(path), mode.name);
  }
}

// An affinely sheared 3 x 2 x 2 block of hexahedra (planar faces, so the volume does not
// depend on which diagonal splits a quad) with a pyramid and a tetra on top and a separate wedge.
vtkNew<vtkUnstructuredGrid> makeGrid() {
  vtkNew<vtkUnstructuredGrid> grid;
  vtkNew<vtkPoints> pts;
  const auto id = [](int i, int j, int k) { return vtkIdType(i + 4 * (j + 3 * k)); };
  for (int k = 0; k < 3; ++k)
    for (int j = 0; j < 3; ++j)
      for (int i = 0; i < 4; ++i)
        pts->InsertNextPoint(2.0 * i, 1.5 * j, 1.0 * k + 0.1 * i + 0.05 * j);
  const vtkIdType apex = pts->InsertNextPoint(1.0, 0.75, 3.0);
  const vtkIdType top = pts->InsertNextPoint(5.0, 1.5, 3.5);
  vtkIdType wedge[6];
  for (const double z : {0.0, 1.0}) {
    wedge[z == 0.0 ? 0 : 3] = pts->InsertNextPoint(10.0, 0.0, z);
    wedge[z == 0.0 ? 1 : 4] = pts->InsertNextPoint(10.0, 2.0, z);
    wedge[z == 0.0 ? 2 : 5] = pts->InsertNextPoint(12.0, 0.0, z);
  }
  grid->SetPoints(pts);
  for (int k = 0; k < 2; ++k)
    for (int j = 0; j < 2; ++j)
      for (int i = 0; i < 3; ++i) {
        const vtkIdType h[8] = {
            id(i, j, k),     id(i + 1, j, k),     id(i + 1, j + 1, k),     id(i, j + 1, k),
            id(i, j, k + 1), id(i + 1, j, k + 1), id(i + 1, j + 1, k + 1), id(i, j + 1, k + 1)};
        grid->InsertNextCell(VTK_HEXAHEDRON, 8, h);
      }
  const vtkIdType pyramid[5] = {id(0, 0, 2), id(1, 0, 2), id(1, 1, 2), id(0, 1, 2), apex};
  grid->InsertNextCell(VTK_PYRAMID, 5, pyramid);
  const vtkIdType tetra[4] = {id(2, 1, 2), id(3, 1, 2), id(2, 2, 2), top};
  grid->InsertNextCell(VTK_TETRA, 4, tetra);
  grid->InsertNextCell(VTK_WEDGE, 6, wedge);
  const vtkIdType line[2] = {0, 1};
  grid->InsertNextCell(VTK_LINE, 2, line);
  vtkNew<vtkDoubleArray> temp;
  temp->SetName("temp");
  for (vtkIdType p = 0; p < pts->GetNumberOfPoints(); ++p) temp->InsertNextValue(20.0 + p);
  grid->GetPointData()->AddArray(temp);
  return grid;
}

TEST(VtkXmlOracle, UnstructuredGridBoundaryMatchesVtkSurfaceFilter) {
  auto grid = makeGrid();
  vtkNew<vtkDataSetSurfaceFilter> surface;
  surface->SetInputData(grid);
  vtkNew<vtkTriangleFilter> triangulate;
  triangulate->SetInputConnection(surface->GetOutputPort());
  triangulate->PassLinesOff();
  triangulate->PassVertsOff();
  triangulate->Update();
  // Signed volume of VTK's own boundary (divergence theorem over its triangles).
  double vtkVolume = 0.0;
  vtkPolyData* boundary = triangulate->GetOutput();
  for (vtkIdType c = 0; c < boundary->GetNumberOfCells(); ++c) {
    Eigen::Vector3d p[3];
    for (int k = 0; k < 3; ++k) {
      double x[3];
      boundary->GetPoint(boundary->GetCell(c)->GetPointId(k), x);
      p[k] = Eigen::Vector3d(x[0], x[1], x[2]);
    }
    vtkVolume += p[0].dot(p[1].cross(p[2])) / 6.0;
  }
  ASSERT_GT(vtkVolume, 0.0);
  for (const auto& mode : kModes) {
    const auto path = scratch("block_" + mode.name + ".vtu");
    vtkNew<vtkXMLUnstructuredGridWriter> writer;
    configure(writer.GetPointer(), mode);
    writer->SetInputData(grid);
    writer->SetFileName(path.c_str());
    ASSERT_EQ(writer->Write(), 1) << mode.name;
    const auto m = io::readVtkXmlMesh(path);
    EXPECT_EQ(m.ignoredLineCells, 1) << mode.name;
    EXPECT_EQ(vtkIdType(m.mesh.triangles.size()), triangulate->GetOutput()->GetNumberOfCells())
        << mode.name;
    // Outward: our signed volume equals that of VTK's surface (Float32 points: quads are planar
    // only to float precision, so the diagonals may differ by ~1e-8 mm^3).
    EXPECT_NEAR(m.mesh.signedVolume(), vtkVolume, 1e-6) << mode.name;
    ASSERT_EQ(m.fields.size(), 1u);
    for (vtkIdType p = 0; p < grid->GetNumberOfPoints(); ++p)
      EXPECT_EQ(m.fields[0].values[p], float(20.0 + p));
  }
}

}  // namespace
}  // namespace ddfcam::test
