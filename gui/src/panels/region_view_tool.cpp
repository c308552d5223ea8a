// SPDX-License-Identifier: MIT
// ddfcam gui: RegionViewTool, region colours and the brush and lasso on the part view.
#include <ddfcam/gui/panels/region_view_tool.h>

#include <ddfcam/error.h>
#include <ddfcam/gui/document.h>
#include <ddfcam/gui/part_scene.h>
#include <ddfcam/gui/part_view.h>
#include <ddfcam/gui/region_commands.h>
#include <ddfcam/gui/vtk_view.h>

#include <QMouseEvent>

#include <vtkActor.h>
#include <vtkActor2D.h>
#include <vtkCamera.h>
#include <vtkCellArray.h>
#include <vtkCellData.h>
#include <vtkPointData.h>
#include <vtkPoints.h>
#include <vtkPolyData.h>
#include <vtkPolyDataMapper.h>
#include <vtkPolyDataMapper2D.h>
#include <vtkProperty.h>
#include <vtkProperty2D.h>
#include <vtkRenderer.h>
#include <vtkUnsignedCharArray.h>

#include <cmath>

namespace ddfcam::gui {
namespace {

// The surface's points moved off the surface, towards the tool side, by a thousandth of its
// size: the colours then cover the part without z-fighting (polygon offsets of coincident
// triangles blend the two layers under multisampling). Each point moves along the mean of
// the oriented normals of the support faces its triangles lie in.
vtkSmartPointer<vtkPoints> liftedPoints(vtkPolyData* surface, const std::vector<int>& cellFace,
                                        const std::vector<planning::FaceFrame>& frames) {
  const vtkIdType pointCount = surface->GetNumberOfPoints();
  std::vector<Eigen::Vector3d> direction(static_cast<std::size_t>(pointCount),
                                         Eigen::Vector3d::Zero());
  for (std::size_t c = 0; c < cellFace.size(); ++c) {
    if (cellFace[c] < 0 || cellFace[c] >= static_cast<int>(frames.size())) continue;
    vtkIdType count = 0;
    const vtkIdType* ids = nullptr;
    surface->GetCellPoints(static_cast<vtkIdType>(c), count, ids);
    for (vtkIdType k = 0; k < count; ++k) direction[ids[k]] += frames[cellFace[c]].normal;
  }
  const double* box = surface->GetBounds();
  const double lift = 1e-3 * std::hypot(box[1] - box[0], box[3] - box[2], box[5] - box[4]);
  auto points = vtkSmartPointer<vtkPoints>::New();
  points->SetDataTypeToDouble();
  points->SetNumberOfPoints(pointCount);
  for (vtkIdType i = 0; i < pointCount; ++i) {
    Eigen::Vector3d p;
    surface->GetPoint(i, p.data());
    const double length = direction[i].norm();
    if (length > 0.0) p += lift / length * direction[i];
    points->SetPoint(i, p.data());
  }
  return points;
}

}  // namespace

RegionViewTool::RegionViewTool(Workbench& workbench, std::function<int()> target, QObject* parent)
    : QObject(parent),
      workbench_(workbench),
      target_(std::move(target)),
      view_(&workbench.partView.view()) {
  auto mapper = vtkSmartPointer<vtkPolyDataMapper>::New();
  mapper->SetScalarModeToUseCellData();
  mapper->SetColorModeToDirectScalars();
  mapper->ScalarVisibilityOn();
  colours_ = vtkSmartPointer<vtkActor>::New();
  colours_->SetMapper(mapper);
  colours_->PickableOff();
  colours_->GetProperty()->SetAmbient(0.15);
  colours_->GetProperty()->SetDiffuse(0.85);
  colours_->GetProperty()->SetSpecular(0.1);
  workbench_.partView.view().renderer()->AddActor(colours_);

  auto mapper2d = vtkSmartPointer<vtkPolyDataMapper2D>::New();
  outline_ = vtkSmartPointer<vtkActor2D>::New();
  outline_->SetMapper(mapper2d);
  outline_->GetProperty()->SetColor(1.0, 0.95, 0.2);
  outline_->GetProperty()->SetLineWidth(2.0f);
  outline_->VisibilityOff();
  workbench_.partView.view().annotationRenderer()->AddActor2D(outline_);

  workbench_.partView.view().installEventFilter(this);
  // The colours follow the surface cells: rebuild after the geometry and after region edits.
  connect(&workbench_.partView, &PartView::geometryChanged, this, [this] {
    grid_.reset();  // the geometry follows the part and its heights, as these caches do
    frames_.reset();
    lifted_ = nullptr;
    rebuildColours(workbench_.document.project().regions);
  });
  connect(&workbench_.document, &Document::changed, this, [this](Changes what) {
    if (what & Change::Regions) rebuildColours(workbench_.document.project().regions);
  });
  rebuildColours(workbench_.document.project().regions);
}

RegionViewTool::~RegionViewTool() {
  // The main window may have destroyed the workbench services (and the view) before its docks
  // and their panels: touch only the view, and only while it lives.
  if (!view_) return;
  view_->removeEventFilter(this);
  view_->setMouseTracking(false);
  view_->renderer()->RemoveActor(colours_);
  view_->annotationRenderer()->RemoveActor2D(outline_);
}

void RegionViewTool::setMode(RegionEditMode mode) {
  mode_ = mode;
  dragging_ = false;
  painted_.clear();
  lasso_.clear();
  outline_->VisibilityOff();
  hideBrushCursor();
  VtkView& view = workbench_.partView.view();
  view.setCursor(mode == RegionEditMode::None ? Qt::ArrowCursor : Qt::CrossCursor);
  // The brush circle follows the mouse with no button pressed.
  view.setMouseTracking(mode == RegionEditMode::Brush || mode == RegionEditMode::Erase);
  view.requestRender();
}

void RegionViewTool::setColoursVisible(bool visible) {
  coloursVisible_ = visible;
  colours_->SetVisibility(visible ? 1 : 0);
  workbench_.partView.view().requestRender();
}

long long RegionViewTool::colouredCellCount() const {
  auto* data = vtkPolyData::SafeDownCast(colours_->GetMapper()->GetInput());
  return data ? data->GetNumberOfCells() : 0;
}

void RegionViewTool::rebuildColours(const std::vector<planning::Region>& regions) {
  auto data = vtkSmartPointer<vtkPolyData>::New();
  const PartGeometry* geometry = workbench_.partView.geometry();
  const planning::Project& project = workbench_.document.project();
  if (geometry && geometry->scene.surface && project.part && !regions.empty()) {
    vtkPolyData* surface = geometry->scene.surface;
    std::vector<int> regionOf;
    try {
      regionOf = planning::faceRegionIndex(regions, project.part->faceCount());
    } catch (const Error&) {
      regionOf.clear();  // inconsistent regions never reach the document; show none
    }
    if (!lifted_) lifted_ = liftedPoints(surface, geometry->surfaceTriangleFace, faceFrameCache());
    data->SetPoints(lifted_);
    data->GetPointData()->SetNormals(surface->GetPointData()->GetNormals());
    auto polys = vtkSmartPointer<vtkCellArray>::New();
    auto rgb = vtkSmartPointer<vtkUnsignedCharArray>::New();
    rgb->SetNumberOfComponents(3);
    const auto& cellFace = geometry->surfaceTriangleFace;
    for (std::size_t c = 0; c < cellFace.size() && !regionOf.empty(); ++c) {
      const int region =
          cellFace[c] < static_cast<int>(regionOf.size()) ? regionOf[cellFace[c]] : -1;
      if (region < 0) continue;
      vtkIdType count = 0;
      const vtkIdType* ids = nullptr;
      surface->GetCellPoints(static_cast<vtkIdType>(c), count, ids);
      polys->InsertNextCell(count, ids);
      const auto& color = regions[region].color;
      rgb->InsertNextTuple3(std::lround(255.0 * color[0]), std::lround(255.0 * color[1]),
                            std::lround(255.0 * color[2]));
    }
    data->SetPolys(polys);
    data->GetCellData()->SetScalars(rgb);
  }
  vtkPolyDataMapper::SafeDownCast(colours_->GetMapper())->SetInputData(data);
  workbench_.partView.view().requestRender();
}

const std::vector<planning::FaceFrame>& RegionViewTool::faceFrameCache() const {
  if (!frames_) frames_ = planning::faceFrames(*workbench_.document.project().part);
  return *frames_;
}

const planning::SurfacePointGrid& RegionViewTool::grid() {
  if (!grid_)
    grid_ = std::make_unique<planning::SurfacePointGrid>(*workbench_.document.project().part);
  return *grid_;
}

void RegionViewTool::paintAt(QPointF pos) {
  PartView& partView = workbench_.partView;
  if (!workbench_.document.project().part) return;
  const std::optional<SurfacePick> hit = partView.scene().pickSurface(partView.view(), pos);
  if (!hit) return;
  const std::vector<int> faces = grid().facesWithinDistance(hit->position, radiusMm_);
  const std::size_t before = painted_.size();
  painted_.insert(faces.begin(), faces.end());
  if (painted_.size() == before) return;
  const int target = mode_ == RegionEditMode::Erase ? -1 : target_();
  const planning::Project& project = workbench_.document.project();
  const std::vector<int> list(painted_.begin(), painted_.end());
  try {
    rebuildColours(planning::assignFaces(project.regions, target, list, project.part->faceCount()));
  } catch (const Error&) {
    // No preview for an edit the release will refuse (and report).
  }
}

void RegionViewTool::finishStroke() {
  const std::vector<int> faces(painted_.begin(), painted_.end());
  painted_.clear();
  if (faces.empty()) return;
  const int target = mode_ == RegionEditMode::Erase ? -1 : target_();
  runUserAction(workbench_.reportError, tr("Paint regions"), [&] {
    Document& document = workbench_.document;
    const planning::Project& project = document.project();
    auto after = planning::assignFaces(project.regions, target, faces, project.part->faceCount());
    const QString text = target < 0
                             ? tr("Erase %1 faces").arg(faces.size())
                             : tr("Paint %1 faces into '%2'")
                                   .arg(faces.size())
                                   .arg(QString::fromStdString(project.regions[target].name));
    document.push(std::make_unique<SetRegionsCommand>(document, text, std::move(after)));
  });
  // A refused edit leaves the document as it was; drop the preview.
  rebuildColours(workbench_.document.project().regions);
}

std::vector<int> RegionViewTool::facesInLasso(const std::vector<QPointF>& polygon) const {
  const planning::Project& project = workbench_.document.project();
  if (!project.part || polygon.size() < 3) return {};
  const std::vector<planning::FaceFrame>& frames = faceFrameCache();
  std::vector<Eigen::Vector2d> ring;
  for (const QPointF& p : polygon) ring.emplace_back(p.x(), p.y());
  const VtkView& view = workbench_.partView.view();
  vtkCamera* camera = view.renderer()->GetActiveCamera();
  Eigen::Vector3d eye, towards;
  camera->GetPosition(eye.data());
  camera->GetDirectionOfProjection(towards.data());
  const bool parallel = camera->GetParallelProjection() != 0;
  std::vector<int> faces;
  for (int f = 0; f < static_cast<int>(frames.size()); ++f) {
    const planning::FaceFrame& frame = frames[f];
    const Eigen::Vector3d toEye =
        parallel ? Eigen::Vector3d(-towards) : Eigen::Vector3d(eye - frame.centroid);
    if (frame.normal.dot(toEye) <= 0.0) continue;
    const QPointF at = view.widgetPosition(frame.centroid);
    if (planning::pointInPolygon({at.x(), at.y()}, ring)) faces.push_back(f);
  }
  return faces;
}

void RegionViewTool::updateLassoOutline() {
  auto points = vtkSmartPointer<vtkPoints>::New();
  auto lines = vtkSmartPointer<vtkCellArray>::New();
  const VtkView& view = workbench_.partView.view();
  for (const QPointF& p : lasso_) {
    const Eigen::Vector2d d = view.displayPosition(p);
    points->InsertNextPoint(d.x(), d.y(), 0.0);
  }
  const vtkIdType n = points->GetNumberOfPoints();
  if (n >= 2) {
    lines->InsertNextCell(n + 1);
    for (vtkIdType i = 0; i <= n; ++i) lines->InsertCellPoint(i % n);  // closed ring
  }
  auto data = vtkSmartPointer<vtkPolyData>::New();
  data->SetPoints(points);
  data->SetLines(lines);
  vtkPolyDataMapper2D::SafeDownCast(outline_->GetMapper())->SetInputData(data);
  outline_->SetVisibility(n >= 2 ? 1 : 0);
  workbench_.partView.view().requestRender();
}

void RegionViewTool::finishLasso() {
  const std::vector<int> faces = facesInLasso(lasso_);
  lasso_.clear();
  outline_->VisibilityOff();
  workbench_.partView.view().requestRender();
  if (faces.empty()) return;
  const int target = target_();
  runUserAction(workbench_.reportError, tr("Lasso"), [&] {
    Document& document = workbench_.document;
    const planning::Project& project = document.project();
    auto after = planning::assignFaces(project.regions, target, faces, project.part->faceCount());
    const QString text = tr("Lasso %1 faces into '%2'")
                             .arg(faces.size())
                             .arg(QString::fromStdString(project.regions[target].name));
    document.push(std::make_unique<SetRegionsCommand>(document, text, std::move(after)));
  });
}

bool RegionViewTool::eventFilter(QObject* watched, QEvent* event) {
  if (mode_ == RegionEditMode::None) return QObject::eventFilter(watched, event);
  const QEvent::Type type = event->type();
  if (type == QEvent::KeyPress || type == QEvent::ShortcutOverride) return handleKey(event);
  if (type == QEvent::Leave) hideBrushCursor();
  const bool brush = mode_ == RegionEditMode::Brush || mode_ == RegionEditMode::Erase;
  if (brush && type == QEvent::MouseMove)
    updateBrushCursor(static_cast<QMouseEvent*>(event)->position());
  if (type != QEvent::MouseButtonPress && type != QEvent::MouseMove &&
      type != QEvent::MouseButtonRelease)
    return QObject::eventFilter(watched, event);
  const auto& mouse = *static_cast<QMouseEvent*>(event);
  if (type == QEvent::MouseButtonPress) return handlePress(mouse);
  if (!dragging_) return false;
  return type == QEvent::MouseMove ? handleMove(mouse) : handleRelease(mouse);
}

bool RegionViewTool::handlePress(const QMouseEvent& mouse) {
  if (mouse.button() != Qt::LeftButton || mouse.modifiers() != Qt::NoModifier) return false;
  if (mode_ != RegionEditMode::Erase && target_() < 0) {
    emit refused(tr("Select a region to paint into first."));
    return true;
  }
  dragging_ = true;
  view_->setFocus(Qt::MouseFocusReason);  // for Escape
  painted_.clear();
  lasso_.assign(1, mouse.position());
  if (mode_ != RegionEditMode::Lasso) paintAt(mouse.position());
  return true;
}

bool RegionViewTool::handleMove(const QMouseEvent& mouse) {
  if (mode_ == RegionEditMode::Lasso) {
    const QPointF step = mouse.position() - lasso_.back();
    if (std::hypot(step.x(), step.y()) >= 2.0) lasso_.push_back(mouse.position());
    updateLassoOutline();
  } else {
    paintAt(mouse.position());
  }
  return true;
}

bool RegionViewTool::handleRelease(const QMouseEvent& mouse) {
  if (mouse.button() != Qt::LeftButton) return false;
  dragging_ = false;
  if (mode_ == RegionEditMode::Lasso) {
    if (lasso_.back() != mouse.position()) lasso_.push_back(mouse.position());
    finishLasso();
  } else {
    paintAt(mouse.position());
    finishStroke();
  }
  return true;
}

}  // namespace ddfcam::gui
