// SPDX-License-Identifier: MIT
// ddfcam gui: MouldPanel outputs: the morph surface, deviation export and cross sections.
#include <ddfcam/error.h>
#include <ddfcam/gui/adapters/section_plot.h>
#include <ddfcam/gui/document.h>
#include <ddfcam/gui/mould_view.h>
#include <ddfcam/gui/panels/mould_panel.h>
#include <ddfcam/gui/plot_dock.h>
#include <ddfcam/gui/vtk_view.h>
#include <ddfcam/io/mesh/mesh_io.h>
#include <ddfcam/io/results/deviation_export.h>
#include <ddfcam/planning/inspection/surface_comparison.h>
#include <ddfcam/planning/surface/cross_section.h>

#include <qcustomplot.h>

#include <QLabel>
#include <QSlider>

#include <vtkCamera.h>
#include <vtkRenderer.h>

#include <algorithm>
#include <cmath>
#include <memory>

namespace ddfcam::gui {

double MouldPanel::morphLambda() const {
  return morph_->value() / 100.0;
}

bool MouldPanel::setMorphLambda(double lambda) {
  if (!raster_) return false;
  const int value = static_cast<int>(std::lround(std::clamp(lambda, -1.0, 2.0) * 100.0));
  morphShown_ = true;
  if (value == morph_->value())
    showMorph();
  else
    morph_->setValue(value);
  return true;
}

std::optional<ddf::TriangleMesh> MouldPanel::morphSurface() const {
  const auto& study = workbench().document.project().mould;
  if (!raster_ || !study || !study->result) return std::nullopt;
  const auto& seq = study->result->sequence;
  const std::vector<ddf::Vec3> moved = ddf::morphPositions(seq, morphLambda());
  const std::vector<ddf::Vec3> mould = ddf::morphPositions(seq, 0.0);
  ddf::TriangleMesh mesh = raster_->mesh;
  for (std::size_t v = 0; v < vertexCopy_.size(); ++v) {
    const ddf::Vec3& p = moved[vertexCopy_[v]];
    // A stubble that missed the formed surface has no path: that point stays on the mould.
    mesh.vertices[v] = p.allFinite() ? p : mould[vertexCopy_[v]];
  }
  return mesh;
}

void MouldPanel::showMorph() {
  morphLabel_->setText(tr("lambda = %1 (0 = mould, 1 = formed)").arg(morphLambda(), 0, 'f', 2));
  MouldView* view = workbench().mouldView;
  const std::optional<ddf::TriangleMesh> mesh = morphSurface();
  if (!view || !mesh) return;
  if (view->secondaryPointCount() != static_cast<int>(mesh->vertices.size()) ||
      !view->updateSecondaryPoints(mesh->vertices))
    view->showSecondary(*mesh);
}

bool MouldPanel::exportMorphSurface(const QString& path) {
  return runUserAction(workbench().reportError, tr("Export morph surface"), [&] {
    const std::optional<ddf::TriangleMesh> mesh = morphSurface();
    if (!mesh) throw InvalidInput("compare the surfaces first: the morph runs on the comparison");
    io::writeMesh(*mesh, path.toStdString());
  });
}

bool MouldPanel::exportDeviation(const QString& path) {
  return runUserAction(workbench().reportError, tr("Export deviation"), [&] {
    const auto& study = workbench().document.project().mould;
    if (!study || !study->result) throw InvalidInput("compare the surfaces first");
    if (path.endsWith(QStringLiteral(".csv"), Qt::CaseInsensitive))
      io::writeDeviationCsv(*study->result, path.toStdString());
    else if (path.endsWith(QStringLiteral(".vtp"), Qt::CaseInsensitive))
      io::writeDeviationVtp(*study->result, path.toStdString());
    else
      throw InvalidInput("export the deviation as .vtp or .csv: '" + path.toStdString() + "'");
  });
}

bool MouldPanel::drawSection(const Eigen::Vector3d& a, const Eigen::Vector3d& b) {
  return runUserAction(workbench().reportError, tr("Draw section"), [&] {
    const auto& study = workbench().document.project().mould;
    if (!study || !study->formed) throw InvalidInput("load the mould and the formed surface");
    Eigen::Vector3d direction(0.0, 0.0, -1.0);
    if (MouldView* view = workbench().mouldView)
      view->primaryView().renderer()->GetActiveCamera()->GetDirectionOfProjection(direction.data());
    const planning::SectionPlane plane = planning::sectionPlaneFromView(a, b, direction);
    const auto mouldCurves = planning::sectionCurves(study->mould.mesh, plane);
    const auto formedCurves = planning::sectionCurves(study->formed->mesh, plane);
    QCustomPlot* plot = workbench().plots.plot(kSectionTab);
    setSectionCurve(plot, tr("mould"), mouldCurves, QColor(40, 40, 40));
    setSectionCurve(plot, tr("formed"), formedCurves, QColor(220, 120, 0));
    workbench().plots.showPlot(kSectionTab);
    std::vector<std::vector<Eigen::Vector3d>> lines{{a, b}};
    for (const auto* curves : {&mouldCurves, &formedCurves})
      for (const auto& curve : *curves) {
        std::vector<Eigen::Vector3d> line;
        for (const Eigen::Vector2d& st : curve) line.push_back(planning::sectionToWorld(plane, st));
        lines.push_back(std::move(line));
      }
    if (MouldView* view = workbench().mouldView) view->showOverlayLines(lines);
  });
}

}  // namespace ddfcam::gui
