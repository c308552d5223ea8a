// SPDX-License-Identifier: MIT
// ddfcam gui: SegmentationPanel's automatic segmentation: by curvature type, by tool-radius
// classes and by CAD face, each a job whose result is one undoable SetRegionsCommand.
#include <ddfcam/gui/panels/segmentation_panel.h>

#include <ddfcam/error.h>
#include <ddfcam/gui/document.h>
#include <ddfcam/gui/job_runner.h>
#include <ddfcam/gui/region_commands.h>
#include <ddfcam/planning/analysis/cad_face_segmentation.h>
#include <ddfcam/planning/analysis/curvature.h>
#include <ddfcam/planning/analysis/segmentation.h>

#include <QCheckBox>
#include <QComboBox>
#include <QDoubleSpinBox>
#include <QLabel>
#include <QLineEdit>
#include <QPointer>
#include <QRegularExpression>
#include <QSpinBox>
#include <QStandardItemModel>

#include <algorithm>
#include <memory>

namespace ddfcam::gui {
namespace {

std::vector<double> parseRadii(const QString& text) {
  std::vector<double> radii;
  for (const QString& token : text.split(QRegularExpression("[,;\\s]+"), Qt::SkipEmptyParts)) {
    bool ok = false;
    const double r = token.toDouble(&ok);
    if (!ok) throw InvalidInput("tool radii: '" + token.toStdString() + "' is not a number");
    radii.push_back(r);
  }
  std::sort(radii.begin(), radii.end());
  radii.erase(std::unique(radii.begin(), radii.end()), radii.end());
  return radii;
}

// Regions of the work, computed on copies off the UI thread.
using RegionWork = std::function<std::vector<planning::Region>(const ProgressCallback& progress)>;

}  // namespace

void SegmentationPanel::updateMethodControls() {
  const planning::Project& project = workbench().document.project();
  const bool hasCadFaces =
      project.part && !project.cadFaceNames.empty() &&
      static_cast<int>(project.cadFaceOfSupportFace.size()) == project.part->faceCount();
  // Only a part that came from CAD knows its faces.
  if (auto* model = qobject_cast<QStandardItemModel*>(method_->model()))
    if (QStandardItem* item = model->item(static_cast<int>(SegmentationMethod::CadFace)))
      item->setEnabled(hasCadFaces);
  const auto method = static_cast<SegmentationMethod>(method_->currentIndex());
  if (method == SegmentationMethod::CadFace && !hasCadFaces)
    method_->setCurrentIndex(static_cast<int>(SegmentationMethod::CurvatureType));
  const auto shown = static_cast<SegmentationMethod>(method_->currentIndex());
  flatThreshold_->setEnabled(shown == SegmentationMethod::CurvatureType);
  toolRadii_->setEnabled(shown == SegmentationMethod::ToolRadius);
  // A CAD face is a region even when small (cadFaceSegmentationParams).
  minFaces_->setEnabled(shown != SegmentationMethod::CadFace);
}

bool SegmentationPanel::segment() {
  const planning::Project& project = workbench().document.project();
  if (!project.part) return false;
  const auto method = static_cast<SegmentationMethod>(method_->currentIndex());
  auto copy = std::make_shared<ddf::DisplacementField>(*project.part);
  RegionWork work;
  QString title;
  if (method == SegmentationMethod::CadFace) {
    title = tr("Segment by CAD face");
    auto labels = std::make_shared<std::vector<int>>(project.cadFaceOfSupportFace);
    auto names = std::make_shared<std::vector<std::string>>(project.cadFaceNames);
    work = [copy, labels, names](const ProgressCallback& progress) {
      planning::SegmentationParams p = planning::cadFaceSegmentationParams();
      p.progress = progress;
      return planning::segmentByCadFace(*copy, *labels, *names, p);
    };
  } else {
    const bool byType = method == SegmentationMethod::CurvatureType;
    std::vector<double> radii;
    if (!byType && !runUserAction(workbench().reportError, tr("Segment"),
                                  [&] { radii = parseRadii(toolRadii_->text()); }))
      return false;
    planning::SegmentationParams params;
    params.type.flatCurvaturePerMm = flatThreshold_->value();
    params.minFaces = minFaces_->value();
    title = byType ? tr("Segment by curvature type") : tr("Segment by tool radius");
    const planning::CurvatureParams base = planning::partCurvatureParams(project);
    work = [copy, params, byType, radii, base](const ProgressCallback& progress) {
      planning::CurvatureParams curvatureParams = base;
      curvatureParams.progress = [&](double f) { return !progress || progress(0.7 * f); };
      const planning::CurvatureField curvature = planning::computeCurvature(*copy, curvatureParams);
      planning::SegmentationParams p = params;
      p.progress = [&](double f) { return !progress || progress(0.7 + 0.3 * f); };
      return byType ? planning::segmentByCurvatureType(*copy, curvature, p)
                    : planning::segmentByToolRadius(*copy, curvature, radii, p);
    };
  }
  QPointer<SegmentationPanel> self(this);
  return workbench().jobs.start(title, [=](const ProgressCallback& progress) {
    auto regions = std::make_shared<std::vector<planning::Region>>(work(progress));
    return std::function<void()>([self, regions, title] {
      if (!self) return;
      Document& document = self->workbench().document;
      document.push(std::make_unique<SetRegionsCommand>(document, title, std::move(*regions)));
      self->status_->setText(tr("%1 regions").arg(document.project().regions.size()));
      self->showColours_->setChecked(true);
    });
  });
}

}  // namespace ddfcam::gui
