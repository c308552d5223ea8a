// SPDX-License-Identifier: MIT
// ddfcam gui: PartScene actors and their look, the field colouring and its scalar bar.
#include <ddfcam/gui/part_scene.h>

#include <ddfcam/error.h>
#include <ddfcam/gui/adapters/poly_data.h>
#include <ddfcam/gui/adapters/tolerance_colours.h>
#include <ddfcam/gui/vtk_view.h>

#include "scalar_bar.h"

#include <vtkActor.h>
#include <vtkCellData.h>
#include <vtkCellLocator.h>
#include <vtkCellPicker.h>
#include <vtkDataArray.h>
#include <vtkFloatArray.h>
#include <vtkLookupTable.h>
#include <vtkPointData.h>
#include <vtkPolyData.h>
#include <vtkPolyDataMapper.h>
#include <vtkProperty.h>
#include <vtkRenderWindow.h>
#include <vtkRenderer.h>
#include <vtkRendererCollection.h>
#include <vtkScalarBarActor.h>
#include <vtkTextProperty.h>

#include <algorithm>
#include <cmath>
#include <string>
#include <utility>

namespace ddfcam::gui {

namespace {

vtkSmartPointer<vtkActor> makeActor() {
  auto mapper = vtkSmartPointer<vtkPolyDataMapper>::New();
  mapper->ScalarVisibilityOff();
  mapper->SetInputData(vtkSmartPointer<vtkPolyData>::New());
  auto actor = vtkSmartPointer<vtkActor>::New();
  actor->SetMapper(mapper);
  return actor;
}

vtkPolyDataMapper* mapperOf(vtkActor* actor) {
  return vtkPolyDataMapper::SafeDownCast(actor->GetMapper());
}

void styleSurface(vtkProperty* p) {
  p->SetColor(0.80, 0.72, 0.55);  // brushed brass: grinding targets are metal
  p->SetAmbient(0.10);
  p->SetDiffuse(0.80);
  p->SetSpecular(0.25);
  p->SetSpecularPower(30.0);
  p->SetInterpolationToPhong();
  // Back faces (the inside of the crust) in a darker tone so open parts read correctly.
  p->BackfaceCullingOff();
}

void styleLines(vtkProperty* p, double r, double g, double b, float width) {
  p->SetColor(r, g, b);
  p->SetLineWidth(width);
  p->LightingOff();
  p->SetRepresentationToWireframe();
}

/// Path of the first existing file of @p candidates, or "".
/// Whether any value lies clearly below @p lo / above @p hi: interpolation at display vertices
/// puts values that sit on an end of the range a rounding error beyond it (-1e-17 for 0).
std::pair<bool, bool> outOfRange(const std::vector<float>& values, double lo, double hi) {
  const double slack = 1e-6 * (hi - lo);
  bool below = false, above = false;
  for (float v : values) {
    below = below || v < lo - slack;
    above = above || v > hi + slack;
  }
  return {below, above};
}

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

/// The renderer of layer 1 in @p renderer's window, or @p renderer if there is none.
vtkRenderer* layerOneRenderer(vtkRenderer* renderer) {
  vtkRenderWindow* window = renderer->GetRenderWindow();
  if (!window) return renderer;
  vtkRendererCollection* renderers = window->GetRenderers();
  renderers->InitTraversal();
  while (vtkRenderer* candidate = renderers->GetNextItem())
    if (candidate->GetLayer() == 1) return candidate;
  return renderer;
}

void applyOverlayStyle(vtkActor* actor, const OverlayStyle& style) {
  vtkProperty* p = actor->GetProperty();
  p->SetColor(style.rgb[0], style.rgb[1], style.rgb[2]);
  p->SetOpacity(std::clamp(style.opacity, 0.0, 1.0));
  p->SetLineWidth(static_cast<float>(style.lineWidth));
  p->SetPointSize(static_cast<float>(style.pointSize));
  if (style.surface) {
    p->SetRepresentationToSurface();
    p->LightingOn();
    p->SetAmbient(0.15);
    p->SetDiffuse(0.80);
    p->SetSpecular(0.20);
  } else {
    p->SetRepresentationToWireframe();
    p->LightingOff();
  }
}

}  // namespace

PartScene::PartScene(vtkRenderer* renderer, vtkRenderer* annotationRenderer)
    : renderer_(renderer), annotationRenderer_(annotationRenderer) {
  if (!annotationRenderer_) annotationRenderer_ = layerOneRenderer(renderer);
  for (auto& actor : actors_) {
    actor = makeActor();
    renderer_->AddActor(actor);
  }
  vtkActor* surface = actors_[static_cast<int>(Layer::Surface)];
  styleSurface(surface->GetProperty());
  auto back = vtkSmartPointer<vtkProperty>::New();
  back->DeepCopy(surface->GetProperty());
  back->SetColor(0.45, 0.33, 0.30);
  surface->SetBackfaceProperty(back);
  styleLines(actors_[static_cast<int>(Layer::Support)]->GetProperty(), 0.35, 0.85, 1.0, 1.0f);
  styleLines(actors_[static_cast<int>(Layer::Stubbles)]->GetProperty(), 1.0, 0.45, 0.25, 1.0f);
  // Lines drawn on top of the surface they lie in would z-fight with it.
  for (Layer layer : {Layer::Support, Layer::Stubbles}) {
    auto* mapper = mapperOf(actors_[static_cast<int>(layer)]);
    mapper->SetResolveCoincidentTopologyToPolygonOffset();
    mapper->SetRelativeCoincidentTopologyLineOffsetParameters(0.0, -4.0);
    actors_[static_cast<int>(layer)]->PickableOff();
  }
  scalarBar_ = makeScalarBar();
  annotationRenderer_->AddActor2D(scalarBar_);
  setVisible(Layer::Surface, true);
  setVisible(Layer::Support, false);
  setVisible(Layer::Stubbles, false);
}

PartScene::~PartScene() {
  for (auto& actor : actors_) renderer_->RemoveActor(actor);
  for (auto& [name, actor] : overlays_) renderer_->RemoveActor(actor);
  annotationRenderer_->RemoveActor2D(scalarBar_);
}

void PartScene::setGeometry(const SceneGeometry& geometry) {
  clearSurfaceField();
  surface_ = geometry.surface;
  vtkActor* surfaceActor = actors_[static_cast<int>(Layer::Surface)];
  surfaceActor->SetTexture(geometry.surfaceTexture);
  if (geometry.surfaceTexture)
    surfaceActor->GetProperty()->SetColor(1.0, 1.0, 1.0);  // the texture's colours, lit
  else
    styleSurface(surfaceActor->GetProperty());
  const std::array<vtkPolyData*, kLayerCount> data = {geometry.surface, geometry.support,
                                                      geometry.stubbles};
  for (int l = 0; l < kLayerCount; ++l) {
    if (data[l])
      mapperOf(actors_[l])->SetInputData(data[l]);
    else
      mapperOf(actors_[l])->SetInputData(vtkSmartPointer<vtkPolyData>::New());
  }
}

void PartScene::setVisible(Layer layer, bool visible) {
  actors_[static_cast<int>(layer)]->SetVisibility(visible ? 1 : 0);
  // The support usually lies under the represented surface (heights > 0 on stock); a
  // see-through surface keeps the wireframe visible without losing the shape.
  const bool support = isVisible(Layer::Support);
  actors_[static_cast<int>(Layer::Surface)]->GetProperty()->SetOpacity(support ? 0.55 : 1.0);
}

bool PartScene::isVisible(Layer layer) const {
  return actors_[static_cast<int>(layer)]->GetVisibility() != 0;
}

long long PartScene::cellCount(Layer layer) const {
  auto* mapper = mapperOf(actors_[static_cast<int>(layer)]);
  auto* data = mapper ? mapper->GetInput() : nullptr;
  return data ? static_cast<long long>(data->GetNumberOfCells()) : 0;
}

vtkActor* PartScene::actor(Layer layer) const {
  return actors_[static_cast<int>(layer)];
}

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
  vtkSmartPointer<vtkLookupTable> table =
      style.band ? makeToleranceLookupTable(style.lo, style.hi, *style.band)
                 : makeLookupTable(style.map, style.lo, style.hi);
  // Out-of-range colours only when values are out of range: with colours interpolated before
  // mapping, values exactly at an end of the range would otherwise speckle with them.
  const auto [below, above] = outOfRange(perVertexValues, style.lo, style.hi);
  table->SetUseBelowRangeColor(below ? 1 : 0);
  table->SetUseAboveRangeColor(above ? 1 : 0);
  scalarBar_->SetDrawBelowRangeSwatch(below);
  scalarBar_->SetDrawAboveRangeSwatch(above);

