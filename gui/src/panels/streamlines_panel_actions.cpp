// SPDX-License-Identifier: MIT
// ddfcam gui: StreamlinesPanel actions: field jobs, seeding, smoothing preview and apply.
#include <ddfcam/gui/panels/streamlines_panel.h>

#include <ddfcam/error.h>
#include <ddfcam/gui/adapters/poly_data.h>
#include <ddfcam/gui/console_dock.h>
#include <ddfcam/gui/document.h>
#include <ddfcam/gui/document_command.h>
#include <ddfcam/gui/flow_field_display.h>
#include <ddfcam/gui/job_runner.h>
#include <ddfcam/gui/part_scene.h>
#include <ddfcam/gui/part_view.h>
#include <ddfcam/gui/path_commands.h>
#include <ddfcam/gui/path_list.h>
#include <ddfcam/gui/vtk_view.h>
#include <ddfcam/planning/lines/line_ordering.h>
#include <ddfcam/planning/lines/streamline_fairing.h>
#include <ddfcam/planning/lines/streamline_path.h>
#include <ddfcam/planning/placement/path_linking.h>

#include <QCheckBox>
#include <QComboBox>
#include <QDoubleSpinBox>
#include <QLabel>
#include <QPointer>
#include <QSignalBlocker>
#include <QSlider>

#include <algorithm>
#include <optional>

