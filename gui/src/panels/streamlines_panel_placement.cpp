// SPDX-License-Identifier: MIT
// ddfcam gui: the "Tool placement" group of the Streamlines panel (lead, tilt, sampling from a
// tolerance) and the placement of new paths with it.
#include <ddfcam/gui/panels/streamlines_panel.h>

#include <QCheckBox>
#include <QDoubleSpinBox>
#include <QFormLayout>
#include <QGroupBox>
#include <QHBoxLayout>
#include <QLabel>
#include <QSignalBlocker>

#include <algorithm>
#include <utility>

namespace ddfcam::gui {

namespace {

QDoubleSpinBox* spinBox(QWidget* parent, const char* name, double lo, double hi, double value,
                        int decimals, const QString& suffix) {
  auto* box = new QDoubleSpinBox(parent);
  box->setObjectName(name);
  box->setDecimals(decimals);
  box->setRange(lo, hi);
  box->setValue(value);
  box->setSuffix(suffix);
  return box;
}

}  // namespace

QWidget* StreamlinesPanel::buildPlacementGroup() {
  auto* group = new QGroupBox(tr("Tool placement"), this);
  lead_ = spinBox(group, "placementLead", -89.0, 89.0, 0.0, 1, tr(" deg"));
  lead_->setToolTip(tr("Lead angle: the tool axis leans towards the feed"));
  tilt_ = spinBox(group, "placementTilt", -89.0, 89.0, 0.0, 1, tr(" deg"));
  tilt_->setToolTip(tr("Tilt angle: the tool axis turns about the feed"));
  sampleFromTolerance_ = new QCheckBox(tr("sample from tolerance"), group);
  sampleFromTolerance_->setObjectName("sampleFromTolerance");
  tolerance_ = spinBox(group, "samplingTolerance", 0.0001, 10.0, 0.01, 4, tr(" mm"));
  overrideStep_ = new QCheckBox(tr("step"), group);
  overrideStep_->setObjectName("overrideSamplingStep");
  step_ = spinBox(group, "samplingStep", 0.001, 1000.0, 0.5, 3, tr(" mm"));
  samplingLabel_ = new QLabel(tr("poses at the streamline points"), group);
  samplingLabel_->setObjectName("samplingLabel");
  samplingLabel_->setWordWrap(true);
  // Two short rows each, so the group never widens the dock beyond the other panels.
  auto* angles = new QHBoxLayout;
  angles->addWidget(lead_);
  angles->addWidget(new QLabel(tr("tilt"), group));
  angles->addWidget(tilt_);
  auto* step = new QHBoxLayout;
  step->addWidget(overrideStep_);
  step->addWidget(step_);
  auto* form = new QFormLayout(group);
  form->addRow(tr("lead"), angles);
  form->addRow(sampleFromTolerance_, tolerance_);
  form->addRow(step);
  form->addRow(samplingLabel_);
  const auto sync = [this] {
    tolerance_->setEnabled(sampleFromTolerance_->isChecked());
    overrideStep_->setEnabled(sampleFromTolerance_->isChecked());
    step_->setEnabled(sampleFromTolerance_->isChecked() && overrideStep_->isChecked());
  };
  connect(sampleFromTolerance_, &QCheckBox::toggled, this, sync);
  connect(overrideStep_, &QCheckBox::toggled, this, sync);
  sync();
  return group;
}

void StreamlinesPanel::setPlacementAngles(double leadDeg, double tiltDeg) {
  lead_->setValue(leadDeg);
  tilt_->setValue(tiltDeg);
}

void StreamlinesPanel::setSampling(bool fromTolerance, double toleranceMm,
                                   std::optional<double> stepOverrideMm) {
  tolerance_->setValue(toleranceMm);
  if (stepOverrideMm) step_->setValue(*stepOverrideMm);
  overrideStep_->setChecked(stepOverrideMm.has_value());
  sampleFromTolerance_->setChecked(fromTolerance);
}

planning::StreamlinePathParams StreamlinesPanel::placementParams() const {
  planning::StreamlinePathParams params;
  params.placement.leadDeg = lead_->value();
  params.placement.tiltDeg = tilt_->value();
  if (sampleFromTolerance_->isChecked()) {
    planning::PathSamplingParams sampling;
    sampling.toleranceMm = tolerance_->value();
    if (overrideStep_->isChecked()) sampling.stepOverrideMm = step_->value();
    params.sampling = sampling;
  }
  return params;
}

planning::ToolPath StreamlinesPanel::placeLines(const ddf::DisplacementField& part,
                                                const std::vector<planning::Streamline>& lines,
                                                const planning::Tool& tool, int toolIndex,
                                                planning::StreamlinePathParams params) {
  const planning::StreamlinePathParams placement = placementParams();
  params.placement = placement.placement;
  params.sampling = placement.sampling;
  planning::PlacedPath placed =
      planning::toolPathFromStreamlinesDetailed(part, lines, tool, toolIndex, params);
  lastSampling_ = std::move(placed.passes);
  showSampling();
  return std::move(placed.path);
}

void StreamlinesPanel::showSampling() {
  if (lastSampling_.empty()) {
    samplingLabel_->setText(tr("poses at the streamline points"));
    return;
  }
  // The finest pass decides what the user has to know about the path.
  const auto finest =
      std::min_element(lastSampling_.begin(), lastSampling_.end(),
                       [](const auto& a, const auto& b) { return a.step.stepMm < b.step.stepMm; });
  int inserted = 0;
  for (const planning::PassSampling& pass : lastSampling_) inserted += pass.sweepInsertedPoses;
  QString text = tr("step %1 mm (%2)")
                     .arg(finest->step.stepMm, 0, 'g', 6)
                     .arg(QString::fromUtf8(planning::stepRuleName(finest->step.rule)));
  if (inserted > 0) text += tr(", %1 poses added by the orientation sweep").arg(inserted);
  samplingLabel_->setText(text);
}

}  // namespace ddfcam::gui
