// SPDX-License-Identifier: MIT
// ddfcam gui: StreamlinesPanel.
#include <ddfcam/gui/panels/streamlines_panel.h>

#include <ddfcam/error.h>
#include <ddfcam/gui/document.h>
#include <ddfcam/gui/document_command.h>
#include <ddfcam/gui/job_runner.h>
#include <ddfcam/gui/part_view.h>
#include <ddfcam/planning/curvature.h>
#include <ddfcam/planning/flow_field.h>
#include <ddfcam/planning/streamline.h>
#include <ddfcam/planning/streamline_path.h>

#include <QCheckBox>
#include <QComboBox>
#include <QDoubleSpinBox>
#include <QFormLayout>
#include <QLabel>
#include <QPointer>
#include <QPushButton>
#include <QToolButton>
#include <QVBoxLayout>

namespace ddfcam::gui {

/// The line fields the paths follow, for one state of the part's heights.
struct StreamlinesPanel::Fields {
  bool alongMax = true;
  bool smoothed = false;
  planning::LineField field;       ///< the tool flow field
  planning::LineField transverse;  ///< the other principal direction, for seeding families
};

namespace {

std::shared_ptr<StreamlinesPanel::Fields> computeFields(const ddf::DisplacementField& part,
                                                        bool alongMax, bool smoothed,
                                                        const ProgressCallback& progress) {
  planning::CurvatureParams curvatureParams;
  curvatureParams.progress = [&](double f) { return !progress || progress(0.2 * f); };
  const planning::CurvatureField curvature = planning::computeCurvature(part, curvatureParams);
  auto fields = std::make_shared<StreamlinesPanel::Fields>();
  fields->alongMax = alongMax;
  fields->smoothed = smoothed;
  planning::FlowFieldParams params;
  params.smoothing = smoothed;
  params.progress = [&](double f) { return !progress || progress(0.2 + 0.4 * f); };
  using Source = planning::FlowFieldSource;
  params.source = alongMax ? Source::MaxCurvatureDirection : Source::MinCurvatureDirection;
  fields->field = planning::flowField(part, curvature, params);
  params.progress = [&](double f) { return !progress || progress(0.6 + 0.4 * f); };
  params.source = alongMax ? Source::MinCurvatureDirection : Source::MaxCurvatureDirection;
  fields->transverse = planning::flowField(part, curvature, params);
  return fields;
}

}  // namespace

StreamlinesPanel::StreamlinesPanel(Workbench& workbench, QWidget* parent)
    : Panel(workbench, parent) {
  direction_ = new QComboBox(this);
  direction_->setObjectName("streamlineDirectionCombo");
  direction_->addItem(tr("along k_max (lines of max. curvature)"));
  direction_->addItem(tr("along k_min (lines of min. curvature)"));
  smooth_ = new QCheckBox(tr("Smooth the field (Ceres; slower)"), this);
  smooth_->setObjectName("smoothFieldCheck");
  seedByClick_ = new QToolButton(this);
  seedByClick_->setObjectName("seedByClickButton");
  seedByClick_->setText(tr("Seed by click"));
  seedByClick_->setCheckable(true);
  spacing_ = new QDoubleSpinBox(this);
  spacing_->setObjectName("streamlineSpacing");
  spacing_->setRange(0.05, 100.0);
  spacing_->setValue(2.0);
  spacing_->setSuffix(" mm");
  auto* family = new QPushButton(tr("Seed family at last pick"), this);
  family->setObjectName("seedFamilyButton");
  status_ = new QLabel(tr("Pick a point on the part, then seed."), this);
  status_->setWordWrap(true);
  auto* form = new QFormLayout;
  form->addRow(tr("Direction"), direction_);
  form->addRow(smooth_);
  form->addRow(seedByClick_);
  form->addRow(tr("Spacing w"), spacing_);
  form->addRow(family);
  auto* layout = new QVBoxLayout(this);
  layout->addLayout(form);
  layout->addWidget(status_);
  layout->addStretch(1);
  connect(family, &QPushButton::clicked, this, [this] { seedFamily(); });
  connect(&workbench.partView, &PartView::picked, this, &StreamlinesPanel::onPicked);
  connect(&workbench.document, &Document::changed, this, [this](Changes what) {
    if (what & (Change::Part | Change::Heights)) fields_.reset();
    if (what & Change::Part) lastPick_.reset();
  });
}

StreamlinesPanel::~StreamlinesPanel() = default;

void StreamlinesPanel::setSeedByClick(bool on) {
  seedByClick_->setChecked(on);
}

void StreamlinesPanel::onPicked(const PickResult& pick) {
  lastPick_ = pick.location;
  if (seedByClick_->isChecked()) seedAt(pick.location);
}

bool StreamlinesPanel::withFields(const std::function<void()>& then) {
  const bool alongMax = direction_->currentIndex() == 0, smoothed = smooth_->isChecked();
  if (fields_ && fields_->alongMax == alongMax && fields_->smoothed == smoothed) {
    then();
    return true;
  }
  const auto& part = workbench().document.project().part;
  if (!part) return false;
  auto copy = std::make_shared<ddf::DisplacementField>(*part);
  QPointer<StreamlinesPanel> self(this);
  return workbench().jobs.start(tr("Compute tool flow field"),
                                [copy, alongMax, smoothed, self, then](const auto& progress) {
                                  auto fields = computeFields(*copy, alongMax, smoothed, progress);
                                  return std::function<void()>([fields, self, then] {
                                    if (!self) return;
                                    self->fields_ = fields;
                                    then();
                                  });
                                });
}

bool StreamlinesPanel::seedAt(const ddf::SurfaceLocation& seed) {
  return withFields([this, seed] {
    const auto& part = *workbench().document.project().part;
    addPath({planning::traceStreamline(part, fields_->field, seed)}, tr("streamline"));
  });
}

bool StreamlinesPanel::seedFamily() {
  if (!lastPick_) {
    workbench().reportError(tr("Seed family"), tr("Pick a point on the part first."));
    return false;
  }
  const ddf::SurfaceLocation seed = *lastPick_;
  const double spacing = spacing_->value();
  return withFields([this, seed, spacing] {
    const auto& part = *workbench().document.project().part;
    addPath(planning::seedAlongTransverse(part, fields_->field, fields_->transverse, seed, spacing),
            tr("streamline family"));
  });
}

void StreamlinesPanel::addPath(std::vector<planning::Streamline> lines, const QString& name) {
  runUserAction(workbench().reportError, tr("Add %1").arg(name), [&] {
    Document& document = workbench().document;
    const planning::Project& p = document.project();
    const bool needTool = p.tools.empty();
    const planning::Tool tool = needTool ? planning::Tool{} : p.tools.front();
    planning::StreamlinePathParams params;
    params.name = QString("%1 %2").arg(name).arg(p.paths.size() + 1).toStdString();
    planning::ToolPath path = planning::toolPathFromStreamlines(*p.part, lines, tool, 0, params);
    double length = 0;
    for (const auto& line : lines) length += line.lengthMm;
    document.push(std::make_unique<AddPathCommand>(document, std::move(path),
                                                   needTool ? std::optional(tool) : std::nullopt));
    status_->setText(tr("%1: %2 lines, %3 mm")
                         .arg(QString::fromStdString(params.name))
                         .arg(lines.size())
                         .arg(length, 0, 'f', 1));
  });
}

}  // namespace ddfcam::gui
