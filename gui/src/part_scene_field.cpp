// SPDX-License-Identifier: MIT
// ddfcam gui: PartScene's field colouring (per display vertex or at raster resolution through a
// texture) and its scalar bar.
#include <ddfcam/error.h>
#include <ddfcam/gui/adapters/poly_data.h>
#include <ddfcam/gui/adapters/raster_field_surface.h>
#include <ddfcam/gui/adapters/tolerance_colours.h>
#include <ddfcam/gui/part_scene.h>

#include "part_scene_look.h"

#include <vtkActor.h>
#include <vtkDataArray.h>
#include <vtkFloatArray.h>
#include <vtkLookupTable.h>
#include <vtkPointData.h>
#include <vtkPolyData.h>
#include <vtkPolyDataMapper.h>
#include <vtkProperty.h>
#include <vtkScalarBarActor.h>
#include <vtkTextProperty.h>

#include <cmath>
#include <string>

namespace ddfcam::gui {

namespace {

using detail::mapperOf;

/// One value per point of @p surface: split points (feature edges) take the value of the mesh
/// vertex they copy ("vertex" point data).
vtkSmartPointer<vtkFloatArray> pointScalars(vtkPolyData* surface,
                                            const std::vector<float>& perVertexValues) {
  vtkDataArray* vertexIds = surface->GetPointData()->GetArray(kVertexArrayName);
  const vtkIdType points = surface->GetNumberOfPoints();
  auto scalars = vtkSmartPointer<vtkFloatArray>::New();
  scalars->SetName("field");
  scalars->SetNumberOfTuples(points);
  for (vtkIdType p = 0; p < points; ++p) {
    const auto v =
        vertexIds ? static_cast<std::size_t>(vertexIds->GetTuple1(p)) : static_cast<std::size_t>(p);
    scalars->SetValue(p, perVertexValues[v]);
  }
  return scalars;
}

/// The lookup table of @p style, using its out-of-range colours only where @p values leave the
/// range (values exactly at an end would otherwise speckle with them after interpolation).
vtkSmartPointer<vtkLookupTable> tableFor(const FieldStyle& style, std::span<const float> values,
                                         std::pair<bool, bool>& outOfRange) {
  vtkSmartPointer<vtkLookupTable> table =
      style.band ? makeToleranceLookupTable(style.lo, style.hi, *style.band)
                 : makeLookupTable(style.map, style.lo, style.hi);
  outOfRange = valuesOutOfRange(values, style.lo, style.hi);
  table->SetUseBelowRangeColor(outOfRange.first ? 1 : 0);
  table->SetUseAboveRangeColor(outOfRange.second ? 1 : 0);
  return table;
}

}  // namespace

long long PartScene::surfaceVertexCount() const {
  if (!surface_) return 0;
  vtkDataArray* ids = surface_->GetPointData()->GetArray(kVertexArrayName);
  if (!ids || ids->GetNumberOfTuples() == 0) return surface_->GetNumberOfPoints();
  return static_cast<long long>(std::llround(ids->GetRange(0)[1])) + 1;
}

void PartScene::setSurfaceField(const std::vector<float>& perVertexValues,
                                const FieldStyle& style) {
  if (!surface_ || surface_->GetNumberOfPoints() == 0)
    throw InvalidInput("setSurfaceField: the scene shows no surface to colour");
  const long long vertices = surfaceVertexCount();
  if (static_cast<long long>(perVertexValues.size()) != vertices)
    throw InvalidInput("setSurfaceField: field '" + style.title + "' has " +
                       std::to_string(perVertexValues.size()) + " values, the surface has " +
                       std::to_string(vertices) + " vertices");
  std::pair<bool, bool> outside;
  vtkSmartPointer<vtkLookupTable> table = tableFor(style, perVertexValues, outside);

  // A shallow copy carries the scalars, so the caller's polydata (shared with PartGeometry)
  // is never modified.
  auto shown = vtkSmartPointer<vtkPolyData>::New();
  shown->ShallowCopy(surface_);
  shown->GetPointData()->SetScalars(pointScalars(surface_, perVertexValues));

  showPlainSurface();
  vtkPolyDataMapper* mapper = mapperOf(actors_[static_cast<int>(Layer::Surface)]);
  mapper->SetInputData(shown);
  mapper->SetLookupTable(table);
  // The table's own range is authoritative; the mapper must not overwrite it.
  mapper->UseLookupTableScalarRangeOn();
  mapper->SetScalarModeToUsePointData();
  mapper->SetColorModeToMapScalars();
  // Colours interpolated in value space (a 1D texture) keep a sharp map across big triangles.
  mapper->InterpolateScalarsBeforeMappingOn();
  mapper->ScalarVisibilityOn();
  showScalarBar(table, style, outside);
}

bool PartScene::showsRasterFields() const {
  return cornerParams_ && surface_ && RasterFieldSurface::available(rasterFaces_, rasterSteps_);
}

void PartScene::setSurfaceRasterField(std::span<const float> rasterValues,
                                      const FieldStyle& style) {
  if (!showsRasterFields())
    throw InvalidInput("setSurfaceRasterField: the surface has no raster positions to colour");
  if (!rasterField_)
    rasterField_ = std::make_unique<RasterFieldSurface>(surface_, *cornerParams_, rasterFaces_,
                                                        rasterSteps_);
  std::pair<bool, bool> outside;
  vtkSmartPointer<vtkLookupTable> table = tableFor(style, rasterValues, outside);
  rasterField_->setValues(rasterValues, table);

  vtkActor* surfaceActor = actors_[static_cast<int>(Layer::Surface)];
  vtkPolyDataMapper* mapper = mapperOf(surfaceActor);
  mapper->ScalarVisibilityOff();
  mapper->SetInputData(rasterField_->polyData());
  mapper->SetLookupTable(table);  // scalarRange() reads it
  surfaceActor->SetTexture(rasterField_->texture());
  surfaceActor->GetProperty()->SetColor(1.0, 1.0, 1.0);  // the texture's colours, lit
  showScalarBar(table, style, outside);
}

const RasterTextureAtlas* PartScene::rasterFieldAtlas() const {
  return fieldShown_ && rasterField_ &&
                 actors_[static_cast<int>(Layer::Surface)]->GetTexture() == rasterField_->texture()
             ? &rasterField_->atlas()
             : nullptr;
}

void PartScene::showScalarBar(vtkLookupTable* table, const FieldStyle& style,
                              std::pair<bool, bool> outOfRange) {
  scalarBar_->SetDrawBelowRangeSwatch(outOfRange.first);
  scalarBar_->SetDrawAboveRangeSwatch(outOfRange.second);
  scalarBar_->SetLookupTable(table);
  scalarBar_->SetLabelFormat(scaleLabelFormat(style.lo, style.hi).c_str());
  scalarBar_->SetTitle(style.title.c_str());
  if (style.stale)
    scalarBar_->GetTitleTextProperty()->SetColor(1.0, 0.62, 0.15);
  else
    scalarBar_->GetTitleTextProperty()->SetColor(0.93, 0.93, 0.93);
  scalarBar_->SetVisibility(1);
  fieldShown_ = true;
}

void PartScene::clearSurfaceField() {
  vtkPolyDataMapper* mapper = mapperOf(actors_[static_cast<int>(Layer::Surface)]);
  mapper->ScalarVisibilityOff();
  if (fieldShown_) {
    mapper->SetInputData(surface_ ? surface_.Get() : vtkSmartPointer<vtkPolyData>::New().Get());
    showPlainSurface();
  }
  scalarBar_->SetVisibility(0);
  scalarBar_->SetTitle("");
  fieldShown_ = false;
}

bool PartScene::isFieldShown() const {
  return fieldShown_;
}

std::string PartScene::scalarBarTitle() const {
  const char* title = scalarBar_->GetTitle();
  return fieldShown_ && title ? std::string(title) : std::string();
}

ValueRange PartScene::scalarRange() const {
  if (!fieldShown_) return {0.0, 0.0};
  const double* range =
      mapperOf(actors_[static_cast<int>(Layer::Surface)])->GetLookupTable()->GetRange();
  return {range[0], range[1]};
}

}  // namespace ddfcam::gui
