// SPDX-License-Identifier: MIT
// ddfcam gui adapters: LiveSurfacePolyData.
#include <ddfcam/gui/adapters/live_surface.h>
#include <ddfcam/gui/adapters/poly_data.h>

#include <vtkCellArray.h>
#include <vtkCellData.h>
#include <vtkFloatArray.h>
#include <vtkIntArray.h>
#include <vtkPointData.h>
#include <vtkPoints.h>
#include <vtkPolyData.h>
#include <vtkTypeInt32Array.h>

#include <algorithm>
#include <cstring>

namespace ddfcam::gui {

namespace {

void copyFloats(vtkFloatArray* array, const std::vector<float>& values) {
  array->SetNumberOfComponents(3);
  array->SetNumberOfTuples(static_cast<vtkIdType>(values.size() / 3));
  if (!values.empty())
    std::memcpy(array->GetPointer(0), values.data(), values.size() * sizeof(float));
  array->Modified();
}

}  // namespace

LiveSurfacePolyData::LiveSurfacePolyData() : data_(vtkSmartPointer<vtkPolyData>::New()) {
  auto positions = vtkSmartPointer<vtkFloatArray>::New();
  positions->SetNumberOfComponents(3);
  auto points = vtkSmartPointer<vtkPoints>::New();
  points->SetData(positions);
  data_->SetPoints(points);
  auto normals = vtkSmartPointer<vtkFloatArray>::New();
  normals->SetName("Normals");
  normals->SetNumberOfComponents(3);
  data_->GetPointData()->SetNormals(normals);
  auto faces = vtkSmartPointer<vtkIntArray>::New();
  faces->SetName(kFaceArrayName);
  data_->GetCellData()->AddArray(faces);
  auto cells = vtkSmartPointer<vtkCellArray>::New();
  cells->Use32BitStorage();
  data_->SetPolys(cells);
}

void LiveSurfacePolyData::apply(const planning::LiveFrame& frame) {
  auto* positions = vtkFloatArray::SafeDownCast(data_->GetPoints()->GetData());
  copyFloats(positions, frame.positions);
  data_->GetPoints()->Modified();
  copyFloats(vtkFloatArray::SafeDownCast(data_->GetPointData()->GetNormals()), frame.normals);
  const vtkIdType triangles = static_cast<vtkIdType>(frame.triangleFace.size());
  auto offsets = vtkSmartPointer<vtkTypeInt32Array>::New();
  offsets->SetNumberOfValues(triangles + 1);
  for (vtkIdType t = 0; t <= triangles; ++t) offsets->SetValue(t, static_cast<int>(3 * t));
  auto connectivity = vtkSmartPointer<vtkTypeInt32Array>::New();
  connectivity->SetNumberOfValues(3 * triangles);
  if (triangles > 0)
    std::memcpy(connectivity->GetPointer(0), frame.triangles.data(),
                frame.triangles.size() * sizeof(std::int32_t));
  data_->GetPolys()->SetData(offsets, connectivity);
  auto* faces = vtkIntArray::SafeDownCast(data_->GetCellData()->GetArray(kFaceArrayName));
  faces->SetNumberOfValues(triangles);
  if (triangles > 0)
    std::memcpy(faces->GetPointer(0), frame.triangleFace.data(),
                frame.triangleFace.size() * sizeof(std::int32_t));
  faces->Modified();
  data_->Modified();
}

}  // namespace ddfcam::gui
