// SPDX-License-Identifier: MIT
// ddfcam gui adapters: LiveSurfacePolyData.
#include <ddfcam/gui/adapters/live_surface.h>
#include <ddfcam/gui/adapters/poly_data.h>

#include <vtkCallbackCommand.h>
#include <vtkCellArray.h>
#include <vtkCellData.h>
#include <vtkFloatArray.h>
#include <vtkIntArray.h>
#include <vtkPointData.h>
#include <vtkPoints.h>
#include <vtkPolyData.h>
#include <vtkRenderer.h>
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

LiveSurfacePolyData::LiveSurfacePolyData(int faceCount, int rasterSteps)
    : data_(vtkSmartPointer<vtkPolyData>::New()) {
  if (RasterTextureAtlas::fits(faceCount, rasterSteps))
    atlas_ = std::make_unique<RasterTextureAtlas>(faceCount, rasterSteps);
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
  auto tcoords = vtkSmartPointer<vtkFloatArray>::New();
  tcoords->SetName("tolerance texture coordinates");
  tcoords->SetNumberOfComponents(2);
  data_->GetPointData()->SetTCoords(tcoords);
}

LiveSurfacePolyData::~LiveSurfacePolyData() {
  if (renderer_) renderer_->RemoveObserver(observer_);
}

void LiveSurfacePolyData::uploadBeforeRendering(vtkRenderer* renderer) {
  if (!atlas_ || !renderer) return;
  if (renderer_) renderer_->RemoveObserver(observer_);
  renderer_ = renderer;
  auto command = vtkSmartPointer<vtkCallbackCommand>::New();
  command->SetClientData(atlas_.get());
  command->SetCallback([](vtkObject*, unsigned long, void* atlas, void*) {
    static_cast<RasterTextureAtlas*>(atlas)->uploadChanged();
  });
  observer_ = renderer->AddObserver(vtkCommand::StartEvent, command);
}

vtkTexture* LiveSurfacePolyData::texture() const {
  return atlas_ ? atlas_->texture() : nullptr;
}

void LiveSurfacePolyData::apply(const planning::LiveFrame& frame) {
  const bool textured = atlas_ && !frame.toleranceClasses.empty() &&
                        frame.cornerParams.size() == 2 * frame.triangles.size();
  if (textured)
    applyTextured(frame);
  else
    applyShared(frame);
}

void LiveSurfacePolyData::applyTextured(const planning::LiveFrame& frame) {
  atlas_->setClasses(frame.toleranceClasses);
  // One point per (vertex slot, support face): the triangles of a face share their corners,
  // only a slot on a face border gets a copy per face (its texture coordinates differ there).
  const std::size_t corners = frame.triangles.size();
  slotFace_.assign(frame.positions.size() / 3, -1);
  slotPoint_.resize(slotFace_.size());
  connectivity_.resize(corners);
  points_.clear();
  for (std::size_t c = 0; c < corners; ++c) {
    const auto slot = static_cast<std::size_t>(frame.triangles[c]);
    const int face = frame.triangleFace[c / 3];
    if (slotFace_[slot] != face) {
      slotFace_[slot] = face;
      slotPoint_[slot] = static_cast<int>(points_.size());
      points_.push_back(c);
    }
    connectivity_[c] = slotPoint_[slot];
  }
  auto* positions = vtkFloatArray::SafeDownCast(data_->GetPoints()->GetData());
  auto* normals = vtkFloatArray::SafeDownCast(data_->GetPointData()->GetNormals());
  auto* tcoords = vtkFloatArray::SafeDownCast(data_->GetPointData()->GetTCoords());
  for (vtkFloatArray* a : {positions, normals, tcoords})
    a->SetNumberOfTuples(static_cast<vtkIdType>(points_.size()));
  float* p = positions->GetPointer(0);
  float* n = normals->GetPointer(0);
  float* t = tcoords->GetPointer(0);
  for (std::size_t i = 0; i < points_.size(); ++i) {
    const std::size_t c = points_[i];
    const std::size_t slot = 3 * static_cast<std::size_t>(frame.triangles[c]);
    std::memcpy(p + 3 * i, frame.positions.data() + slot, 3 * sizeof(float));
    std::memcpy(n + 3 * i, frame.normals.data() + slot, 3 * sizeof(float));
    const auto st = atlas_->texCoord(frame.triangleFace[c / 3], frame.cornerParams[2 * c],
                                     frame.cornerParams[2 * c + 1]);
    t[2 * i] = st[0];
    t[2 * i + 1] = st[1];
  }
  for (vtkFloatArray* a : {positions, normals, tcoords}) a->Modified();
  data_->GetPoints()->Modified();
  setCells(frame, connectivity_);
}

void LiveSurfacePolyData::applyShared(const planning::LiveFrame& frame) {
  auto* positions = vtkFloatArray::SafeDownCast(data_->GetPoints()->GetData());
  copyFloats(positions, frame.positions);
  data_->GetPoints()->Modified();
  copyFloats(vtkFloatArray::SafeDownCast(data_->GetPointData()->GetNormals()), frame.normals);
  vtkFloatArray::SafeDownCast(data_->GetPointData()->GetTCoords())->SetNumberOfTuples(0);
  setCells(frame, frame.triangles);
}

void LiveSurfacePolyData::setCells(const planning::LiveFrame& frame,
                                   const std::vector<std::int32_t>& corners) {
  const vtkIdType triangles = static_cast<vtkIdType>(frame.triangleFace.size());
  auto offsets = vtkSmartPointer<vtkTypeInt32Array>::New();
  offsets->SetNumberOfValues(triangles + 1);
  for (vtkIdType t = 0; t <= triangles; ++t) offsets->SetValue(t, static_cast<int>(3 * t));
  auto connectivity = vtkSmartPointer<vtkTypeInt32Array>::New();
  connectivity->SetNumberOfValues(3 * triangles);
  if (triangles > 0)
    std::memcpy(connectivity->GetPointer(0), corners.data(), corners.size() * sizeof(std::int32_t));
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
