// SPDX-License-Identifier: MIT
// ddfcam gui: PartScene actors and their look.
#include <ddfcam/gui/part_scene.h>

#include <vtkActor.h>
#include <vtkPolyData.h>
#include <vtkPolyDataMapper.h>
#include <vtkProperty.h>
#include <vtkRenderer.h>

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

}  // namespace

PartScene::PartScene(vtkRenderer* renderer) : renderer_(renderer) {
  for (auto& actor : actors_) {
    actor = makeActor();
    renderer_->AddActor(actor);
  }
  styleSurface(actors_[static_cast<int>(Layer::Surface)]->GetProperty());
  auto back = vtkSmartPointer<vtkProperty>::New();
  back->DeepCopy(actors_[static_cast<int>(Layer::Surface)]->GetProperty());
  back->SetColor(0.45, 0.33, 0.30);
  actors_[static_cast<int>(Layer::Surface)]->SetBackfaceProperty(back);
  styleLines(actors_[static_cast<int>(Layer::Support)]->GetProperty(), 0.35, 0.85, 1.0, 1.0f);
  styleLines(actors_[static_cast<int>(Layer::Stubbles)]->GetProperty(), 1.0, 0.45, 0.25, 1.0f);
  // Lines drawn on top of the surface they lie in would z-fight with it.
  for (Layer layer : {Layer::Support, Layer::Stubbles}) {
    auto* mapper = vtkPolyDataMapper::SafeDownCast(actors_[static_cast<int>(layer)]->GetMapper());
    mapper->SetResolveCoincidentTopologyToPolygonOffset();
    mapper->SetRelativeCoincidentTopologyLineOffsetParameters(0.0, -4.0);
  }
  setVisible(Layer::Surface, true);
  setVisible(Layer::Support, false);
  setVisible(Layer::Stubbles, false);
}

PartScene::~PartScene() {
  for (auto& actor : actors_) renderer_->RemoveActor(actor);
}

void PartScene::setGeometry(const SceneGeometry& geometry) {
  const std::array<vtkPolyData*, kLayerCount> data = {geometry.surface, geometry.support,
                                                      geometry.stubbles};
  for (int l = 0; l < kLayerCount; ++l) {
    auto* mapper = vtkPolyDataMapper::SafeDownCast(actors_[l]->GetMapper());
    if (data[l])
      mapper->SetInputData(data[l]);
    else
      mapper->SetInputData(vtkSmartPointer<vtkPolyData>::New());
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
  auto* mapper = vtkPolyDataMapper::SafeDownCast(actors_[static_cast<int>(layer)]->GetMapper());
  auto* data = mapper ? mapper->GetInput() : nullptr;
  return data ? static_cast<long long>(data->GetNumberOfCells()) : 0;
}

}  // namespace ddfcam::gui
