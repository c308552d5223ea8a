// SPDX-License-Identifier: MIT
// ddfcam gui: MouldView's secondary surface, overlay lines, highlight and picking.
#include <ddfcam/gui/mould_view.h>

#include "mould_view_scene.h"

#include <ddfcam/error.h>
#include <ddfcam/gui/adapters/colour_map.h>
#include <ddfcam/gui/adapters/poly_data.h>
#include <ddfcam/gui/vtk_view.h>

#include <vtkActor.h>
#include <vtkCellData.h>
#include <vtkCellLocator.h>
#include <vtkCellPicker.h>
#include <vtkFloatArray.h>
#include <vtkLookupTable.h>
#include <vtkPointData.h>
#include <vtkPoints.h>
#include <vtkProperty.h>
#include <vtkRenderer.h>

#include <algorithm>
#include <cmath>

namespace ddfcam::gui {
namespace {

using mould_view_detail::mapperOf;
using mould_view_detail::rawPolyData;

/// @throws InvalidInput if @p field has not one value per triangle (per cell) or per vertex.
void checkFieldSize(const ddf::TriangleMesh& mesh, const planning::MeshField& field) {
  const std::size_t expected = field.perCell ? mesh.triangles.size() : mesh.vertices.size();
  if (field.values.size() != expected)
    throw InvalidInput("mould view: field '" + field.name + "' has " +
                       std::to_string(field.values.size()) + " values, the formed mesh needs " +
                       std::to_string(expected));
}

vtkSmartPointer<vtkFloatArray> fieldArray(const planning::MeshField& field) {
  auto values = vtkSmartPointer<vtkFloatArray>::New();
  values->SetName(field.name.c_str());
  values->SetNumberOfValues(static_cast<vtkIdType>(field.values.size()));
  for (std::size_t i = 0; i < field.values.size(); ++i)
    values->SetValue(static_cast<vtkIdType>(i), field.values[i]);
  return values;
}

// The colour range over the finite values (NaN and infinities have no colour of their own).
ValueRange finiteRange(const std::vector<float>& values) {
  double lo = INFINITY, hi = -INFINITY;
  for (float v : values)
    if (std::isfinite(v)) {
      lo = std::min(lo, static_cast<double>(v));
      hi = std::max(hi, static_cast<double>(v));
    }
  if (!(lo <= hi)) lo = hi = 0.0;
  return defaultRange(lo, hi, false);
}

}  // namespace

void MouldView::showSecondary(const ddf::TriangleMesh& mesh, const planning::MeshField* field) {
  if (field != nullptr) checkFieldSize(mesh, *field);
  const bool first = scene_->secondaryData->GetNumberOfPoints() == 0 &&
                     scene_->primaryData->GetNumberOfPoints() == 0;
  scene_->secondaryData = rawPolyData(mesh);
  scene_->secondaryNormals->SetInputData(scene_->secondaryData);
  scene_->locators[kSecondary] = nullptr;
  mapperOf(scene_->secondary)->ScalarVisibilityOff();
  scene_->secondaryBar->SetVisibility(0);
  if (field != nullptr && !field->values.empty()) colourSecondary(*field);
  scene_->secondary->SetVisibility(!mesh.triangles.empty());
  scene_->overlay->SetVisibility(layout_ == Layout::Overlay && !mesh.triangles.empty());
  if (first && !mesh.triangles.empty()) fitCameras();
  primary_->requestRender();
  secondary_->requestRender();
}

void MouldView::colourSecondary(const planning::MeshField& field) {
  const ValueRange range = finiteRange(field.values);
  vtkPolyDataMapper* mapper = mapperOf(scene_->secondary);
  if (field.perCell) {
    scene_->secondaryData->GetCellData()->SetScalars(fieldArray(field));
    mapper->SetScalarModeToUseCellData();
  } else {
    scene_->secondaryData->GetPointData()->SetScalars(fieldArray(field));
    mapper->SetScalarModeToUsePointData();
  }
  vtkSmartPointer<vtkLookupTable> table = makeLookupTable(ColourMap::Viridis, range.lo, range.hi);
  mapper->SetLookupTable(table);
  mapper->SetScalarRange(range.lo, range.hi);
  mapper->ScalarVisibilityOn();
  const std::string title = field.name + (field.unit.empty() ? "" : " [" + field.unit + "]");
  scene_->secondaryBar->SetLookupTable(table);
  scene_->secondaryBar->SetTitle(title.c_str());
  scene_->secondaryBar->SetLabelFormat(scaleLabelFormat(range.lo, range.hi).c_str());
  scene_->secondaryBar->SetVisibility(1);
}

bool MouldView::updateSecondaryPoints(const std::vector<Eigen::Vector3d>& vertices) {
  vtkPoints* points = scene_->secondaryData->GetPoints();
  if (points == nullptr || points->GetNumberOfPoints() != static_cast<vtkIdType>(vertices.size()))
    return false;
  for (std::size_t i = 0; i < vertices.size(); ++i)
    points->SetPoint(static_cast<vtkIdType>(i), vertices[i].data());
  points->Modified();
  scene_->secondaryData->Modified();
  scene_->locators[kSecondary] = nullptr;
  primary_->requestRender();
  secondary_->requestRender();
  return true;
}

void MouldView::showOverlayLines(const std::vector<std::vector<Eigen::Vector3d>>& polylines,
                                 const Eigen::Vector3d& rgb) {
  auto make = [&](vtkSmartPointer<vtkActor>& actor, VtkView& view) {
    if (actor) view.renderer()->RemoveActor(actor);
    actor = nullptr;
    if (polylines.empty()) return;
    auto mapper = vtkSmartPointer<vtkPolyDataMapper>::New();
    mapper->SetInputData(toPolylinePolyData(polylines));
    mapper->ScalarVisibilityOff();
    actor = vtkSmartPointer<vtkActor>::New();
    actor->SetMapper(mapper);
    actor->GetProperty()->SetColor(rgb.x(), rgb.y(), rgb.z());
    actor->GetProperty()->SetLineWidth(3.0f);
    actor->GetProperty()->LightingOff();
    actor->PickableOff();
    view.renderer()->AddActor(actor);
    view.requestRender();
  };
  make(scene_->linesPrimary, *primary_);
  make(scene_->linesSecondary, *secondary_);
  primary_->requestRender();
  secondary_->requestRender();
}

void MouldView::showHighlightedTriangles(const std::vector<int>& triangles) {
  if (scene_->highlight) primary_->renderer()->RemoveActor(scene_->highlight);
  scene_->highlight = nullptr;
  const ddf::TriangleMesh& mesh = scene_->primaryMesh;
  ddf::TriangleMesh subset;
  subset.vertices = mesh.vertices;
  for (int t : triangles)
    if (t >= 0 && t < static_cast<int>(mesh.triangles.size()))
      subset.triangles.push_back(mesh.triangles[static_cast<std::size_t>(t)]);
  if (!subset.triangles.empty()) {
    auto mapper = vtkSmartPointer<vtkPolyDataMapper>::New();
    mapper->SetInputData(toWireframePolyData(subset));
    mapper->ScalarVisibilityOff();
    scene_->highlight = vtkSmartPointer<vtkActor>::New();
    scene_->highlight->SetMapper(mapper);
    scene_->highlight->GetProperty()->SetColor(1.0, 0.0, 1.0);
    scene_->highlight->GetProperty()->SetLineWidth(2.0f);
    scene_->highlight->GetProperty()->LightingOff();
    scene_->highlight->PickableOff();
    primary_->renderer()->AddActor(scene_->highlight);
  }
  primary_->requestRender();
}

int MouldView::secondaryPointCount() const {
  return static_cast<int>(scene_->secondaryData->GetNumberOfPoints());
}

Eigen::Vector3d MouldView::secondaryPoint(int i) const {
  Eigen::Vector3d p;
  scene_->secondaryData->GetPoint(i, p.data());
  return p;
}

std::optional<Eigen::Vector3d> MouldView::pickAt(int view, QPointF widgetPos) {
  const bool primary = view == kPrimary;
  VtkView& v = primary ? *primary_ : *secondary_;
  vtkActor* actor = primary ? scene_->primary.Get() : scene_->secondary.Get();
  if (!actor->GetVisibility()) return std::nullopt;
  scene_->primaryNormals->Update();
  scene_->secondaryNormals->Update();
  vtkDataSet* data = mapperOf(actor)->GetInput();
  if (data == nullptr || data->GetNumberOfCells() == 0) return std::nullopt;
  // A locator makes the picker return the nearest hit along the ray, not the back side.
  vtkSmartPointer<vtkCellLocator>& locator = scene_->locators[primary ? 0 : 1];
  if (!locator || locator->GetDataSet() != data) {
    locator = vtkSmartPointer<vtkCellLocator>::New();
    locator->SetDataSet(data);
    locator->BuildLocator();
  }
  const Eigen::Vector2d display = v.displayPosition(widgetPos);
  auto picker = vtkSmartPointer<vtkCellPicker>::New();
  picker->PickFromListOn();
  picker->AddPickList(actor);
  picker->AddLocator(locator);
  if (!picker->Pick(display.x(), display.y(), 0.0, v.renderer()) || picker->GetCellId() < 0)
    return std::nullopt;
  Eigen::Vector3d point;
  picker->GetPickPosition(point.data());
  emit pointPicked(view, point);
  return point;
}

}  // namespace ddfcam::gui
