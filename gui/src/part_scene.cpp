// SPDX-License-Identifier: MIT
// ddfcam gui: PartScene actors and their look, the field colouring and its scalar bar.
#include <ddfcam/gui/part_scene.h>

#include <ddfcam/error.h>
#include <ddfcam/gui/adapters/poly_data.h>
#include <ddfcam/gui/adapters/raster_field_surface.h>
#include <ddfcam/gui/adapters/tolerance_colours.h>
#include <ddfcam/gui/vtk_view.h>

#include "part_scene_look.h"
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

vtkPolyDataMapper* detail::mapperOf(vtkActor* actor) {
  return vtkPolyDataMapper::SafeDownCast(actor->GetMapper());
}

void detail::styleSurface(vtkProperty* p) {
  p->SetColor(kSurfaceRgb[0], kSurfaceRgb[1], kSurfaceRgb[2]);
  p->SetAmbient(0.10);
  p->SetDiffuse(0.80);
  p->SetSpecular(0.25);
  p->SetSpecularPower(30.0);
  p->SetInterpolationToPhong();
  // Back faces (the inside of the crust) in a darker tone so open parts read correctly.
  p->BackfaceCullingOff();
}

namespace {

using detail::mapperOf;
using detail::kSurfaceRgb;
using detail::styleSurface;

vtkSmartPointer<vtkActor> makeActor() {
  auto mapper = vtkSmartPointer<vtkPolyDataMapper>::New();
  mapper->ScalarVisibilityOff();
  mapper->SetInputData(vtkSmartPointer<vtkPolyData>::New());
  auto actor = vtkSmartPointer<vtkActor>::New();
  actor->SetMapper(mapper);
  return actor;
}

void styleLines(vtkProperty* p, double r, double g, double b, float width) {
  p->SetColor(r, g, b);
  p->SetLineWidth(width);
  p->LightingOff();
  p->SetRepresentationToWireframe();
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
  surfaceTexture_ = geometry.surfaceTexture;
  rasterField_.reset();
  cornerParams_ = geometry.surfaceCornerParams;
  rasterFaces_ = geometry.rasterFaces;
  rasterSteps_ = geometry.rasterSteps;
  showPlainSurface();
  const std::array<vtkPolyData*, kLayerCount> data = {geometry.surface, geometry.support,
                                                      geometry.stubbles};
  for (int l = 0; l < kLayerCount; ++l) {
    if (data[l])
      mapperOf(actors_[l])->SetInputData(data[l]);
    else
      mapperOf(actors_[l])->SetInputData(vtkSmartPointer<vtkPolyData>::New());
  }
}

void PartScene::showPlainSurface() {
  vtkActor* surfaceActor = actors_[static_cast<int>(Layer::Surface)];
  surfaceActor->SetTexture(surfaceTexture_);
  // Only the colour: the rest of the material may have been adjusted through actor().
  if (surfaceTexture_)
    surfaceActor->GetProperty()->SetColor(1.0, 1.0, 1.0);  // the texture's colours, lit
  else
    surfaceActor->GetProperty()->SetColor(kSurfaceRgb[0], kSurfaceRgb[1], kSurfaceRgb[2]);
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
