// SPDX-License-Identifier: MIT
// Writes the mesh oracle files of tests/data/mesh_oracles with VTK's and OpenMesh's writers.
/*
  Not part of the build: ddfcam's readers are checked against files that another program wrote,
  so this program must not use ddfcam. Build and run it from the repository root (Debian 12:
  libvtk9-dev, libopenmesh-dev; VTK 9.1 has no pkg-config file, hence the explicit libraries):

    g++ -std=c++17 -O1 scripts/make-mesh-oracles.cpp -o make-mesh-oracles \
      -I/usr/include/vtk-9.1 -lvtkIOGeometry-9.1 -lvtkIOPLY-9.1 -lvtkFiltersSources-9.1 \
      -lvtkFiltersGeneral-9.1 -lvtkFiltersCore-9.1 -lvtkIOCore-9.1 -lvtkCommonTransforms-9.1 \
      -lvtkCommonExecutionModel-9.1 -lvtkCommonDataModel-9.1 -lvtkCommonCore-9.1 -lOpenMeshCore
    ./make-mesh-oracles tests/data/mesh_oracles

  For each file it prints one line of facts (markdown table row and C++ initializer). Counts are
  those of the data handed to the writer (every writer here writes all points and cells); the
  STL welded vertex count, bounding box, area and volume are computed from the file as the
  writing program's own reader reads it back (vtkSTLReader, which merges coincident points,
  vtkPLYReader, vtkOBJReader; OpenMesh::IO::read_mesh), area and volume by vtkMassProperties.
  Both programs keep coordinates as float, so the facts hold to float precision.
*/
#include <OpenMesh/Core/IO/MeshIO.hh>
#include <OpenMesh/Core/Mesh/TriMesh_ArrayKernelT.hh>

#include <vtkCellArray.h>
#include <vtkCubeSource.h>
#include <vtkCylinderSource.h>
#include <vtkMassProperties.h>
#include <vtkNew.h>
#include <vtkOBJReader.h>
#include <vtkOBJWriter.h>
#include <vtkPLYReader.h>
#include <vtkPLYWriter.h>
#include <vtkPoints.h>
#include <vtkPolyData.h>
#include <vtkSTLReader.h>
#include <vtkSTLWriter.h>
#include <vtkSmartPointer.h>
#include <vtkSphereSource.h>
#include <vtkTransform.h>
#include <vtkTransformPolyDataFilter.h>
#include <vtkTriangleFilter.h>
#include <vtkVersion.h>

#include <cmath>
#include <cstdio>
#include <string>

