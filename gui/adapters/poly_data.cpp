// SPDX-License-Identifier: MIT
// ddfcam gui adapters: meshes, segments, poly-lines and arrow glyphs to vtkPolyData.
#include <ddfcam/gui/adapters/poly_data.h>

#include <ddfcam/error.h>

#include <Eigen/Geometry>

#include <vtkCellArray.h>
#include <vtkCellData.h>
#include <vtkDoubleArray.h>
#include <vtkIntArray.h>
#include <vtkPointData.h>
#include <vtkPoints.h>
#include <vtkPolyData.h>
#include <vtkPolyDataNormals.h>

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <numbers>
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

std::vector<int> identityIds(std::size_t count) {
  std::vector<int> values(count);
  for (std::size_t i = 0; i < count; ++i) values[i] = static_cast<int>(i);
  return values;
}

vtkSmartPointer<vtkIntArray> toIntArray(const char* name, std::span<const int> values) {
  auto array = vtkSmartPointer<vtkIntArray>::New();
  array->SetName(name);
  array->SetNumberOfComponents(1);
  array->SetNumberOfTuples(static_cast<vtkIdType>(values.size()));
  for (std::size_t i = 0; i < values.size(); ++i)
    array->SetValue(static_cast<vtkIdType>(i), values[i]);
  return array;
}

constexpr double kHeadFraction = 0.25;  // head stroke length / arrow length
constexpr double kHeadAngleRad = 25.0 * std::numbers::pi / 180.0;

/// A unit vector perpendicular to unit @p d: d crossed with the axis least aligned with it,
/// so the result never degenerates.
Eigen::Vector3d perpendicular(const Eigen::Vector3d& d) {
  Eigen::Index axis = 0;
  d.cwiseAbs().minCoeff(&axis);
  return d.cross(Eigen::Vector3d::Unit(axis)).normalized();
}

}  // namespace

vtkSmartPointer<vtkPolyData> toSurfacePolyData(const ddf::TriangleMesh& mesh) {
  return toSurfacePolyData(mesh, {});
}

vtkSmartPointer<vtkPolyData> toSurfacePolyData(const ddf::TriangleMesh& mesh,
                                               std::span<const int> triangleFace) {
  const bool withFaces = !triangleFace.empty();
  if (withFaces && triangleFace.size() != mesh.triangles.size())
    throw InvalidInput("toSurfacePolyData: " + std::to_string(triangleFace.size()) +
                       " triangle faces for " + std::to_string(mesh.triangles.size()) +
                       " triangles");
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
  // Attribute arrays ride through vtkPolyDataNormals: split points copy their original's
  // "vertex", and cells keep their order and "face".
  raw->GetPointData()->AddArray(toIntArray(kVertexArrayName, identityIds(mesh.vertices.size())));
  if (withFaces) raw->GetCellData()->AddArray(toIntArray(kFaceArrayName, triangleFace));
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

vtkSmartPointer<vtkPolyData> toPolylinePolyData(
    const std::vector<std::vector<Eigen::Vector3d>>& polylines) {
  auto points = vtkSmartPointer<vtkPoints>::New();
  points->SetDataTypeToDouble();
  auto lines = vtkSmartPointer<vtkCellArray>::New();
  auto index = vtkSmartPointer<vtkIntArray>::New();
  index->SetName(kPolylineArrayName);
  for (std::size_t l = 0; l < polylines.size(); ++l) {
    const auto& line = polylines[l];
    if (line.size() < 2) continue;
    lines->InsertNextCell(static_cast<vtkIdType>(line.size()));
    for (const Eigen::Vector3d& p : line) lines->InsertCellPoint(points->InsertNextPoint(p.data()));
    index->InsertNextValue(static_cast<int>(l));
  }
  auto poly = vtkSmartPointer<vtkPolyData>::New();
  poly->SetPoints(points);
  poly->SetLines(lines);
  poly->GetCellData()->AddArray(index);
  return poly;
}

vtkSmartPointer<vtkPolyData> toGlyphPolyData(const std::vector<Eigen::Vector3d>& points,
                                             const std::vector<Eigen::Vector3d>& directions,
                                             double lengthMm) {
  if (points.size() != directions.size())
    throw InvalidInput("toGlyphPolyData: " + std::to_string(points.size()) + " points but " +
                       std::to_string(directions.size()) + " directions");
  if (!(lengthMm > 0.0) || !std::isfinite(lengthMm))
    throw InvalidInput("toGlyphPolyData: arrow length " + std::to_string(lengthMm) +
                       " mm, expected a positive length");
  auto out = vtkSmartPointer<vtkPoints>::New();
  out->SetDataTypeToDouble();
  out->SetNumberOfPoints(static_cast<vtkIdType>(4 * points.size()));
  auto lines = vtkSmartPointer<vtkCellArray>::New();
  lines->AllocateExact(static_cast<vtkIdType>(3 * points.size()),
                       static_cast<vtkIdType>(6 * points.size()));
  const double back = kHeadFraction * lengthMm * std::cos(kHeadAngleRad);
  const double side = kHeadFraction * lengthMm * std::sin(kHeadAngleRad);
  for (std::size_t i = 0; i < points.size(); ++i) {
    const double norm = directions[i].norm();
    if (!(norm > 0.0) || !std::isfinite(norm))
      throw InvalidInput("toGlyphPolyData: direction " + std::to_string(i) +
                         " is zero or not finite");
    const Eigen::Vector3d d = directions[i] / norm;
    const Eigen::Vector3d tip = points[i] + lengthMm * d;
    const Eigen::Vector3d across = perpendicular(d);
    const auto base = static_cast<vtkIdType>(4 * i);
    out->SetPoint(base, points[i].data());
    out->SetPoint(base + 1, tip.data());
    out->SetPoint(base + 2, Eigen::Vector3d(tip - back * d + side * across).data());
    out->SetPoint(base + 3, Eigen::Vector3d(tip - back * d - side * across).data());
    // Shaft base -> tip, then the two head strokes from the tip.
    const vtkIdType cells[3][2] = {{base, base + 1}, {base + 1, base + 2}, {base + 1, base + 3}};
    for (const auto& ids : cells) lines->InsertNextCell(2, ids);
  }
  auto poly = vtkSmartPointer<vtkPolyData>::New();
  poly->SetPoints(out);
  poly->SetLines(lines);
  return poly;
}

}  // namespace ddfcam::gui
