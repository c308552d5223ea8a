// SPDX-License-Identifier: MIT
// ddfcam gui: SpacingRefinementPanel: inputs, the refinement job, apply.
#include <ddfcam/gui/panels/spacing_refinement_panel.h>

#include <ddfcam/gui/panels/streamlines_panel.h>

#include <ddfcam/error.h>
#include <ddfcam/gui/composite_command.h>
#include <ddfcam/gui/document.h>
#include <ddfcam/gui/job_runner.h>
#include <ddfcam/gui/part_scene.h>
#include <ddfcam/gui/part_view.h>
#include <ddfcam/planning/model/field_freshness.h>

#include <QComboBox>
#include <QDoubleSpinBox>
#include <QFormLayout>
#include <QLabel>
#include <QListWidget>
#include <QPushButton>
#include <QSignalBlocker>
#include <QSpinBox>
#include <QVBoxLayout>

namespace ddfcam::gui {
namespace {

using Source = planning::FlowFieldSource;

// Flow field and tracing stay in [0, 0.2] and [0.2, 1] of the job's progress.
ProgressCallback scaled(const ProgressCallback& progress, double from, double to) {
  return [progress, from, to](double f) { return !progress || progress(from + (to - from) * f); };
}

}  // namespace

SpacingRefinementPanel::SpacingRefinementPanel(Workbench& workbench, QWidget* parent)
    : Panel(workbench, parent) {
  buildForm();
  connect(&workbench.document, &Document::changed, this, [this](Changes what) {
    if (what & (Change::Part | Change::Regions | Change::Tools)) refreshChoices();
    if (what & (Change::Part | Change::Heights)) {
      result_.reset();
      showResult();
    }
  });
  refreshChoices();
  showResult();
}

SpacingRefinementPanel::~SpacingRefinementPanel() = default;

void SpacingRefinementPanel::buildForm() {
  auto* layout = new QVBoxLayout(this);
  auto* form = new QFormLayout;
  region_ = new QComboBox(this);
  region_->setObjectName("refineRegionCombo");
  tool_ = new QComboBox(this);
  tool_->setObjectName("refineToolCombo");
  source_ = new QComboBox(this);
  source_->setObjectName("refineSourceCombo");
  source_->addItem(tr("k_max direction"), static_cast<int>(Source::MaxCurvatureDirection));
  source_->addItem(tr("k_min direction"), static_cast<int>(Source::MinCurvatureDirection));
  source_->addItem(tr("fixed direction x"), static_cast<int>(Source::FixedDirection));
  tolerance_ = new QDoubleSpinBox(this);
  tolerance_->setObjectName("refineToleranceSpin");
  tolerance_->setDecimals(4);
  tolerance_->setRange(0.0001, 10.0);
  tolerance_->setSingleStep(0.005);
  tolerance_->setSuffix(QStringLiteral(" mm"));
  tolerance_->setValue(0.01);
  iterations_ = new QSpinBox(this);
  iterations_->setObjectName("refineIterationsSpin");
  iterations_->setRange(0, 200);
  iterations_->setValue(planning::SpacingRefinementParams{}.maxIterations);
  form->addRow(tr("Region"), region_);
  form->addRow(tr("Tool"), tool_);
  form->addRow(tr("Feed direction"), source_);
  form->addRow(tr("Scallop tolerance"), tolerance_);
  form->addRow(tr("Fix-up iterations"), iterations_);
  layout->addLayout(form);
  refine_ = new QPushButton(tr("Refine spacing"), this);
  refine_->setObjectName("refineSpacingButton");
  list_ = new QListWidget(this);
  list_->setObjectName("refinementIterationList");
  summary_ = new QLabel(this);
  summary_->setObjectName("refinementSummaryLabel");
  apply_ = new QPushButton(tr("Apply: add path and error map"), this);
  apply_->setObjectName("applyRefinementButton");
  for (QWidget* w : {static_cast<QWidget*>(refine_), static_cast<QWidget*>(list_),
                     static_cast<QWidget*>(summary_), static_cast<QWidget*>(apply_)})
    layout->addWidget(w);
  connect(refine_, &QPushButton::clicked, this, [this] { refine(); });
  connect(apply_, &QPushButton::clicked, this, [this] { apply(); });
  connect(list_, &QListWidget::currentRowChanged, this, [this](int row) { showIteration(row); });
}

void SpacingRefinementPanel::refreshChoices() {
  const planning::Project& p = workbench().document.project();
  const QSignalBlocker blockRegion(region_), blockTool(tool_);
  const int region = region_->currentIndex(), tool = tool_->currentIndex();
  region_->clear();
  region_->addItem(tr("whole part"), -1);
  for (std::size_t r = 0; r < p.regions.size(); ++r)
    region_->addItem(QString::fromStdString(p.regions[r].name), static_cast<int>(r));
  region_->setCurrentIndex(region >= 0 && region < region_->count() ? region : 0);
  tool_->clear();
  for (const planning::Tool& t : p.tools) tool_->addItem(QString::fromStdString(t.name));
  tool_->setCurrentIndex(tool >= 0 && tool < tool_->count() ? tool : 0);
  refine_->setEnabled(p.part.has_value() && !p.tools.empty());
}

void SpacingRefinementPanel::setRegion(int index) {
  const int at = region_->findData(index);
  region_->setCurrentIndex(at >= 0 ? at : 0);
}

void SpacingRefinementPanel::setTool(int index) {
  tool_->setCurrentIndex(index);
}

void SpacingRefinementPanel::setFieldSource(planning::FlowFieldSource source) {
  const int at = source_->findData(static_cast<int>(source));
  if (at >= 0) source_->setCurrentIndex(at);
}

void SpacingRefinementPanel::setTolerance(double toleranceMm) {
  tolerance_->setValue(toleranceMm);
}

void SpacingRefinementPanel::setMaxIterations(int iterations) {
  iterations_->setValue(iterations);
}

bool SpacingRefinementPanel::refine() {
  const planning::Project& p = workbench().document.project();
  bool started = false;
  runUserAction(workbench().reportError, tr("Refine spacing"), [&] {
    if (!p.part) throw InvalidInput("there is no part to plan on");
    const int toolIndex = tool_->currentIndex();
    if (toolIndex < 0 || toolIndex >= static_cast<int>(p.tools.size()))
      throw InvalidInput("choose a tool");
    const int region = region_->currentData().toInt();
    auto part = std::make_shared<const ddf::DisplacementField>(*p.part);
    const planning::CurvatureParams curvatureParams = planning::partCurvatureParams(p);
    FieldChoice choice;
    choice.plan.flowSource = static_cast<Source>(source_->currentData().toInt());
    choice.plan.smoothField = false;
    if (region >= 0) choice.faceMask = planning::regionFaceMask(*part, p.regions[region]);
    const planning::Tool tool = p.tools[static_cast<std::size_t>(toolIndex)];
    planning::SpacingRefinementParams params;
    params.toleranceMm = tolerance_->value();
    params.maxIterations = iterations_->value();
    params.toolIndex = toolIndex;
    SpacingRefinementPanel* self = this;
    started = workbench().jobs.start(tr("Refine spacing"), [=](const ProgressCallback& progress) {
      const auto fields = computeStreamlineFields(*part, choice, nullptr, curvatureParams,
                                                  scaled(progress, 0, 0.2));
      planning::SpacingRefinementParams run = params;
      run.progress = scaled(progress, 0.2, 1.0);
      auto result = std::make_shared<const planning::SpacingRefinementResult>(
          planning::refineSpacing(*part, fields->field, choice.faceMask, tool, run));
      const std::uint64_t digest = planning::heightsDigest(part->allHeights());
      return std::function<void()>([self, result, toolIndex, tol = params.toleranceMm, digest] {
        self->result_ = result;
        self->resultHeightsDigest_ = digest;
        self->resultTool_ = toolIndex;
        self->resultToleranceMm_ = tol;
        self->showResult();
      });
    });
    if (!started) throw InvalidInput("another job is running; wait for it or cancel it first");
  });
  return started;
}

bool SpacingRefinementPanel::apply() {
  return runUserAction(workbench().reportError, tr("Apply spacing refinement"), [&] {
    if (!result_) throw InvalidInput("refine the spacing first");
    Document& document = workbench().document;
    planning::ToolPath path = result_->toolPath;
    path.tool = resultTool_;
    planning::ScalarField error{kErrorField, "mm", true, result_->errorField, {}};
    error.heightsDigest = resultHeightsDigest_;
    std::vector<std::unique_ptr<DocumentCommand>> parts;
    parts.push_back(std::make_unique<AddPathCommand>(document, std::move(path)));
    parts.push_back(std::make_unique<AddFieldCommand>(document, std::move(error)));
    document.push(
        std::make_unique<CompositeCommand>(document, tr("Refined path spacing"), std::move(parts)));
    workbench().partView.showField(kErrorField);
    workbench().partView.setToleranceBand(
        planning::ToleranceBand{-resultToleranceMm_, resultToleranceMm_});
  });
}

}  // namespace ddfcam::gui