namespace {

using Poly = vtkSmartPointer<vtkPolyData>;
using OmMesh = OpenMesh::TriMesh_ArrayKernelT<>;

std::string outDir;

struct Counts {
  long vertices = 0;   // vertices in the file
  long faces = 0;      // faces (STL: facets) in the file
  long triangles = 0;  // triangles after splitting each n-gon into n - 2
};

Counts countsOf(vtkPolyData* poly) {
  Counts c{poly->GetNumberOfPoints(), poly->GetNumberOfPolys(), 0};
  vtkIdType n = 0;
  const vtkIdType* ids = nullptr;
  auto* polys = poly->GetPolys();
  for (polys->InitTraversal(); polys->GetNextCell(n, ids);) c.triangles += n - 2;
  return c;
}

/// Prints the facts of @p file read back as @p poly; @p welded is the STL vertex count or -1.
void report(const std::string& file, const std::string& how, const Counts& c, vtkPolyData* poly,
            long welded, const std::string& analytic) {
  vtkNew<vtkTriangleFilter> triangles;
  triangles->SetInputData(poly);
  vtkNew<vtkMassProperties> mass;
  mass->SetInputConnection(triangles->GetOutputPort());
  mass->Update();
  double b[6];
  poly->GetBounds(b);
  std::printf(
      "| %s | %s | %ld | %ld | %ld | %ld | (%.9g, %.9g, %.9g) | (%.9g, %.9g, %.9g) | %.9g | "
      "%.9g | %s |\n",
      file.c_str(), how.c_str(), c.vertices, c.faces, c.triangles, welded, b[0], b[2], b[4], b[1],
      b[3], b[5], mass->GetSurfaceArea(), mass->GetVolume(), analytic.c_str());
  std::printf(
      "CXX {\"%s\", %ld, %ld, %ld, %ld, {%.9g, %.9g, %.9g}, {%.9g, %.9g, %.9g}, %.9g, %.9g},\n",
      file.c_str(), c.vertices, c.faces, c.triangles, welded, b[0], b[2], b[4], b[1], b[3], b[5],
      mass->GetSurfaceArea(), mass->GetVolume());
}

Poly transformed(vtkAlgorithm* source, vtkTransform* transform) {
  vtkNew<vtkTransformPolyDataFilter> filter;
  filter->SetInputConnection(source->GetOutputPort());
  filter->SetTransform(transform);
  filter->Update();
  return filter->GetOutput();
}

Poly triangulated(vtkPolyData* poly) {
  vtkNew<vtkTriangleFilter> filter;
  filter->SetInputData(poly);
  filter->Update();
  return filter->GetOutput();
}

template <class Reader>
Poly readBack(const std::string& path) {
  vtkNew<Reader> reader;
  reader->SetFileName(path.c_str());
  reader->Update();
  return reader->GetOutput();
}

void writeStl(vtkPolyData* poly, const std::string& file, bool binary,
              const std::string& analytic) {
  const std::string path = outDir + "/" + file;
  vtkNew<vtkSTLWriter> writer;
  writer->SetInputData(poly);
  writer->SetFileName(path.c_str());
  if (binary)
    writer->SetFileTypeToBinary();
  else
    writer->SetFileTypeToASCII();
  writer->Write();
  const Poly back = readBack<vtkSTLReader>(path);  // merges coincident points
  report(file, binary ? "vtkSTLWriter binary" : "vtkSTLWriter ASCII", countsOf(poly), back,
         back->GetNumberOfPoints(), analytic);
}

void writePly(vtkPolyData* poly, const std::string& file, int type, int order, bool colours,
              const std::string& analytic) {
  const std::string path = outDir + "/" + file;
  vtkNew<vtkPLYWriter> writer;
  writer->SetInputData(poly);
  writer->SetFileName(path.c_str());
  writer->SetFileType(type);
  writer->SetDataByteOrder(order);
  if (colours) {  // extra uchar red/green/blue properties on every face
    writer->SetColorModeToUniformCellColor();
    writer->SetColor(200, 120, 40);
  }
  writer->Write();
  std::string how = type == VTK_ASCII            ? "vtkPLYWriter ASCII"
                    : order == VTK_LITTLE_ENDIAN ? "vtkPLYWriter binary little endian"
                                                 : "vtkPLYWriter binary big endian";
  if (colours) how += ", uniform face colour";
  report(file, how, countsOf(poly), readBack<vtkPLYReader>(path), -1, analytic);
}

void writeObj(vtkPolyData* poly, const std::string& file, const std::string& analytic) {
  const std::string path = outDir + "/" + file;
  vtkNew<vtkOBJWriter> writer;
  writer->SetInputData(poly);
  writer->SetFileName(path.c_str());
  writer->Write();
  report(file, "vtkOBJWriter", countsOf(poly), readBack<vtkOBJReader>(path), -1, analytic);
}

void writeVtkFiles() {
  vtkNew<vtkSphereSource> sphere;  // 2 poles + 8 x 4 rings: 34 points, 64 triangles
  sphere->SetRadius(4.0);
  sphere->SetThetaResolution(8);
  sphere->SetPhiResolution(6);
  vtkNew<vtkTransform> sphereMove;
  sphereMove->Translate(1.0, -2.0, 0.5);
  sphereMove->RotateWXYZ(30.0, 1.0, 1.0, 0.0);
  const Poly s = transformed(sphere, sphereMove);
  const std::string polyhedron = "polyhedron inscribed in r = 4";
  writeStl(s, "sphere_vtk_binary.stl", true, polyhedron);
  writePly(s, "sphere_vtk_binary_le.ply", VTK_BINARY, VTK_LITTLE_ENDIAN, true, polyhedron);
  writeObj(s, "sphere_vtk.obj", polyhedron);

  vtkNew<vtkCubeSource> cube;  // 6 quads over 24 points (each face its own corners)
  cube->SetXLength(2.0);
  cube->SetYLength(3.0);
  cube->SetZLength(4.0);
  vtkNew<vtkTransform> cubeMove;
  cubeMove->Translate(0.5, 1.0, -1.0);
  cubeMove->RotateZ(25.0);
  cubeMove->RotateX(40.0);
  const Poly c = transformed(cube, cubeMove);
  const std::string box = "2 x 3 x 4 box: area 52, volume 24";
  writeStl(triangulated(c), "cube_vtk_ascii.stl", false, box);
  writePly(c, "cube_vtk_binary_be.ply", VTK_BINARY, VTK_BIG_ENDIAN, false, box);

  vtkNew<vtkCylinderSource> cylinder;  // 8 side quads and two octagon caps over 32 points
  cylinder->SetRadius(3.0);
  cylinder->SetHeight(5.0);
  cylinder->SetResolution(8);
  vtkNew<vtkTransform> cylinderMove;
  cylinderMove->Translate(-1.0, 0.5, 2.0);
  cylinderMove->RotateX(90.0);
  cylinderMove->RotateY(10.0);
  const Poly y = transformed(cylinder, cylinderMove);
  const double octagon = 2.0 * std::sqrt(2.0) * 9.0;
  const double side = 2.0 * 3.0 * std::sin(M_PI / 8.0);
  char prism[160];
  std::snprintf(prism, sizeof prism, "octagonal prism r = 3, h = 5: area %.9g, volume %.9g",
                2.0 * octagon + 8.0 * side * 5.0, octagon * 5.0);
  writeObj(y, "cylinder_vtk.obj", prism);
  writePly(y, "cylinder_vtk_ascii.ply", VTK_ASCII, VTK_LITTLE_ENDIAN, false, prism);
}

/// Regular icosahedron with edge 2 s, the corners (0, +-1, +-phi) cycled, scaled by s, moved.
OmMesh icosahedron(double s, const OmMesh::Point& at) {
  const double phi = (1.0 + std::sqrt(5.0)) / 2.0;
  OmMesh mesh;
  OmMesh::VertexHandle v[12];
  int k = 0;
  for (int axis = 0; axis < 3; ++axis)
    for (const double a : {-1.0, 1.0})
      for (const double b : {-phi, phi}) {
        double p[3];
        p[axis] = 0.0;
        p[(axis + 1) % 3] = a;
        p[(axis + 2) % 3] = b;
        v[k++] = mesh.add_vertex(OmMesh::Point(p[0], p[1], p[2]) * static_cast<float>(s) + at);
      }
  // Faces: every triple of mutually adjacent corners (edge 2), oriented outwards.
  const double edge2 = 4.0 * s * s;
  for (int i = 0; i < 12; ++i)
    for (int j = i + 1; j < 12; ++j)
      for (int l = j + 1; l < 12; ++l) {
        const auto pi = mesh.point(v[i]), pj = mesh.point(v[j]), pl = mesh.point(v[l]);
        auto near = [&](const OmMesh::Point& p, const OmMesh::Point& q) {
          return std::abs((p - q).sqrnorm() - edge2) < 1e-3 * edge2;
        };
        if (!near(pi, pj) || !near(pj, pl) || !near(pi, pl)) continue;
        const auto normal = OpenMesh::cross(pj - pi, pl - pi);
        const auto outward = (pi + pj + pl) / 3.0f - at;
        if (OpenMesh::dot(normal, outward) > 0)
          mesh.add_face(v[i], v[j], v[l]);
        else
          mesh.add_face(v[i], v[l], v[j]);
      }
  return mesh;
}

Poly toPoly(const OmMesh& mesh) {
  vtkNew<vtkPoints> points;
  for (const auto vh : mesh.vertices()) {
    const auto p = mesh.point(vh);
    points->InsertNextPoint(p[0], p[1], p[2]);
  }
  vtkNew<vtkCellArray> cells;
  for (const auto fh : mesh.faces()) {
    cells->InsertNextCell(0);
    for (const auto vh : mesh.fv_range(fh)) cells->InsertCellPoint(vh.idx());
    cells->UpdateCellCount(static_cast<vtkIdType>(mesh.valence(fh)));
  }
  Poly poly = Poly::New();
  poly->SetPoints(points);
  poly->SetPolys(cells);
  return poly;
}

void writeOpenMesh(OmMesh& mesh, const std::string& file, OpenMesh::IO::Options options,
                   const std::string& how, const std::string& analytic) {
  const std::string path = outDir + "/" + file;
  if (!OpenMesh::IO::write_mesh(mesh, path, options, 9))
    std::fprintf(stderr, "cannot write %s\n", path.c_str());
  OmMesh back;
  OpenMesh::IO::Options readOptions = options;
  if (!OpenMesh::IO::read_mesh(back, path, readOptions))
    std::fprintf(stderr, "cannot read %s\n", path.c_str());
  const Counts c{static_cast<long>(mesh.n_vertices()), static_cast<long>(mesh.n_faces()),
                 static_cast<long>(mesh.n_faces())};
  const bool stl = file.substr(file.size() - 4) == ".stl";
  report(file, how, c, toPoly(back), stl ? static_cast<long>(back.n_vertices()) : -1, analytic);
}

void writeOpenMeshFiles() {
  OmMesh mesh = icosahedron(1.5, OmMesh::Point(0.25f, -0.5f, 1.0f));
  const double a = 3.0;  // edge
  char ico[160];
  std::snprintf(ico, sizeof ico, "icosahedron edge 3: area %.9g, volume %.9g",
                5.0 * std::sqrt(3.0) * a * a, 5.0 * (3.0 + std::sqrt(5.0)) / 12.0 * a * a * a);
  mesh.request_vertex_colors();
  for (const auto vh : mesh.vertices())
    mesh.set_color(vh, OmMesh::Color(static_cast<unsigned char>(20 * vh.idx()), 128, 255));
  namespace io = OpenMesh::IO;
  writeOpenMesh(mesh, "icosahedron_openmesh.off", io::Options::VertexColor,
                "write_mesh, OFF with vertex colours (COFF)", ico);
  writeOpenMesh(mesh, "icosahedron_openmesh.obj", io::Options::Default, "write_mesh, OBJ", ico);
  writeOpenMesh(mesh, "icosahedron_openmesh_binary_be.ply",
                io::Options(io::Options::Binary | io::Options::MSB | io::Options::VertexColor),
                "write_mesh, PLY binary big endian with vertex colours", ico);
  writeOpenMesh(mesh, "icosahedron_openmesh_ascii.stl", io::Options::Default,
                "write_mesh, STL ASCII", ico);
}

}  // namespace

int main(int argc, char** argv) {
  if (argc != 2) {
    std::fprintf(stderr, "usage: %s OUTPUT_DIR\n", argv[0]);
    return 2;
  }
  outDir = argv[1];
  std::printf("VTK %s, OpenMesh %d.%d\n", vtkVersion::GetVTKVersion(), OM_GET_VER, OM_GET_MAJ);
  std::printf(
      "| file | writer | vertices | faces | triangles | STL welded | bbox min | bbox max | "
      "area | volume | analytic |\n");
  writeVtkFiles();
  writeOpenMeshFiles();
  return 0;
}
