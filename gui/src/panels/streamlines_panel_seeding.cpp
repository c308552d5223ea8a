// SPDX-License-Identifier: MIT
// ddfcam gui: StreamlinesPanel seeding: a click, a family along the transverse line, coverage.
#include <ddfcam/gui/panels/streamlines_panel.h>

#include "streamlines_fields.h"

#include <ddfcam/ddf/crust_hash.h>
#include <ddfcam/gui/document.h>
#include <ddfcam/gui/job_runner.h>
#include <ddfcam/planning/evenly_spaced_streamlines.h>
#include <ddfcam/planning/scallop_spacing.h>
#include <ddfcam/planning/streamline_continuous.h>
#include <ddfcam/planning/streamline_raster_walk.h>

#include <QDoubleSpinBox>

#include <algorithm>
#include <limits>
#include <memory>
#include <optional>

namespace ddfcam::gui {

namespace {

/// The lines through @p seeds traced by @p method (one crust hash for all continuous lines).
std::vector<planning::Streamline> traceAll(planning::StreamlineMethod method,
                                           const ddf::DisplacementField& part,
                                           const planning::LineField& field,
                                           const std::vector<ddf::SurfaceLocation>& seeds,
                                           const planning::StreamlineParams& params,
                                           const ProgressCallback& progress) {
  std::optional<ddf::CrustHash> hash;
  if (method == planning::StreamlineMethod::Continuous) hash.emplace(part);
  planning::ContinuousStreamlineParams continuous;
  continuous.crustHash = hash ? &*hash : nullptr;
  std::vector<planning::Streamline> lines;
  for (std::size_t s = 0; s < seeds.size(); ++s) {
    reportProgress(progress, static_cast<double>(s) / seeds.size());
    lines.push_back(
        planning::traceStreamlineWith(method, part, field, seeds[s], params, {}, continuous));
  }
  reportProgress(progress, 1.0);
  return lines;
}

/// Floor of the curvature-dependent spacing, mm: the spin boxes' smallest value.
constexpr double kMinSpacingMm = 0.05;

}  // namespace

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
        return traceAll(method, part, fields.field, {seed}, params, nullptr);
      },
      tr("streamline"));
}

bool StreamlinesPanel::seedFamily() {
  if (!lastPick_) {
    workbench().reportError(tr("Seed family"), tr("Pick a point on the part first."));
    return false;
  }
  const ddf::SurfaceLocation seed = *lastPick_;
  const double spacing = spacing_->value();
  const std::vector<std::uint8_t> mask = currentChoice().faceMask;
  const planning::StreamlineMethod method = streamlineMethod();
  return runWithFields(
      tr("Seed streamline family"),
      [seed, spacing, mask, method](const ddf::DisplacementField& part, const Fields& fields,
                                    const ProgressCallback& progress) {
        planning::StreamlineParams params;
        params.faceMask = mask;
        if (method == planning::StreamlineMethod::Rk4) {
          params.progress = progress;
          return planning::seedAlongTransverse(part, fields.field, fields.transverse, seed, spacing,
                                               params);
        }
        // The seeds as seedAlongTransverse places them; the family's lines by the method.
        const planning::Streamline transverse =
            planning::traceStreamline(part, fields.transverse, seed, params);
        return traceAll(method, part, fields.field, planning::seedsAlong(part, transverse, spacing),
                        params, progress);
      },
      tr("streamline family"));
}

bool StreamlinesPanel::coverRegion(double dSepMm) {
  if (!(dSepMm > 0)) {
    workbench().reportError(tr("Cover region"), tr("d_sep must be positive."));
    return false;
  }
  const std::vector<std::uint8_t> mask = currentChoice().faceMask;
  const planning::RegionPlan* plan = selectedPlan();
  const auto& tools = workbench().document.project().tools;
  auto note = std::make_shared<QString>();
  // Scallop-height spacing needs a curved cross-feed profile: a ball's (radius), not a roll's.
  std::optional<double> ballRadius;
  double scallopMm = 0.0;
  if (plan && plan->spacingMode == planning::SpacingMode::ScallopTolerance) {
    const int t = plan->tool >= 0 && plan->tool < static_cast<int>(tools.size()) ? plan->tool : 0;
    const planning::Tool tool = tools.empty() ? planning::Tool{} : tools[t];
    ballRadius = planning::effectiveCrossFeedRadiusMm(tool);
    scallopMm = plan->scallopToleranceMm;
    if (!ballRadius) {
      dSepMm = plan->spacingMm;
      *note = tr("Scallop tolerance not applied: a straight roll has no scallop formula, the "
                 "plan's fixed spacing %1 mm is used.")
                  .arg(dSepMm, 0, 'g', 4);
    }
  }
  return runWithFields(
      tr("Cover region with streamlines"),
      [dSepMm, mask, ballRadius, scallopMm, note](const ddf::DisplacementField& part,
                                                  const Fields& fields,
                                                  const ProgressCallback& progress) {
        planning::EvenSpacingParams params;
        params.separationMm = dSepMm;
        params.faceMask = mask;
        params.progress = progress;
        if (ballRadius) {
          std::vector<float> spacing = planning::scallopSpacingField(
              part, *fields.curvature, fields.field, *ballRadius, scallopMm);
          // No line runs where the field is undefined (outside the region, singular points):
          // their plane values must not set the smallest spacing (NaN reads as the smallest).
          for (std::size_t i = 0; i < spacing.size(); ++i)
            if (!(fields.field[i].squaredNorm() > 0))
              spacing[i] = std::numeric_limits<float>::quiet_NaN();
          const double smallest =
              std::max(planning::smallestFiniteSpacing(spacing).value_or(dSepMm), kMinSpacingMm);
          params.separationMm = smallest;
          params.separationAt = planning::spacingFunction(part, spacing, smallest);
          *note = tr("Scallop height %1 mm with a ball of radius %2 mm: spacing from %3 mm by "
                     "cross-feed curvature.")
                      .arg(scallopMm, 0, 'g', 3)
                      .arg(*ballRadius, 0, 'g', 4)
                      .arg(smallest, 0, 'f', 3);
        }
        return planning::evenlySpacedStreamlines(part, fields.field, params);
      },
      tr("coverage"), note);
}

}  // namespace ddfcam::gui
