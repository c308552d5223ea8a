// SPDX-License-Identifier: MIT
// ddfcam gui: MouldToolsPanel: the blended surface f = s + d h v over the study's comparison,
// with its blending function and the picks and brush strokes in the mould view.
#include <ddfcam/gui/panels/mould_tools_panel.h>

#include "mould_tools_widgets.h"

#include <ddfcam/ddf/ddf_warp.h>
#include <ddfcam/ddf/deformation_sequence.h>
#include <ddfcam/error.h>
#include <ddfcam/gui/document.h>
#include <ddfcam/gui/interaction_mode.h>
#include <ddfcam/planning/model/project.h>

#include <QComboBox>
#include <QDoubleSpinBox>
#include <QFormLayout>
#include <QGroupBox>
#include <QLabel>
#include <QPushButton>
#include <QSignalBlocker>
#include <QVBoxLayout>

#include <algorithm>

namespace ddfcam::gui {
namespace {

const ddf::DeformationSequence& studySequence(const planning::Project& project) {
  if (!project.mould || !project.mould->result || project.mould->result->sequence.stages.empty())
    throw InvalidInput("compare the formed surface with the mould first (no comparison)");
  return project.mould->result->sequence;
}

}  // namespace

QGroupBox* MouldToolsPanel::buildBlending() {
  auto* group = new QGroupBox(tr("Blending f = s + d h v"), this);
  group->setObjectName("blendingGroup");
  QFormLayout* form = buildBlendForm(group);
  blendLabel_ = new QLabel(group);
  blendLabel_->setObjectName("blendLabel");
  auto* show = new QPushButton(tr("Show blended surface"), group);
  show->setObjectName("showBlendedButton");
  auto* clearPaint = new QPushButton(tr("Clear painted region"), group);
  clearPaint->setObjectName("clearPaintButton");
  auto* box = new QVBoxLayout(group);
  box->addLayout(form);
  box->addWidget(blendLabel_);
  box->addWidget(show);
  box->addWidget(clearPaint);
  connect(show, &QPushButton::clicked, this, [this] { showBlended(); });
  connect(clearPaint, &QPushButton::clicked, this, [this] {
    blend_.faces.clear();
    refreshBlendWidgets();
  });
  refreshBlendWidgets();
  return group;
}

QFormLayout* MouldToolsPanel::buildBlendForm(QGroupBox* group) {
  const planning::BlendParams defaults;
  blendKind_ = new QComboBox(group);
  blendKind_->setObjectName("blendKindCombo");
  blendKind_->addItem(tr("Constant"), static_cast<int>(planning::BlendKind::Constant));
  blendKind_->addItem(tr("Radial fall-off"), static_cast<int>(planning::BlendKind::Radial));
  blendKind_->addItem(tr("Painted region"), static_cast<int>(planning::BlendKind::Region));
  blendKind_->addItem(tr("Distance to boundary"), static_cast<int>(planning::BlendKind::Boundary));
  blendValue_ = mould_tools::decimalSpin(group, "blendValueSpin", -5.0, 5.0, defaults.value, {});
  blendRadius_ =
      mould_tools::decimalSpin(group, "blendRadiusSpin", 0.01, 1e5, defaults.radiusMm, " mm");
  blendEdge_ =
      mould_tools::decimalSpin(group, "blendEdgeSpin", 0.01, 1e5, defaults.edgeWidthMm, " mm");
  blendBoundary_ =
      mould_tools::decimalSpin(group, "blendBoundarySpin", 0.01, 1e5, defaults.widthMm, " mm");
  brush_ = mould_tools::decimalSpin(group, "brushRadiusSpin", 0.01, 1e5, 5.0, " mm");
  pickMode_ = new QComboBox(group);
  pickMode_->setObjectName("blendPickModeCombo");
  pickMode_->addItem(tr("nothing"), static_cast<int>(BlendPickMode::None));
  pickMode_->addItem(tr("sets the radial centre"), static_cast<int>(BlendPickMode::PickCentre));
  pickMode_->addItem(tr("paints the region"), static_cast<int>(BlendPickMode::PaintRegion));
  auto* form = new QFormLayout;
  form->addRow(tr("Function d"), blendKind_);
  form->addRow(tr("Strength"), blendValue_);
  form->addRow(tr("Fall-off radius"), blendRadius_);
  form->addRow(tr("Region edge width"), blendEdge_);
  form->addRow(tr("Boundary width"), blendBoundary_);
  form->addRow(tr("Brush radius"), brush_);
  form->addRow(tr("Click in mould view"), pickMode_);
  connect(pickMode_, &QComboBox::currentIndexChanged, this, [this] {
    InteractionMode* modes = workbench().mode;
    if (!modes) return;
    const auto mode = static_cast<BlendPickMode>(pickMode_->currentData().toInt());
    if (mode == BlendPickMode::None) return modes->clear(this);
    modes->begin(this, tr("Blend"),
                 mode == BlendPickMode::PickCentre
                     ? tr("click the fall-off centre")
                     : tr("click to paint the region"),
                 [this] { setBlendPickMode(BlendPickMode::None); });
  });
  return form;
}

void MouldToolsPanel::refreshBlendWidgets() {
  blendLabel_->setText(tr("centre (%1, %2, %3) mm; %4 painted faces")
                           .arg(blend_.centreMm.x(), 0, 'g', 5)
                           .arg(blend_.centreMm.y(), 0, 'g', 5)
                           .arg(blend_.centreMm.z(), 0, 'g', 5)
                           .arg(blend_.faces.size()));
}

void MouldToolsPanel::setBlendParams(planning::BlendParams params) {
  blendKind_->setCurrentIndex(blendKind_->findData(static_cast<int>(params.kind)));
  blendValue_->setValue(params.value);
  blendRadius_->setValue(params.radiusMm);
  blendEdge_->setValue(params.edgeWidthMm);
  blendBoundary_->setValue(params.widthMm);
  blend_ = std::move(params);
  refreshBlendWidgets();
}

planning::BlendParams MouldToolsPanel::blendParams() const {
  planning::BlendParams params = blend_;
  params.kind = static_cast<planning::BlendKind>(blendKind_->currentData().toInt());
  params.value = blendValue_->value();
  params.radiusMm = blendRadius_->value();
  params.edgeWidthMm = blendEdge_->value();
  params.widthMm = blendBoundary_->value();
  return params;
}

void MouldToolsPanel::setBlendPickMode(BlendPickMode mode) {
  pickMode_->setCurrentIndex(pickMode_->findData(static_cast<int>(mode)));
}

void MouldToolsPanel::setBrushRadius(double radiusMm) {
  brush_->setValue(radiusMm);
}

void MouldToolsPanel::applyPick(const Eigen::Vector3d& point) {
  const auto mode = static_cast<BlendPickMode>(pickMode_->currentData().toInt());
  if (mode == BlendPickMode::None) return;
  runUserAction(workbench().reportError, tr("Blending pick"), [&] {
    if (mode == BlendPickMode::PickCentre) {
      blend_.centreMm = point;
      blendKind_->setCurrentIndex(
          blendKind_->findData(static_cast<int>(planning::BlendKind::Radial)));
    } else {
      const ddf::DisplacementField& mould =
          studySequence(workbench().document.project()).stages.front().ddf;
      const std::vector<int> faces = planning::facesWithinRadius(mould, point, brush_->value());
      blend_.faces.insert(blend_.faces.end(), faces.begin(), faces.end());
      std::sort(blend_.faces.begin(), blend_.faces.end());
      blend_.faces.erase(std::unique(blend_.faces.begin(), blend_.faces.end()), blend_.faces.end());
      blendKind_->setCurrentIndex(
          blendKind_->findData(static_cast<int>(planning::BlendKind::Region)));
    }
    refreshBlendWidgets();
  });
  showBlended();
}

// Synchronous: the weights are one Dijkstra over the lattice and the positions one pass, far
// below a second on the shared pair's 41,000 faces at the default resolution.
bool MouldToolsPanel::showBlended() {
  return runUserAction(workbench().reportError, tr("Blended surface"), [&] {
    const ddf::DeformationSequence& sequence = studySequence(workbench().document.project());
    const ddf::DisplacementField& mould = sequence.stages.front().ddf;
    std::vector<float> weights = planning::blendWeights(mould, blendParams());
    const std::vector<ddf::Vec3> positions = ddf::morphPositions(sequence, weights);
    showSurface(ddf::morphMesh(mould, positions), true, false);
    weights_ = std::move(weights);
  });
}

}  // namespace ddfcam::gui
