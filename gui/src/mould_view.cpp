// SPDX-License-Identifier: MIT
// ddfcam gui: MouldView: two linked VTK views of the mould and the formed surface.
#include <ddfcam/gui/mould_view.h>

#include "mould_view_scene.h"

#include <ddfcam/error.h>
#include <ddfcam/gui/adapters/colour_map.h>
#include <ddfcam/gui/adapters/tolerance_colours.h>
#include <ddfcam/gui/vtk_view.h>

#include <QEvent>
#include <QHBoxLayout>
#include <QImage>
#include <QPainter>

#include <vtkActor.h>
#include <vtkCamera.h>
#include <vtkCellArray.h>
#include <vtkFloatArray.h>
#include <vtkLookupTable.h>
#include <vtkPointData.h>
#include <vtkPoints.h>
#include <vtkProperty.h>
#include <vtkRenderer.h>

#include <algorithm>
#include <cmath>

namespace ddfcam::gui {
namespace mould_view_detail {

// Points and triangles as they are (no feature splitting): point i is mesh vertex i, so the
// morph slider can move the points in place.
vtkSmartPointer<vtkPolyData> rawPolyData(const ddf::TriangleMesh& mesh) {
  auto points = vtkSmartPointer<vtkPoints>::New();
  points->SetDataTypeToDouble();
  points->SetNumberOfPoints(static_cast<vtkIdType>(mesh.vertices.size()));
  for (std::size_t i = 0; i < mesh.vertices.size(); ++i)
    points->SetPoint(static_cast<vtkIdType>(i), mesh.vertices[i].data());
  auto cells = vtkSmartPointer<vtkCellArray>::New();
  for (const auto& t : mesh.triangles) {
    const vtkIdType ids[3] = {t[0], t[1], t[2]};
    cells->InsertNextCell(3, ids);
  }
  auto data = vtkSmartPointer<vtkPolyData>::New();
  data->SetPoints(points);
  data->SetPolys(cells);
  return data;
}

vtkSmartPointer<vtkPolyDataNormals> smoothNormals() {
  auto normals = vtkSmartPointer<vtkPolyDataNormals>::New();
  // No splitting: point ids stay the mesh's vertex ids.
  normals->SplittingOff();
  normals->ConsistencyOff();
  normals->AutoOrientNormalsOff();
  return normals;
}

vtkPolyDataMapper* mapperOf(vtkActor* actor) {
  return vtkPolyDataMapper::SafeDownCast(actor->GetMapper());
}

}  // namespace mould_view_detail

namespace {

using mould_view_detail::mapperOf;
using mould_view_detail::rawPolyData;

constexpr double kPlainGrey[3] = {0.78, 0.78, 0.80};

vtkSmartPointer<vtkActor> surfaceActor(vtkAlgorithmOutput* input) {
  auto mapper = vtkSmartPointer<vtkPolyDataMapper>::New();
  mapper->SetInputConnection(input);
  mapper->ScalarVisibilityOff();
  auto actor = vtkSmartPointer<vtkActor>::New();
  actor->SetMapper(mapper);
  actor->GetProperty()->SetColor(kPlainGrey[0], kPlainGrey[1], kPlainGrey[2]);
  actor->VisibilityOff();
  return actor;
}

}  // namespace

MouldView::MouldView(QWidget* parent) : QWidget(parent), scene_(std::make_unique<Scene>()) {
  primary_ = new VtkView(this);
  primary_->setObjectName("mouldPrimaryView");
  secondary_ = new VtkView(this);
  secondary_->setObjectName("mouldSecondaryView");
  auto* layout = new QHBoxLayout(this);
  layout->setContentsMargins(0, 0, 0, 0);
  layout->setSpacing(2);
  layout->addWidget(primary_, 1);
  layout->addWidget(secondary_, 1);

  Scene& s = *scene_;
  s.primaryData = rawPolyData({});
  s.primaryNormals->SetInputData(s.primaryData);
  s.primary = surfaceActor(s.primaryNormals->GetOutputPort());
  s.secondaryData = rawPolyData({});
  s.secondaryNormals->SetInputData(s.secondaryData);
  s.secondary = surfaceActor(s.secondaryNormals->GetOutputPort());
  s.overlay = surfaceActor(s.secondaryNormals->GetOutputPort());
  s.overlay->GetProperty()->SetOpacity(kOverlayOpacity);
  s.overlay->GetProperty()->SetColor(0.85, 0.85, 0.95);
  s.overlay->PickableOff();
  primary_->renderer()->AddActor(s.primary);
  primary_->renderer()->AddActor(s.overlay);
  secondary_->renderer()->AddActor(s.secondary);
  primary_->annotationRenderer()->AddActor2D(s.primaryBar);
  secondary_->annotationRenderer()->AddActor2D(s.secondaryBar);
  linkCameras();
  connect(primary_, &VtkView::clicked, this, [this](QPointF pos) { pickAt(kPrimary, pos); });
  connect(secondary_, &VtkView::clicked, this, [this](QPointF pos) { pickAt(kSecondary, pos); });
}

MouldView::~MouldView() = default;

void MouldView::linkCameras() {
  // One camera for both renderers: interacting with either view turns both. A camera observer
  // would ping-pong (each render resets the clipping range, which modifies the camera), so the
  // other view is repainted after the input events that move the camera.
  secondary_->renderer()->SetActiveCamera(primary_->renderer()->GetActiveCamera());
  primary_->installEventFilter(this);
  secondary_->installEventFilter(this);
}

bool MouldView::eventFilter(QObject* watched, QEvent* event) {
  switch (event->type()) {
    case QEvent::MouseMove:
    case QEvent::MouseButtonRelease:
    case QEvent::Wheel:
      if (watched == primary_) secondary_->requestRender();
      if (watched == secondary_) primary_->requestRender();
      break;
    default:
      break;
  }
  return QWidget::eventFilter(watched, event);
}

void MouldView::setLayout(Layout layout) {
  layout_ = layout;
  const bool overlay = layout == Layout::Overlay;
  secondary_->setVisible(!overlay);
  scene_->overlay->SetVisibility(overlay && scene_->secondaryData->GetNumberOfPoints() > 0);
  primary_->requestRender();
  secondary_->requestRender();
}

void MouldView::showPrimary(const ddf::TriangleMesh& mesh, std::vector<float> vertexValuesMm,
                            const planning::ToleranceBand& band) {
  if (vertexValuesMm.size() != mesh.vertices.size())
    throw InvalidInput("mould view: " + std::to_string(vertexValuesMm.size()) +
                       " deviation values for " + std::to_string(mesh.vertices.size()) +
                       " mould vertices");
  planning::validateToleranceBand(band);
  double a = 2.0 * std::max(-band.lowerMm, band.upperMm);
  for (float v : vertexValuesMm)
    if (std::isfinite(v)) a = std::max(a, static_cast<double>(std::abs(v)));
  if (!(a > 0.0)) a = 1.0;
  showPrimaryPlain(mesh);
  auto values = vtkSmartPointer<vtkFloatArray>::New();
  values->SetName("deviation");
  values->SetNumberOfValues(static_cast<vtkIdType>(vertexValuesMm.size()));
  for (std::size_t i = 0; i < vertexValuesMm.size(); ++i)
    values->SetValue(static_cast<vtkIdType>(i), vertexValuesMm[i]);
  scene_->primaryData->GetPointData()->SetScalars(values);
  vtkSmartPointer<vtkLookupTable> table = makeToleranceLookupTable(-a, a, band);
  table->SetNanColor(0.55, 0.55, 0.55, 1.0);
  vtkPolyDataMapper* mapper = mapperOf(scene_->primary);
  mapper->SetLookupTable(table);
  mapper->SetScalarRange(-a, a);
  mapper->UseLookupTableScalarRangeOff();
  mapper->SetScalarModeToUsePointData();
  mapper->ScalarVisibilityOn();
  scene_->primaryBar->SetLookupTable(table);
  scene_->primaryBar->SetTitle("deviation [mm]");
  scene_->primaryBar->SetLabelFormat(scaleLabelFormat(-a, a).c_str());
  scene_->primaryBar->SetVisibility(1);
  scene_->coloured = true;
  primary_->requestRender();
}

void MouldView::showPrimaryPlain(const ddf::TriangleMesh& mesh) {
  const bool first = scene_->primaryData->GetNumberOfPoints() == 0;
  scene_->primaryMesh = mesh;
  scene_->primaryData = rawPolyData(mesh);
  scene_->primaryNormals->SetInputData(scene_->primaryData);
  mapperOf(scene_->primary)->ScalarVisibilityOff();
  scene_->primary->SetVisibility(!mesh.triangles.empty());
  scene_->primaryBar->SetVisibility(0);
  scene_->coloured = false;
  scene_->locators[kPrimary] = nullptr;
  showHighlightedTriangles({});
  if (first && !mesh.triangles.empty()) fitCameras();
  primary_->requestRender();
}

void MouldView::clear() {
  showOverlayLines({});
  showPrimaryPlain({});
  showSecondary({});
}

void MouldView::fitCameras() {
  // The shared camera fits what the primary view shows, or the formed surface if it is alone.
  VtkView& fit = scene_->primaryData->GetNumberOfPoints() > 0 ? *primary_ : *secondary_;
  fit.viewFrom(ViewDirection::Isometric);
  primary_->requestRender();
  secondary_->requestRender();
}

bool MouldView::primaryColoured() const {
  return scene_->coloured;
}

bool MouldView::saveScreenshot(const QString& path) {
  const qreal ratio = devicePixelRatioF();
  auto sizeOf = [&](const VtkView& v) {
    return QSize(std::max(64, static_cast<int>(v.width() * ratio)),
                 std::max(64, static_cast<int>(v.height() * ratio)));
  };
  const QImage first = primary_->renderImage(sizeOf(*primary_));
  if (first.isNull()) return false;
  if (layout_ == Layout::Overlay) return first.save(path);
  const QImage second = secondary_->renderImage(sizeOf(*secondary_));
  if (second.isNull()) return false;
  QImage both(first.width() + second.width() + 2, std::max(first.height(), second.height()),
              QImage::Format_RGB32);
  both.fill(Qt::black);
  QPainter painter(&both);
  painter.drawImage(0, 0, first);
  painter.drawImage(first.width() + 2, 0, second);
  painter.end();
  return both.save(path);
}

}  // namespace ddfcam::gui