namespace ddfcam::gui {

std::shared_ptr<StreamlinesPanel::Fields> computeStreamlineFields(
    const ddf::DisplacementField& part, const FieldChoice& choice,
    std::shared_ptr<const planning::CurvatureField> curvature,
    const planning::CurvatureParams& curvatureParams, const ProgressCallback& progress) {
  auto fields = std::make_shared<StreamlinesPanel::Fields>();
  fields->choice = choice;
  if (!curvature) {
    planning::CurvatureParams params = curvatureParams;
    params.progress = [&](double f) { return !progress || progress(0.2 * f); };
    curvature =
        std::make_shared<const planning::CurvatureField>(planning::computeCurvature(part, params));
  }
  fields->curvature = curvature;
  static_cast<planning::RegionFields&>(*fields) =
      planning::regionFields(part, *curvature, choice.plan, choice.faceMask,
                             [&](double f) { return !progress || progress(0.2 + 0.8 * f); });
  return fields;
}

bool StreamlinesPanel::runWithFields(const QString& title, LineWork work, const QString& pathName,
                                     std::shared_ptr<const QString> note) {
  const auto& part = workbench().document.project().part;
  if (!part) {
    workbench().reportError(title, tr("There is no part."));
    return false;
  }
  const FieldChoice choice = currentChoice();
  std::shared_ptr<const Fields> cached = fields_ && fields_->choice == choice ? fields_ : nullptr;
  std::shared_ptr<const planning::CurvatureField> curvature =
      fields_ ? fields_->curvature : nullptr;
  auto copy = std::make_shared<ddf::DisplacementField>(*part);
  const planning::CurvatureParams curvatureParams =
      planning::partCurvatureParams(workbench().document.project());
  QPointer<StreamlinesPanel> self(this);
  const std::uint64_t generation = generation_;
  return workbench().jobs.start(title, [=](const ProgressCallback& progress) {
    std::shared_ptr<const Fields> fields = cached;
    const double share = fields ? 0.0 : 0.7;
    if (!fields)
      fields = computeStreamlineFields(*copy, choice, curvature, curvatureParams,
                                       [&](double f) { return !progress || progress(share * f); });
    std::vector<planning::Streamline> lines;
    if (work)
      lines = work(*copy, *fields,
                   [&](double f) { return !progress || progress(share + (1.0 - share) * f); });
    return std::function<void()>(
        [self, fields, lines = std::move(lines), pathName, generation, note]() mutable {
          if (!self || self->generation_ != generation) return;  // computed for another part
          self->adoptFields(fields);
          if (!pathName.isEmpty()) self->addPath(std::move(lines), pathName);
          if (note && !note->isEmpty())
            self->status_->setText(self->status_->text() + "\n" + *note);
        });
  });
}

void StreamlinesPanel::adoptFields(std::shared_ptr<const Fields> fields) {
  const bool changed = fields_ != fields || !display_->hasFields();
  fields_ = std::move(fields);
  if (!changed) return;
  const auto& part = workbench().document.project().part;
  if (!part) return;
  display_->show(*part, fields_->field, *fields_->curvature, fields_->singularities);
  double indexSum = 0;
  for (const auto& s : fields_->singularities) indexSum += s.index;
  status_->setText(tr("Field: %1 singularities, index sum %2")
                       .arg(fields_->singularities.size())
                       .arg(indexSum, 0, 'g', 3));
  workbench().partView.view().requestRender();
}

bool StreamlinesPanel::showField() {
  // Showing the field means seeing something: turn the flow glyphs on if nothing is on.
  if (!display_->isVisible(GlyphField::Flow) && !display_->isVisible(GlyphField::MaxDirection) &&
      !display_->isVisible(GlyphField::MinDirection)) {
    const QSignalBlocker block(glyphToggles_[0]);
    glyphToggles_[0]->setChecked(true);
    display_->setVisible(GlyphField::Flow, true);
  }
  if (fields_ && fields_->choice == currentChoice() && display_->hasFields()) return true;
  return runWithFields(tr("Compute tool flow field"), nullptr, {});
}

void StreamlinesPanel::addPath(std::vector<planning::Streamline> lines, const QString& name) {
  runUserAction(workbench().reportError, tr("Add %1").arg(name), [&] {
    Document& document = workbench().document;
    const planning::Project& p = document.project();
    for (planning::Streamline& line : lines) planning::dropRepeatedPoints(line);
    std::erase_if(lines, [](const planning::Streamline& l) { return l.points.size() < 2; });
    const planning::RegionPlan* selected = selectedPlan();
    const planning::RegionPlan plan = selected ? *selected : planning::RegionPlan{};
    // The region's tool if its plan names one, else the project's first (or a new default).
    const int toolIndex =
        plan.tool >= 0 && plan.tool < static_cast<int>(p.tools.size()) ? plan.tool : 0;
    const bool needTool = p.tools.empty();
    const planning::Tool tool = needTool ? planning::Tool{} : p.tools[toolIndex];
    planning::StreamlinePathParams params = placementParams();
    params.name = QString("%1 %2").arg(name).arg(p.paths.size() + 1).toStdString();
    planning::RegionPath placed = planning::regionToolPath(*p.part, std::move(lines), plan, tool,
                                                           toolIndex, link_->isChecked(), params);
    lastSampling_ = std::move(placed.placed.passes);
    showSampling();
    const QString idle =
        placed.linked ? tr(", linked: idle %1 mm").arg(placed.linked->idleLengthMm, 0, 'f', 1)
                      : QString();
    document.push(std::make_unique<AddPathCommand>(document, std::move(placed.placed.path),
                                                   needTool ? std::optional(tool) : std::nullopt));
    // A tool the engineer did not choose is said out loud, with where to change it.
    const QString added =
        needTool ? tr(". The project had no tool: added the default %1 (change it in the Tools "
                      "panel)")
                       .arg(QString::fromStdString(tool.name))
                 : QString();
    status_->setText(tr("%1: %2 lines, cutting %3 mm%4%5")
                         .arg(QString::fromStdString(params.name))
                         .arg(placed.lines.size())
                         .arg(placed.cuttingLengthMm, 0, 'f', 1)
                         .arg(idle, added));
    if (needTool) workbench().console.appendMessage(LogLevel::Warning, added.mid(2));
  });
}

const planning::RegionPlan* StreamlinesPanel::selectedPlan() const {
  const int region = region_->currentData().isValid() ? region_->currentData().toInt() : -1;
  const auto& regions = workbench().document.project().regions;
  return region >= 0 && region < static_cast<int>(regions.size()) ? &regions[region].plan : nullptr;
}

const std::vector<planning::Streamline>* StreamlinesPanel::selectedRawLines(int* index) const {
  const int selected = pathList_->selectedPath();
  const auto& paths = workbench().document.project().paths;
  if (index) *index = selected;
  if (selected < 0 || selected >= static_cast<int>(paths.size()) ||
      !workbench().document.project().part)
    return nullptr;
  const planning::ToolPath& path = paths[selected];
  if (path.rawLines.empty() || path.rawLines.size() != path.passStarts.size()) return nullptr;
  return &path.rawLines;
}

void StreamlinesPanel::updatePreview() {
  const int k = window_->value();
  windowLabel_->setText(tr("k = %1").arg(k));
  PartScene& scene = workbench().partView.scene();
  int index = -1;
  const auto* raw = selectedRawLines(&index);
  const auto& paths = workbench().document.project().paths;
  if (k == 0 || index < 0 || index >= static_cast<int>(paths.size())) {
    if (scene.removeOverlay(kPreviewOverlay)) workbench().partView.view().requestRender();
    return;
  }
  // The raw lines: as traced if this panel made the path, else the path's contacts.
  std::vector<std::vector<Eigen::Vector3d>> lines;
  if (raw) {
    for (const auto& line : *raw) lines.push_back(line.polyline());
  } else {
    const planning::ToolPath& path = paths[index];
    for (std::size_t s = 0; s < path.passStarts.size(); ++s) {
      const std::size_t end =
          s + 1 < path.passStarts.size() ? path.passStarts[s + 1] : path.poses.size();
      auto& line = lines.emplace_back();
      for (std::size_t i = path.passStarts[s]; i < end; ++i) line.push_back(path.poses[i].contact);
    }
  }
  for (auto& line : lines) line = planning::smoothMovingAverage(line, k);
  OverlayStyle style;
  style.rgb = {0.2, 0.95, 1.0};
  style.lineWidth = 3.0;
  style.onTop = true;
  scene.setOverlay(kPreviewOverlay, toPolylinePolyData(lines), style);
  workbench().partView.view().requestRender();
}

void StreamlinesPanel::replaceSelected(std::vector<planning::Streamline> lines,
                                       const QString& what) {
  runUserAction(workbench().reportError, what, [&] {
    Document& document = workbench().document;
    const planning::Project& p = document.project();
    const int index = pathList_->selectedPath();
    if (index < 0 || index >= static_cast<int>(p.paths.size()))
      throw InvalidInput("no path is selected");
    const planning::ToolPath& old = p.paths[index];
    planning::StreamlinePathParams params;
    params.name = old.name;
    params.feedMmPerMin = old.feedMmPerMin;
    planning::ToolPath path = placeLines(*p.part, lines, p.tools.at(old.tool), old.tool, params);
    path.rawLines = old.rawLines;  // smoothing again starts from the lines as traced
    path.linkedIdleMm = old.linkedIdleMm;
    const QString text = QString("%1 '%2'").arg(what, QString::fromStdString(old.name));
    document.push(std::make_unique<ReplacePathCommand>(document, index, std::move(path), text));
  });
}

bool StreamlinesPanel::applySmoothing() {
  const auto* raw = selectedRawLines(nullptr);
  const int k = window_->value();
  if (!raw || k == 0) {
    workbench().reportError(tr("Smooth path"), raw ? tr("Set the smoothing window first.")
                                                   : tr("Select a path traced in this panel."));
    return false;
  }
  const std::size_t before = workbench().document.project().paths.size();
  const auto revision = workbench().document.revision();
  replaceSelected(planning::smoothOnSurface(*workbench().document.project().part, *raw, k),
                  tr("Smooth path"));
  return workbench().document.revision() != revision &&
         workbench().document.project().paths.size() == before;
}

bool StreamlinesPanel::fairSelected(double deviationMm) {
  const auto* raw = selectedRawLines(nullptr);
  const auto& part = workbench().document.project().part;
  if (!raw || !part) {
    workbench().reportError(tr("Fair path"), tr("Select a path traced in this panel."));
    return false;
  }
  auto lines = std::make_shared<std::vector<planning::Streamline>>(*raw);
  auto copy = std::make_shared<ddf::DisplacementField>(*part);
  const planning::CurvatureParams curvatureParams =
      planning::partCurvatureParams(workbench().document.project());
  QPointer<StreamlinesPanel> self(this);
  const std::uint64_t generation = generation_;
  return workbench().jobs.start(tr("Fair path"), [=](const ProgressCallback& progress) {
    std::vector<planning::Streamline> faired;
    for (std::size_t l = 0; l < lines->size(); ++l) {
      planning::FairingParams params;
      params.deviationMm = deviationMm;
      faired.push_back(planning::fairStreamline(*copy, (*lines)[l], params));
      reportProgress(progress, double(l + 1) / lines->size());
    }
    return std::function<void()>([self, faired = std::move(faired), generation]() mutable {
      if (self && self->generation_ == generation)
        self->replaceSelected(std::move(faired), tr("Fair path"));
    });
  });
}

}  // namespace ddfcam::gui
