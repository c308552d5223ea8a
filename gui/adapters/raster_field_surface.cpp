// SPDX-License-Identifier: MIT
// ddfcam gui adapters: RasterFieldSurface.
#include <ddfcam/error.h>
#include <ddfcam/gui/adapters/poly_data.h>
#include <ddfcam/gui/adapters/raster_field_surface.h>

#include <vtkCellArray.h>
#include <vtkCellData.h>
#include <vtkDataArray.h>
#include <vtkFloatArray.h>
#include <vtkIdList.h>
#include <vtkIntArray.h>
#include <vtkLookupTable.h>
#include <vtkPointData.h>
#include <vtkPoints.h>
#include <vtkTypeInt32Array.h>

#include <cstdint>
#include <cstring>
#include <string>
#include <vector>

namespace ddfcam::gui {

namespace {

vtkSmartPointer<vtkFloatArray> floatArray(const char* name, int components, vtkIdType tuples) {
  auto a = vtkSmartPointer<vtkFloatArray>::New();
  a->SetName(name);
  a->SetNumberOfComponents(components);
  a->SetNumberOfTuples(tuples);
  return a;
}

/// Triangle cells whose corners are points 3t, 3t + 1, 3t + 2.
vtkSmartPointer<vtkCellArray> ownCornerCells(vtkIdType triangles) {
  auto offsets = vtkSmartPointer<vtkTypeInt32Array>::New();
  offsets->SetNumberOfValues(triangles + 1);
  for (vtkIdType t = 0; t <= triangles; ++t) offsets->SetValue(t, static_cast<int>(3 * t));
  auto connectivity = vtkSmartPointer<vtkTypeInt32Array>::New();
  connectivity->SetNumberOfValues(3 * triangles);
  for (vtkIdType c = 0; c < 3 * triangles; ++c) connectivity->SetValue(c, static_cast<int>(c));
  auto cells = vtkSmartPointer<vtkCellArray>::New();
  cells->SetData(offsets, connectivity);
  return cells;
}

struct Sources {
  vtkDataArray* normals;
  vtkDataArray* vertexIds;
  vtkDataArray* faces;
};

Sources sourcesOf(vtkPolyData* surface, std::span<const float> cornerParams, int faces) {
  const vtkIdType triangles = surface->GetNumberOfCells();
  Sources s{surface->GetPointData()->GetNormals(),
            surface->GetPointData()->GetArray(kVertexArrayName),
            surface->GetCellData()->GetArray(kFaceArrayName)};
  if (!s.faces || s.faces->GetNumberOfTuples() != triangles)
    throw InvalidInput("RasterFieldSurface: the surface has no '" + std::string(kFaceArrayName) +
                       "' value per triangle");
  if (static_cast<vtkIdType>(cornerParams.size()) != 6 * triangles)
    throw InvalidInput("RasterFieldSurface: " + std::to_string(cornerParams.size()) +
                       " corner parameters for " + std::to_string(triangles) +
                       " triangles (6 each expected)");
  const double* range = s.faces->GetRange(0);
  if (triangles > 0 && (range[0] < 0 || range[1] >= faces))
    throw InvalidInput("RasterFieldSurface: a triangle names support face " +
                       std::to_string(static_cast<long long>(range[1])) + " of " +
                       std::to_string(faces));
  return s;
}

}  // namespace

bool RasterFieldSurface::available(int faces, int steps) {
  return RasterTextureAtlas::fits(faces, steps);
}

RasterFieldSurface::RasterFieldSurface(vtkPolyData* surface, std::span<const float> cornerParams,
                                       int faces, int steps)
    : atlas_(faces, steps), data_(vtkSmartPointer<vtkPolyData>::New()) {
  const Sources src = sourcesOf(surface, cornerParams, faces);
  const vtkIdType triangles = surface->GetNumberOfCells();
  auto positions = floatArray("positions", 3, 3 * triangles);
  auto normals = floatArray("Normals", 3, src.normals ? 3 * triangles : 0);
  auto tcoords = floatArray("field texture coordinates", 2, 3 * triangles);
  auto vertexIds = vtkSmartPointer<vtkIntArray>::New();
  vertexIds->SetName(kVertexArrayName);
  vertexIds->SetNumberOfValues(src.vertexIds ? 3 * triangles : 0);
  auto cellFaces = vtkSmartPointer<vtkIntArray>::New();
  cellFaces->SetName(kFaceArrayName);
  cellFaces->SetNumberOfValues(triangles);
  auto corners = vtkSmartPointer<vtkIdList>::New();
  for (vtkIdType t = 0; t < triangles; ++t) {
    surface->GetCellPoints(t, corners);
    if (corners->GetNumberOfIds() != 3)
      throw InvalidInput("RasterFieldSurface: cell " + std::to_string(t) + " is no triangle");
    const int face = static_cast<int>(src.faces->GetTuple1(t));
    cellFaces->SetValue(t, face);
    for (int c = 0; c < 3; ++c) {
      const vtkIdType from = corners->GetId(c), to = 3 * t + c;
      positions->SetTuple(to, surface->GetPoint(from));
      if (src.normals) normals->SetTuple(to, src.normals->GetTuple(from));
      if (src.vertexIds) vertexIds->SetValue(to, static_cast<int>(src.vertexIds->GetTuple1(from)));
      const auto st = atlas_.texCoord(face, cornerParams[6 * t + 2 * c], cornerParams[6 * t + 2 * c + 1]);
      tcoords->SetTuple2(to, st[0], st[1]);
    }
  }
  auto points = vtkSmartPointer<vtkPoints>::New();
  points->SetData(positions);
  data_->SetPoints(points);
  data_->SetPolys(ownCornerCells(triangles));
  if (src.normals) data_->GetPointData()->SetNormals(normals);
  if (src.vertexIds) data_->GetPointData()->AddArray(vertexIds);
  data_->GetPointData()->SetTCoords(tcoords);
  data_->GetCellData()->AddArray(cellFaces);
}

RasterFieldSurface::~RasterFieldSurface() = default;

void RasterFieldSurface::setValues(std::span<const float> values, vtkLookupTable* table) {
  std::vector<std::uint8_t> rgba(4 * values.size());
  for (std::size_t p = 0; p < values.size(); ++p)
    std::memcpy(rgba.data() + 4 * p, table->MapValue(static_cast<double>(values[p])), 4);
  for (std::size_t p = 0; p < values.size(); ++p) rgba[4 * p + 3] = 255;  // opacity: the actor's
  atlas_.setColours(rgba);
}

std::pair<bool, bool> valuesOutOfRange(std::span<const float> values, double lo, double hi) {
  const double slack = 1e-6 * (hi - lo);
  bool below = false, above = false;
  for (float v : values) {
    below = below || v < lo - slack;
    above = above || v > hi + slack;
  }
  return {below, above};
}

}  // namespace ddfcam::gui
