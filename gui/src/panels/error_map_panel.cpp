// SPDX-License-Identifier: MIT
// ddfcam gui: ErrorMapPanel: inputs, the error-map job and the band.
#include <ddfcam/gui/panels/error_map_panel.h>

#include <ddfcam/error.h>
#include <ddfcam/gui/document.h>
#include <ddfcam/gui/document_command.h>
#include <ddfcam/gui/job_runner.h>
#include <ddfcam/gui/part_view.h>
#include <ddfcam/gui/plot_dock.h>
#include <ddfcam/planning/model/field_freshness.h>
#include <ddfcam/planning/simulation/workpiece.h>

#include <QComboBox>
#include <QDoubleSpinBox>
#include <QFormLayout>
#include <QLabel>
#include <QPushButton>
#include <QSignalBlocker>
#include <QVBoxLayout>

#include <limits>
#include <memory>

namespace ddfcam::gui {
namespace {

QDoubleSpinBox* bandSpin(QWidget* parent, const char* name, double value) {
  auto* spin = new QDoubleSpinBox(parent);
  spin->setObjectName(name);
  spin->setDecimals(4);
  spin->setSingleStep(0.001);
  spin->setRange(value < 0.0 ? -100.0 : 0.0, value < 0.0 ? 0.0 : 100.0);
  spin->setSuffix(QStringLiteral(" mm"));
  spin->setValue(value);
  return spin;
}

// The desired heights on the part's own support: a stored state as it is, or the design mesh
// put onto the stubbles. Points whose stubble misses the mesh get NaN, so they have no
// deviation and count against the coverage instead of as "in tolerance".
std::vector<float> desiredHeights(const ddf::DisplacementField& part,
                                  const std::optional<std::vector<float>>& state,
                                  const std::optional<ddf::TriangleMesh>& design,
                                  const ProgressCallback& progress) {
  if (state) return *state;
  planning::StockWorkpieceParams params;
  params.requireFullCoverage = false;
  params.fill.progress = progress;
  planning::StockWorkpiece stock = planning::workpieceFromStockMesh(part, *design, params);
  std::vector<float> heights = std::move(stock.workpiece.allHeights());
  for (std::size_t l = 0; l < heights.size(); ++l)
    if (l < stock.missingMask.size() && stock.missingMask[l] != 0)
      heights[l] = std::numeric_limits<float>::quiet_NaN();
  return heights;
}

}  // namespace

ErrorMapPanel::ErrorMapPanel(Workbench& workbench, QWidget* parent) : Panel(workbench, parent) {
  buildInputs();
  buildOutputs();
  connect(&workbench.document, &Document::changed, this, [this](Changes what) {
    if (what & (Change::Part | Change::States | Change::Regions | Change::Paths)) refreshChoices();
    if (what & (Change::Part | Change::Fields | Change::Regions | Change::Heights))
      updateStatistics();
  });
  refreshChoices();
  updateStatistics();
}

void ErrorMapPanel::buildInputs() {
  auto* layout = new QVBoxLayout(this);
  auto* form = new QFormLayout;
  desired_ = new QComboBox(this);
  desired_->setObjectName("desiredSurfaceCombo");
  region_ = new QComboBox(this);
  region_->setObjectName("errorRegionCombo");
  lower_ = bandSpin(this, "toleranceLowerSpin", -0.01);
  upper_ = bandSpin(this, "toleranceUpperSpin", 0.01);
  form->addRow(tr("Desired surface"), desired_);
  form->addRow(tr("Region"), region_);
  form->addRow(tr("Lower tolerance e_l"), lower_);
  form->addRow(tr("Upper tolerance e_u"), upper_);
  layout->addLayout(form);
  compute_ = new QPushButton(tr("Compute error map"), this);
  compute_->setObjectName("computeErrorMapButton");
  layout->addWidget(compute_);
  connect(compute_, &QPushButton::clicked, this, [this] { computeErrorMap(); });
  connect(lower_, &QDoubleSpinBox::valueChanged, this, [this] { onBandEdited(); });
  connect(upper_, &QDoubleSpinBox::valueChanged, this, [this] { onBandEdited(); });
  connect(region_, &QComboBox::currentIndexChanged, this, [this] { updateStatistics(); });
}

void ErrorMapPanel::refreshChoices() {
  const planning::Project& p = workbench().document.project();
  const QSignalBlocker blockDesired(desired_), blockRegion(region_), blockPath(path_);
  const int desired = desired_->currentData().isValid() ? desired_->currentData().toInt() : 0;
  const int region = region_->currentIndex(), path = path_->currentIndex();
  desired_->clear();
  for (std::size_t s = 0; s < p.states.size(); ++s)
    desired_->addItem(tr("state '%1'").arg(QString::fromStdString(p.states[s].name)),
                      static_cast<int>(s));
  if (p.designMesh) desired_->addItem(tr("design mesh"), -1);
  const int at = desired_->findData(desired);
  desired_->setCurrentIndex(at >= 0 ? at : 0);
  region_->clear();
  region_->addItem(tr("whole part"), -1);
  for (std::size_t r = 0; r < p.regions.size(); ++r)
    region_->addItem(QString::fromStdString(p.regions[r].name), static_cast<int>(r));
  region_->setCurrentIndex(region >= 0 && region < region_->count() ? region : 0);
  path_->clear();
  for (const planning::ToolPath& tp : p.paths) path_->addItem(QString::fromStdString(tp.name));
  path_->setCurrentIndex(path >= 0 && path < path_->count() ? path : 0);
  compute_->setEnabled(p.part.has_value() && desired_->count() > 0);
  alongPath_->setEnabled(path_->count() > 0);
}

bool ErrorMapPanel::setDesiredSurface(int stateIndex) {
  const int at = desired_->findData(stateIndex);
  if (at < 0) return false;
  desired_->setCurrentIndex(at);
  return true;
}

void ErrorMapPanel::setRegion(int index) {
  const int at = region_->findData(index);
  region_->setCurrentIndex(at >= 0 ? at : 0);
}

planning::ToleranceBand ErrorMapPanel::toleranceBand() const {
  return {lower_->value(), upper_->value()};
}

void ErrorMapPanel::setToleranceBand(const planning::ToleranceBand& band) {
  planning::validateToleranceBand(band);
  {
    const QSignalBlocker blockLower(lower_), blockUpper(upper_);
    lower_->setValue(band.lowerMm);
    upper_->setValue(band.upperMm);
  }
  onBandEdited();
}

void ErrorMapPanel::onBandEdited() {
  PartView& view = workbench().partView;
  if (deviationField() != nullptr && view.fieldDisplay().field == kDeviationField)
    runUserAction(workbench().reportError, tr("Tolerance band"),
                  [&] { view.setToleranceBand(toleranceBand()); });
  updateStatistics();
}

const planning::ScalarField* ErrorMapPanel::deviationField() const {
  for (const planning::ScalarField& f : workbench().document.project().fields)
    if (f.name == kDeviationField) return &f;
  return nullptr;
}

bool ErrorMapPanel::computeErrorMap() {
  const planning::Project& p = workbench().document.project();
  bool started = false;
  runUserAction(workbench().reportError, tr("Compute error map"), [&] {
    if (!p.part) throw InvalidInput("there is no part to inspect");
    const int desired = desired_->currentData().isValid() ? desired_->currentData().toInt() : -2;
    if (desired == -1 && !p.designMesh) throw InvalidInput("the project has no design mesh");
    if (desired < -1 || desired >= static_cast<int>(p.states.size()))
      throw InvalidInput("choose the desired surface: a simulation state or the design mesh");
    auto part = std::make_shared<const ddf::DisplacementField>(*p.part);
    std::optional<std::vector<float>> state;
    if (desired >= 0) state = p.states[static_cast<std::size_t>(desired)].heights;
    std::optional<ddf::TriangleMesh> design;
    if (desired == -1) design = *p.designMesh;
    Workbench* wb = &workbench();
    ErrorMapPanel* self = this;
    started = wb->jobs.start(tr("Error map"), [=](const ProgressCallback& progress) {
      planning::ScalarField field =
          planning::deviationMap(*part, desiredHeights(*part, state, design, progress));
      field.name = kDeviationField;
      planning::markComputedFrom(field, *part);
      return std::function<void()>([wb, self, field = std::move(field)]() mutable {
        wb->document.push(std::make_unique<AddFieldCommand>(wb->document, std::move(field)));
        wb->partView.showField(kDeviationField);
        wb->partView.setToleranceBand(self->toleranceBand());
        self->updateStatistics();
        wb->plots.showPlot(kHistogramTab);
      });
    });
    if (!started) throw InvalidInput("another job is running; wait for it or cancel it first");
  });
  return started;
}

}  // namespace ddfcam::gui
