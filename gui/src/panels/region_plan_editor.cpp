// SPDX-License-Identifier: MIT
// ddfcam gui: RegionPlanEditor.
#include <ddfcam/gui/panels/region_plan_editor.h>

#include <QCheckBox>
#include <QComboBox>
#include <QDoubleSpinBox>
#include <QFormLayout>
#include <QHBoxLayout>
#include <QSignalBlocker>

#include <memory>

namespace ddfcam::gui {
namespace {

QDoubleSpinBox* spinBox(QWidget* parent, const char* name, double lo, double hi, int decimals,
                        const QString& suffix = {}) {
  auto* box = new QDoubleSpinBox(parent);
  box->setObjectName(name);
  box->setRange(lo, hi);
  box->setDecimals(decimals);
  box->setSuffix(suffix);
  box->setKeyboardTracking(false);
  return box;
}

QComboBox* comboBox(QWidget* parent, const char* name, const QStringList& items) {
  auto* box = new QComboBox(parent);
  box->setObjectName(name);
  box->addItems(items);
  // Narrow docks: the combo may be narrower than its longest entry (the popup shows it all).
  box->setSizeAdjustPolicy(QComboBox::AdjustToMinimumContentsLengthWithIcon);
  box->setMinimumContentsLength(8);
  return box;
}

// The box's value, or @p shown if the box still displays @p shown (rounded to its decimals):
// a value the box cannot represent must not change just because another choice was edited.
double valueOr(const QDoubleSpinBox* box, double shown) {
  const double displayed = QString::number(shown, 'f', box->decimals()).toDouble();
  return box->value() == displayed ? shown : box->value();
}

}  // namespace

RegionPlanEditor::RegionPlanEditor(QWidget* parent) : QWidget(parent) {
  tool_ = comboBox(this, "regionTool", {tr("(no tool)")});
  source_ = comboBox(this, "regionFlowSource",
                     {tr("direction of k_max"), tr("direction of k_min"), tr("fixed direction"),
                      tr("drawn strokes")});
  auto* directionRow = new QHBoxLayout;
  const char* names[3] = {"regionDirectionX", "regionDirectionY", "regionDirectionZ"};
  for (int a = 0; a < 3; ++a) {
    direction_[a] = spinBox(this, names[a], -1e3, 1e3, 3);
    direction_[a]->setButtonSymbols(QAbstractSpinBox::NoButtons);  // three in a row
    direction_[a]->setMinimumWidth(40);
    directionRow->addWidget(direction_[a]);
  }
  smooth_ = new QCheckBox(tr("Smooth the field"), this);
  smooth_->setObjectName("regionSmooth");
  weight_ = spinBox(this, "regionSmoothWeight", 0.0, 1e3, 4);
  weight_->setSingleStep(0.01);
  spacingMode_ =
      comboBox(this, "regionSpacingMode", {tr("fixed spacing"), tr("scallop tolerance")});
  spacing_ = spinBox(this, "regionSpacing", 0.001, 1e3, 3, " mm");
  tolerance_ = spinBox(this, "regionScallopTolerance", 0.0001, 10.0, 4, " mm");
  tolerance_->setSingleStep(0.001);
  tolerance_->setToolTip(
      tr("Largest scallop height between paths: with a ball the path spacing "
         "follows the cross-feed curvature; a straight roll has no scallop "
         "formula and uses the fixed spacing"));
  feed_ = comboBox(this, "regionFeedSign", {tr("+ along the field"), tr("- against the field")});
  linking_ = comboBox(this, "regionLinking", {tr("zig-zag"), tr("one direction")});

  auto* form = new QFormLayout(this);
  form->setContentsMargins(0, 0, 0, 0);
  form->addRow(tr("Tool"), tool_);
  form->addRow(tr("Flow field"), source_);
  form->addRow(tr("Direction"), directionRow);
  form->addRow(smooth_);
  form->addRow(tr("Smoothness weight"), weight_);
  form->addRow(tr("Spacing by"), spacingMode_);
  form->addRow(tr("Spacing"), spacing_);
  form->addRow(tr("Scallop tolerance"), tolerance_);
  form->addRow(tr("Feed"), feed_);
  form->addRow(tr("Linking"), linking_);

  for (QComboBox* box : {tool_, source_, spacingMode_, feed_, linking_})
    connect(box, &QComboBox::currentIndexChanged, this, &RegionPlanEditor::emitEdited);
  connect(smooth_, &QCheckBox::toggled, this, &RegionPlanEditor::emitEdited);
  // editingFinished also fires on focus loss without a change; emitEdited drops no-ops.
  for (QDoubleSpinBox* box :
       {direction_[0], direction_[1], direction_[2], weight_, spacing_, tolerance_})
    connect(box, &QDoubleSpinBox::editingFinished, this, &RegionPlanEditor::emitEdited);
  updateEnabled();
}

void RegionPlanEditor::setPlan(const planning::RegionPlan& plan,
                               const std::vector<planning::Tool>& tools) {
  const QList<QWidget*> all = findChildren<QWidget*>();
  std::vector<std::unique_ptr<QSignalBlocker>> blockers;
  for (QWidget* w : all) blockers.push_back(std::make_unique<QSignalBlocker>(w));
  shown_ = plan;
  tool_->clear();
  tool_->addItem(tr("(no tool)"));
  for (const planning::Tool& tool : tools) tool_->addItem(QString::fromStdString(tool.name));
  tool_->setCurrentIndex(
      plan.tool >= 0 && plan.tool < static_cast<int>(tools.size()) ? plan.tool + 1 : 0);
  source_->setCurrentIndex(static_cast<int>(plan.flowSource));
  for (int a = 0; a < 3; ++a) direction_[a]->setValue(plan.fixedDirection[a]);
  smooth_->setChecked(plan.smoothField);
  weight_->setValue(plan.smoothnessWeight);
  spacingMode_->setCurrentIndex(static_cast<int>(plan.spacingMode));
  spacing_->setValue(plan.spacingMm);
  tolerance_->setValue(plan.scallopToleranceMm);
  feed_->setCurrentIndex(plan.feedSign < 0 ? 1 : 0);
  linking_->setCurrentIndex(static_cast<int>(plan.linking));
  updateEnabled();
}

planning::RegionPlan RegionPlanEditor::plan() const {
  planning::RegionPlan plan = shown_;
  plan.tool = tool_->currentIndex() - 1;
  plan.flowSource = static_cast<planning::FlowFieldSource>(source_->currentIndex());
  const ddf::Vec3 direction(valueOr(direction_[0], shown_.fixedDirection.x()),
                            valueOr(direction_[1], shown_.fixedDirection.y()),
                            valueOr(direction_[2], shown_.fixedDirection.z()));
  // A zero direction is no direction: keep the previous one rather than store it.
  if (direction.norm() > 0.0) plan.fixedDirection = direction;
  plan.smoothField = smooth_->isChecked();
  plan.smoothnessWeight = valueOr(weight_, shown_.smoothnessWeight);
  plan.spacingMode = static_cast<planning::SpacingMode>(spacingMode_->currentIndex());
  plan.spacingMm = valueOr(spacing_, shown_.spacingMm);
  plan.scallopToleranceMm = valueOr(tolerance_, shown_.scallopToleranceMm);
  plan.feedSign = feed_->currentIndex() == 1 ? -1 : 1;
  plan.linking = static_cast<planning::LinkingOrder>(linking_->currentIndex());
  return plan;
}

void RegionPlanEditor::updateEnabled() {
  const bool fixed =
      source_->currentIndex() == static_cast<int>(planning::FlowFieldSource::FixedDirection);
  for (QDoubleSpinBox* box : direction_) box->setEnabled(fixed);
  weight_->setEnabled(smooth_->isChecked());
  // The fixed spacing also serves a scallop-tolerance plan whose tool is a straight roll.
  tolerance_->setEnabled(spacingMode_->currentIndex() != 0);
  const auto strokes = static_cast<int>(shown_.strokes.size());
  source_->setItemText(static_cast<int>(planning::FlowFieldSource::UserStrokes),
                       tr("drawn strokes (%1)").arg(strokes));
  source_->setToolTip(tr("Strokes are drawn in the Streamlines panel with this region chosen"));
}

void RegionPlanEditor::emitEdited() {
  updateEnabled();
  const planning::RegionPlan edited = plan();
  if (edited == shown_) return;
  shown_ = edited;
  emit planEdited(edited);
}

}  // namespace ddfcam::gui