  // A shallow copy carries the scalars, so the caller's polydata (shared with PartGeometry)
  // is never modified.
  auto shown = vtkSmartPointer<vtkPolyData>::New();
  shown->ShallowCopy(surface_);
  shown->GetPointData()->SetScalars(pointScalars(surface_, perVertexValues));

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
  if (fieldShown_)
    mapper->SetInputData(surface_ ? surface_.Get() : vtkSmartPointer<vtkPolyData>::New().Get());
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

void PartScene::setOverlay(const std::string& name, vtkSmartPointer<vtkPolyData> data,
                           const OverlayStyle& style) {
  auto& actor = overlays_[name];
  if (!actor) {
    actor = makeActor();
    auto* mapper = mapperOf(actor);
    // Paths and markers lie on the surface; pull them towards the camera so they stay visible.
    mapper->SetResolveCoincidentTopologyToPolygonOffset();
    mapper->SetRelativeCoincidentTopologyLineOffsetParameters(0.0, -6.0);
    mapper->SetRelativeCoincidentTopologyPointOffsetParameter(-6.0);
    actor->PickableOff();
  }
  // On-top overlays live in the annotation layer, whose depth buffer starts empty; it shares
  // the 3D camera so they stay registered with the part.
  renderer_->RemoveActor(actor);
  annotationRenderer_->RemoveActor(actor);
  if (style.onTop) {
    annotationRenderer_->SetActiveCamera(renderer_->GetActiveCamera());
    annotationRenderer_->AddActor(actor);
  } else {
    renderer_->AddActor(actor);
  }
  mapperOf(actor)->SetInputData(data ? data : vtkSmartPointer<vtkPolyData>::New());
  applyOverlayStyle(actor, style);
}

bool PartScene::removeOverlay(const std::string& name) {
  const auto it = overlays_.find(name);
  if (it == overlays_.end()) return false;
  renderer_->RemoveActor(it->second);
  annotationRenderer_->RemoveActor(it->second);
  overlays_.erase(it);
  return true;
}

vtkActor* PartScene::overlayActor(const std::string& name, const char* caller) const {
  const auto it = overlays_.find(name);
  if (it == overlays_.end())
    throw InvalidInput(std::string(caller) + ": there is no overlay '" + name + "'");
  return it->second;
}

void PartScene::setOverlayVisible(const std::string& name, bool visible) {
  overlayActor(name, "setOverlayVisible")->SetVisibility(visible ? 1 : 0);
}

bool PartScene::isOverlayVisible(const std::string& name) const {
  return overlayActor(name, "isOverlayVisible")->GetVisibility() != 0;
}

bool PartScene::hasOverlay(const std::string& name) const {
  return overlays_.count(name) != 0;
}

std::vector<std::string> PartScene::overlayNames() const {
  std::vector<std::string> names;
  names.reserve(overlays_.size());
  for (const auto& entry : overlays_) names.push_back(entry.first);
  return names;  // std::map keeps them sorted
}

vtkPolyData* PartScene::overlayData(const std::string& name) const {
  return mapperOf(overlayActor(name, "overlayData"))->GetInput();
}

long long PartScene::overlayCellCount(const std::string& name) const {
  vtkPolyData* data = mapperOf(overlayActor(name, "overlayCellCount"))->GetInput();
  return data ? static_cast<long long>(data->GetNumberOfCells()) : 0;
}

std::optional<SurfacePick> PartScene::pickSurface(const VtkView& view, QPointF widgetPos) const {
  if (view.renderer() != renderer_.Get())
    throw InvalidInput("pickSurface: the view does not render this part scene");
  vtkActor* surface = actors_[static_cast<int>(Layer::Surface)];
  if (!surface->GetVisibility()) return std::nullopt;
  // Without a locator vtkCellPicker ranks cells it hits by parametric distance before depth,
  // so a ray through a mesh vertex (every front cell hit a hair outside) picks the back side.
  // The locator returns the nearest hit along the ray; it is kept until the surface changes.
  vtkDataSet* data = mapperOf(surface)->GetInput();
  if (!data || data->GetNumberOfCells() == 0) return std::nullopt;
  if (!locator_ || locator_->GetDataSet() != data) {
    locator_ = vtkSmartPointer<vtkCellLocator>::New();
    locator_->SetDataSet(data);
    locator_->BuildLocator();
  }
  const Eigen::Vector2d display = view.displayPosition(widgetPos);
  auto picker = vtkSmartPointer<vtkCellPicker>::New();
  picker->PickFromListOn();
  picker->AddPickList(surface);
  picker->AddLocator(locator_);
  if (!picker->Pick(display.x(), display.y(), 0.0, renderer_) || picker->GetCellId() < 0)
    return std::nullopt;
  SurfacePick pick;
  pick.cell = picker->GetCellId();
  if (vtkDataSet* data = picker->GetDataSet())
    if (vtkDataArray* faces = data->GetCellData()->GetArray(kFaceArrayName))
      pick.face = static_cast<int>(faces->GetTuple1(pick.cell));
  double p[3];
  picker->GetPickPosition(p);
  pick.position = {p[0], p[1], p[2]};
  return pick;
}

}  // namespace ddfcam::gui
