// SPDX-License-Identifier: MIT
// ddfcam gui adapters: TriangleMesh and segment lists to vtkPolyData.
#include <ddfcam/gui/adapters/poly_data.h>

#include <ddfcam/error.h>

#include <vtkCellArray.h>
#include <vtkDoubleArray.h>
#include <vtkPoints.h>
#include <vtkPolyData.h>
#include <vtkPolyDataNormals.h>

#include <algorithm>
#include <cstdint>
#include <string>
#include <unordered_set>

namespace ddfcam::gui {

namespace {

vtkSmartPointer<vtkPoints> toPoints(const std::vector<Eigen::Vector3d>& vertices) {
  auto points = vtkSmartPointer<vtkPoints>::New();
  points->SetDataTypeToDouble();
  points->SetNumberOfPoints(static_cast<vtkIdType>(vertices.size()));
  for (std::size_t i = 0; i < vertices.size(); ++i)
    points->SetPoint(static_cast<vtkIdType>(i), vertices[i].data());
  return points;
}

}  // namespace

vtkSmartPointer<vtkPolyData> toSurfacePolyData(const ddf::TriangleMesh& mesh) {
  auto raw = vtkSmartPointer<vtkPolyData>::New();
  raw->SetPoints(toPoints(mesh.vertices));
  auto polys = vtkSmartPointer<vtkCellArray>::New();
  polys->AllocateExact(static_cast<vtkIdType>(mesh.triangles.size()),
                       static_cast<vtkIdType>(3 * mesh.triangles.size()));
  for (const auto& t : mesh.triangles) {
    const vtkIdType ids[3] = {t[0], t[1], t[2]};
    polys->InsertNextCell(3, ids);
  }
  raw->SetPolys(polys);
  if (mesh.triangles.empty()) return raw;

  auto normals = vtkSmartPointer<vtkPolyDataNormals>::New();
  normals->SetInputData(raw);
  normals->SetFeatureAngle(40.0);
  normals->SplittingOn();
  // Orientation is the core's business (front side = counter-clockwise); do not flip it.
  normals->ConsistencyOff();
  normals->AutoOrientNormalsOff();
  normals->ComputePointNormalsOn();
  normals->ComputeCellNormalsOff();
  normals->Update();
  vtkSmartPointer<vtkPolyData> out = normals->GetOutput();
  return out;
}

vtkSmartPointer<vtkPolyData> toWireframePolyData(const ddf::TriangleMesh& mesh) {
  auto poly = vtkSmartPointer<vtkPolyData>::New();
  poly->SetPoints(toPoints(mesh.vertices));
  auto lines = vtkSmartPointer<vtkCellArray>::New();
  std::unordered_set<std::uint64_t> seen;
  seen.reserve(3 * mesh.triangles.size());
  for (const auto& t : mesh.triangles) {
    for (int e = 0; e < 3; ++e) {
      const auto a = static_cast<std::uint32_t>(std::min(t[e], t[(e + 1) % 3]));
      const auto b = static_cast<std::uint32_t>(std::max(t[e], t[(e + 1) % 3]));
      if (!seen.insert((std::uint64_t{a} << 32) | b).second) continue;
      const vtkIdType ids[2] = {a, b};
      lines->InsertNextCell(2, ids);
    }
  }
  poly->SetLines(lines);
  return poly;
}

vtkSmartPointer<vtkPolyData> toSegmentPolyData(const std::vector<Eigen::Vector3d>& from,
                                               const std::vector<Eigen::Vector3d>& to) {
  if (from.size() != to.size())
    throw InvalidInput("toSegmentPolyData: " + std::to_string(from.size()) + " start points but " +
                       std::to_string(to.size()) + " end points");
  const std::size_t count = from.size();
  auto points = vtkSmartPointer<vtkPoints>::New();
  points->SetDataTypeToDouble();
  points->SetNumberOfPoints(static_cast<vtkIdType>(2 * count));
  auto lines = vtkSmartPointer<vtkCellArray>::New();
  lines->AllocateExact(static_cast<vtkIdType>(count), static_cast<vtkIdType>(2 * count));
  for (std::size_t s = 0; s < count; ++s) {
    const auto a = static_cast<vtkIdType>(2 * s);
    points->SetPoint(a, from[s].data());
    points->SetPoint(a + 1, to[s].data());
    const vtkIdType ids[2] = {a, a + 1};
    lines->InsertNextCell(2, ids);
  }
  auto poly = vtkSmartPointer<vtkPolyData>::New();
  poly->SetPoints(points);
  poly->SetLines(lines);
  return poly;
}

}  // namespace ddfcam::gui
