// SPDX-License-Identifier: MIT
// ddfcam gui: SimulationOptions.
#include <ddfcam/gui/panels/simulation_options.h>

#include <QCheckBox>
#include <QComboBox>
#include <QDoubleSpinBox>
#include <QFormLayout>
#include <QSignalBlocker>

namespace ddfcam::gui {

namespace {

/// K_p is shown in units of 1e-7 mm^2/N (1e-13 m^2/N, the order of real grinding values).
constexpr double kCoefficientUnit = 1e-7;

QDoubleSpinBox* makeSpin(QWidget* parent, const char* name, double lo, double hi, int decimals,
                         double value, const QString& suffix) {
  auto* spin = new QDoubleSpinBox(parent);
  spin->setObjectName(name);
  spin->setRange(lo, hi);
  spin->setDecimals(decimals);
  spin->setValue(value);
  spin->setSuffix(suffix);
  return spin;
}

}  // namespace

SimulationOptions::SimulationOptions(QWidget* parent) : QWidget(parent) {
  auto* form = new QFormLayout(this);
  form->setContentsMargins(0, 0, 0, 0);
  mode_ = new QComboBox(this);
  mode_->setObjectName("sweepModeCombo");
  mode_->addItem(tr("Discrete"), static_cast<int>(planning::SweepMode::Discrete));
  mode_->addItem(tr("Swept volume"), static_cast<int>(planning::SweepMode::Swept));
  mode_->setToolTip(
      tr("Swept volume cuts the hull of the tool at consecutive poses, so the "
         "result does not depend on the sampling step (convex tools only)"));
  form->addRow(tr("Mode"), mode_);
  vConvexity_ = new QCheckBox(tr("V-convexity check"), this);
  vConvexity_->setObjectName("vConvexityCheck");
  vConvexity_->setChecked(true);
  collisions_ = new QCheckBox(tr("Collision check"), this);
  collisions_->setObjectName("collisionCheck");
  collisions_->setChecked(true);
  form->addRow(vConvexity_);
  form->addRow(collisions_);
  model_ = new QComboBox(this);
  model_->setObjectName("removalModelCombo");
  model_->addItem(tr("Rigid (depth buffer)"), static_cast<int>(RemovalModel::Rigid));
  model_->addItem(tr("Preston (compliant)"), static_cast<int>(RemovalModel::Preston));
  form->addRow(tr("Removal"), model_);
  // Units shown are the shop-floor ones; prestonParams() converts to mm, N, s.
  const planning::PrestonParams d;
  coefficient_ = makeSpin(this, "prestonCoefficientSpin", 1e-5, 1e7, 5,
                          d.prestonCoefficientMm2PerN / kCoefficientUnit, tr(" ×10⁻⁷ mm²/N"));
  force_ = makeSpin(this, "prestonForceSpin", 0.01, 1e5, 2, d.forceN, tr(" N"));
  speed_ =
      makeSpin(this, "prestonSpeedSpin", 0.01, 500.0, 2, d.surfaceSpeedMmPerS / 1000.0, tr(" m/s"));
  feed_ = makeSpin(this, "prestonFeedSpin", 1.0, 1e6, 1, d.feedMmPerS * 60.0, tr(" mm/min"));
  form->addRow(tr("K_p"), coefficient_);
  form->addRow(tr("Force"), force_);
  form->addRow(tr("Wheel speed"), speed_);
  feed_->setToolTip(tr("Feed of the selected path: saved with it, written to exported programs"));
  feed_->setKeyboardTracking(false);  // one path edit per entered value, not per keystroke
  form->addRow(tr("Feed"), feed_);
  for (QComboBox* combo : {mode_, model_})
    connect(combo, &QComboBox::currentIndexChanged, this, &SimulationOptions::changed);
  for (QCheckBox* box : {vConvexity_, collisions_})
    connect(box, &QCheckBox::toggled, this, &SimulationOptions::changed);
  for (QDoubleSpinBox* spin : {coefficient_, force_, speed_, feed_})
    connect(spin, &QDoubleSpinBox::valueChanged, this, &SimulationOptions::changed);
  connect(feed_, &QDoubleSpinBox::valueChanged, this, &SimulationOptions::feedEdited);
  connect(model_, &QComboBox::currentIndexChanged, this, &SimulationOptions::updateEnabled);
  updateEnabled();
}

planning::GrindingSimulationParams SimulationOptions::grindingParams() const {
  planning::GrindingSimulationParams p;
  p.mode = static_cast<planning::SweepMode>(mode_->currentData().toInt());
  p.checkVConvexity = vConvexity_->isChecked();
  p.checkCollisions = collisions_->isChecked();
  return p;
}

planning::PrestonParams SimulationOptions::prestonParams() const {
  planning::PrestonParams p;
  p.prestonCoefficientMm2PerN = coefficient_->value() * kCoefficientUnit;
  p.forceN = force_->value();
  p.surfaceSpeedMmPerS = speed_->value() * 1000.0;
  p.feedMmPerS = feed_->value() / 60.0;
  return p;
}

RemovalModel SimulationOptions::removalModel() const {
  return static_cast<RemovalModel>(model_->currentData().toInt());
}

void SimulationOptions::setSweepMode(planning::SweepMode mode) {
  mode_->setCurrentIndex(mode_->findData(static_cast<int>(mode)));
}

void SimulationOptions::setRemovalModel(RemovalModel model) {
  model_->setCurrentIndex(model_->findData(static_cast<int>(model)));
}

void SimulationOptions::setChecks(bool vConvexity, bool collisions) {
  vConvexity_->setChecked(vConvexity);
  collisions_->setChecked(collisions);
}

void SimulationOptions::setPreston(double coefficientMm2PerN, double forceN, double speedMPerS,
                                   double feedMmPerMin) {
  coefficient_->setValue(coefficientMm2PerN / kCoefficientUnit);
  force_->setValue(forceN);
  speed_->setValue(speedMPerS);
  feed_->setValue(feedMmPerMin);
}

void SimulationOptions::showFeed(double feedMmPerMin) {
  const QSignalBlocker block(feed_);
  feed_->setValue(feedMmPerMin);
}

void SimulationOptions::updateEnabled() {
  const bool preston = removalModel() == RemovalModel::Preston;
  for (QWidget* w : {static_cast<QWidget*>(coefficient_), static_cast<QWidget*>(force_),
                     static_cast<QWidget*>(speed_), static_cast<QWidget*>(feed_)})
    w->setEnabled(preston);
  // Preston removal has no depth buffer: sweep mode and the checks do not apply to it.
  mode_->setEnabled(!preston);
  vConvexity_->setEnabled(!preston);
  collisions_->setEnabled(!preston);
}

}  // namespace ddfcam::gui
