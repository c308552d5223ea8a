// SPDX-License-Identifier: MIT
// ddfcam gui: StreamlinesPanel seeding: a click, a family along the transverse line, coverage.
#include <ddfcam/gui/panels/streamlines_panel.h>

#include <ddfcam/gui/document.h>
#include <ddfcam/gui/job_runner.h>
#include <ddfcam/planning/pipeline/region_planning.h>

#include <QDoubleSpinBox>

#include <memory>

namespace ddfcam::gui {

bool StreamlinesPanel::seedAt(const ddf::SurfaceLocation& seed) {
  const std::vector<std::uint8_t> mask = currentChoice().faceMask;
  const planning::StreamlineMethod method = streamlineMethod();
  return runWithFields(
      tr("Trace streamline"),
      [seed, mask, method](const ddf::DisplacementField& part, const Fields& fields,
                           const ProgressCallback& progress) {
        planning::StreamlineParams params;
        params.faceMask = mask;
        params.progress = progress;
        return planning::traceLinesThrough(part, fields.field, {seed}, method, params);
      },
      tr("streamline"));
}

bool StreamlinesPanel::seedFamily() {
  if (!lastPick_) {
    workbench().reportError(tr("Seed family"), tr("Pick a point on the part first."));
    return false;
  }
  planning::LineSpacing spacing;
  spacing.minMm = spacing.maxMm = spacing_->value();
  planning::RegionLinesParams params;
  params.seeding = planning::LineSeeding::Family;
  params.tracing = streamlineMethod();
  params.seed = *lastPick_;
  const std::vector<std::uint8_t> mask = currentChoice().faceMask;
  return runWithFields(
      tr("Seed streamline family"),
      [spacing, params, mask](const ddf::DisplacementField& part, const Fields& fields,
                              const ProgressCallback& progress) {
        planning::RegionLinesParams run = params;
        run.progress = progress;
        return planning::planRegionLines(part, fields, mask, spacing, run);
      },
      tr("streamline family"));
}

bool StreamlinesPanel::coverRegion(double dSepMm) {
  if (!(dSepMm > 0)) {
    workbench().reportError(tr("Cover region"), tr("d_sep must be positive."));
    return false;
  }
  const std::vector<std::uint8_t> mask = currentChoice().faceMask;
  // The region's plan decides between a fixed spacing (d_sep) and one from its scallop height.
  const planning::RegionPlan* selected = selectedPlan();
  planning::RegionPlan plan = selected ? *selected : planning::RegionPlan{};
  if (plan.spacingMode != planning::SpacingMode::ScallopTolerance) plan.spacingMm = dSepMm;
  const auto& tools = workbench().document.project().tools;
  const int t = plan.tool >= 0 && plan.tool < static_cast<int>(tools.size()) ? plan.tool : 0;
  const planning::Tool tool = tools.empty() ? planning::Tool{} : tools[t];
  auto note = std::make_shared<QString>();
  return runWithFields(
      tr("Cover region with streamlines"),
      [plan, tool, mask, note](const ddf::DisplacementField& part, const Fields& fields,
                               const ProgressCallback& progress) {
        const planning::LineSpacing spacing =
            planning::regionSpacing(part, *fields.curvature, fields, plan, tool);
        *note = QString::fromStdString(spacing.note);
        planning::RegionLinesParams params;
        params.progress = progress;
        return planning::planRegionLines(part, fields, mask, spacing, params);
      },
      tr("coverage"), note);
}

}  // namespace ddfcam::gui
