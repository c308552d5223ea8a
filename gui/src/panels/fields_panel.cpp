// SPDX-License-Identifier: MIT
// ddfcam gui: FieldsPanel.
#include <ddfcam/gui/panels/fields_panel.h>

#include <ddfcam/ddf/raster_mesh.h>
#include <ddfcam/ddf/surface_sampling.h>
#include <ddfcam/error.h>
#include <ddfcam/gui/document.h>
#include <ddfcam/gui/document_command.h>
#include <ddfcam/gui/histogram_range.h>
#include <ddfcam/gui/job_runner.h>
#include <ddfcam/gui/part_view.h>
#include <ddfcam/gui/plot_dock.h>
#include <ddfcam/planning/analysis/curvature.h>
#include <ddfcam/planning/analysis/segmentation.h>
#include <ddfcam/planning/model/builtin_fields.h>
#include <ddfcam/planning/model/field_freshness.h>
#include <ddfcam/planning/model/field_statistics.h>

#include <QAction>
#include <QCheckBox>
#include <QColor>
#include <QComboBox>
#include <QDoubleSpinBox>
#include <QFormLayout>
#include <QHBoxLayout>
#include <QListWidget>
#include <QListWidgetItem>
#include <QMenu>
#include <QPushButton>
#include <QToolButton>
#include <QVBoxLayout>

#include <algorithm>
#include <map>
#include <memory>
#include <optional>

namespace ddfcam::gui {

namespace {

/// What a field job needs, copied on the UI thread: jobs never read the live document.
struct FieldInputs {
  ddf::DisplacementField part;
  std::vector<float> reference;
  std::optional<ddf::TriangleMesh> design;
  planning::CurvatureParams curvature;  ///< planning::partCurvatureParams of the project
};

double supportDiagonalMm(const ddf::DisplacementField& part) {
  const auto box = ddf::extractSupportMesh(part).bounds();
  return std::max((box[1] - box[0]).norm(), 1e-3);
}

planning::CurvatureField curvatureOf(const FieldInputs& in, const ProgressCallback& progress) {
  planning::CurvatureParams params = in.curvature;
  params.progress = progress;
  return planning::computeCurvature(in.part, params);
}

planning::ScalarField curvature(planning::CurvatureQuantity quantity, const FieldInputs& in,
                                const ProgressCallback& progress) {
  return planning::curvatureScalarField(curvatureOf(in, progress), quantity);
}

planning::ScalarField computeField(FieldKind kind, const FieldInputs& in,
                                   const ProgressCallback& progress) {
  using Q = planning::CurvatureQuantity;
  switch (kind) {
    case FieldKind::Height:
      return planning::heightField(in.part);
    case FieldKind::HeightMm:
      return planning::heightMmField(in.part);
    case FieldKind::MaterialRemoved:
      return planning::materialRemovedField(in.part, in.reference);
    case FieldKind::Deviation:
      return planning::deviationField(in.part, *in.design, progress);
    case FieldKind::KMax:
      return curvature(Q::KMax, in, progress);
    case FieldKind::KMin:
      return curvature(Q::KMin, in, progress);
    case FieldKind::MeanCurvature:
      return curvature(Q::Mean, in, progress);
    case FieldKind::GaussianCurvature:
      return curvature(Q::Gaussian, in, progress);
    case FieldKind::CurvatureType:
      return planning::curvatureTypeField(curvatureOf(in, progress));
    case FieldKind::MaxToolRadius:
      // Capped at the part's size: any larger tool fits, and the colour range stays readable.
      return planning::maxToolRadiusField(curvatureOf(in, progress), supportDiagonalMm(in.part));
  }
  throw InvalidInput("unknown field kind");
}

// The built-in kind that computed a field of this name (the names the planning functions give).
std::optional<FieldKind> kindOfField(const std::string& name) {
  static const std::map<std::string, FieldKind> kinds = {
      {"height (h)", FieldKind::Height},
      {"height above support", FieldKind::HeightMm},
      {"material removed", FieldKind::MaterialRemoved},
      {"deviation from mesh", FieldKind::Deviation},
      {"k_max", FieldKind::KMax},
      {"k_min", FieldKind::KMin},
      {"mean curvature", FieldKind::MeanCurvature},
      {"Gaussian curvature", FieldKind::GaussianCurvature},
      {"curvature type", FieldKind::CurvatureType},
      {"max tool radius", FieldKind::MaxToolRadius}};
  const auto it = kinds.find(name);
  if (it == kinds.end()) return std::nullopt;
  return it->second;
}

QString kindTitle(FieldKind kind) {
  switch (kind) {
    case FieldKind::Height:
      return QObject::tr("Height h (vector lengths)");
    case FieldKind::HeightMm:
      return QObject::tr("Height above support (mm)");
    case FieldKind::MaterialRemoved:
      return QObject::tr("Material removed since stock (mm)");
    case FieldKind::Deviation:
      return QObject::tr("Deviation from design mesh (mm)");
    case FieldKind::KMax:
      return QObject::tr("Principal curvature k_max (1/mm)");
    case FieldKind::KMin:
      return QObject::tr("Principal curvature k_min (1/mm)");
    case FieldKind::MeanCurvature:
      return QObject::tr("Mean curvature (1/mm)");
    case FieldKind::GaussianCurvature:
      return QObject::tr("Gaussian curvature (1/mm^2)");
    case FieldKind::CurvatureType:
      return QObject::tr("Curvature type (flat, convex, concave, saddle)");
    case FieldKind::MaxToolRadius:
      return QObject::tr("Largest tool radius without gouging (mm)");
  }
  return {};
}

}  // namespace

FieldsPanel::FieldsPanel(Workbench& workbench, QWidget* parent) : Panel(workbench, parent) {
  for (FieldKind kind :
       {FieldKind::Height, FieldKind::HeightMm, FieldKind::MaterialRemoved, FieldKind::Deviation,
        FieldKind::KMax, FieldKind::KMin, FieldKind::MeanCurvature, FieldKind::GaussianCurvature,
        FieldKind::CurvatureType, FieldKind::MaxToolRadius}) {
    auto* action = new QAction(tr("Compute %1").arg(kindTitle(kind)), this);
    action->setObjectName(QString("actionComputeField%1").arg(static_cast<int>(kind)));
    connect(action, &QAction::triggered, this, [this, kind] { compute(kind); });
    actions_ << action;
  }
  buildControls();
  connect(&workbench.document, &Document::changed, this, [this](Changes what) {
    if (what & (Change::Fields | Change::Part | Change::Heights)) refreshList();
  });
  rangeMarkers_ = new HistogramRangeMarkers(this);
  connect(rangeMarkers_, &HistogramRangeMarkers::rangeEdited, this, [this](double lo, double hi) {
    runUserAction(this->workbench().reportError, tr("Set colour range"),
                  [&] { this->workbench().partView.setRange(lo, hi); });
  });
  connect(&workbench.partView, &PartView::fieldDisplayChanged, this, [this] {
    refreshList();
    refreshDisplayControls();
    updateHistogram();
  });
  refreshList();
  refreshDisplayControls();
}

void FieldsPanel::buildControls() {
  auto* layout = new QVBoxLayout(this);
  layout->addWidget(buildFieldList(), 1);
  layout->addLayout(buildListButtons());
  layout->addLayout(buildColourControls());
}

QListWidget* FieldsPanel::buildFieldList() {
  list_ = new QListWidget(this);
  list_->setObjectName("fieldList");
  connect(list_, &QListWidget::currentRowChanged, this, [this] { onSelectionChanged(); });
  return list_;
}

QHBoxLayout* FieldsPanel::buildListButtons() {
  auto* computeButton = new QToolButton(this);
  computeButton->setObjectName("computeFieldButton");
  computeButton->setText(tr("Compute"));
  computeButton->setPopupMode(QToolButton::InstantPopup);
  auto* menu = new QMenu(computeButton);
  menu->addActions(actions_);
  computeButton->setMenu(menu);
  recompute_ = new QPushButton(tr("Recompute"), this);
  recompute_->setObjectName("recomputeFieldButton");
  recompute_->setToolTip(tr("Compute the selected field again from the current heights"));
  connect(recompute_, &QPushButton::clicked, this, [this] { recomputeSelected(); });
  remove_ = new QPushButton(tr("Remove"), this);
  remove_->setObjectName("removeFieldButton");
  connect(remove_, &QPushButton::clicked, this, [this] {
    const int index = list_->currentRow() - 1;
    runUserAction(workbench().reportError, tr("Remove field"), [&] {
      workbench().document.push(std::make_unique<RemoveFieldCommand>(workbench().document, index));
    });
  });
  auto* buttons = new QHBoxLayout;
  buttons->addWidget(computeButton);
  buttons->addWidget(recompute_);
  buttons->addWidget(remove_);
  buttons->addStretch(1);
  return buttons;
}

QFormLayout* FieldsPanel::buildColourControls() {
  colourMap_ = new QComboBox(this);
  colourMap_->setObjectName("colourMapCombo");
  for (ColourMap map : allColourMaps())
    colourMap_->addItem(QString::fromStdString(colourMapName(map)), static_cast<int>(map));
  connect(colourMap_, &QComboBox::currentIndexChanged, this, [this] {
    if (!updating_)
      workbench().partView.setColourMap(static_cast<ColourMap>(colourMap_->currentData().toInt()));
  });
  autoRange_ = new QCheckBox(tr("Automatic range"), this);
  autoRange_->setObjectName("autoRangeCheck");
  connect(autoRange_, &QCheckBox::toggled, this, [this](bool on) {
    if (updating_) return;
    if (on)
      workbench().partView.setAutoRange();
    else
      applyRangeFromControls();
  });
  min_ = new QDoubleSpinBox(this);
  max_ = new QDoubleSpinBox(this);
  min_->setObjectName("rangeMin");
  max_->setObjectName("rangeMax");
  for (QDoubleSpinBox* box : {min_, max_}) {
    box->setRange(-1e9, 1e9);
    box->setDecimals(5);
    box->setKeyboardTracking(false);
    connect(box, &QDoubleSpinBox::valueChanged, this, [this] {
      if (!updating_) applyRangeFromControls();
    });
  }
  auto* form = new QFormLayout;
  form->addRow(tr("Colour map"), colourMap_);
  form->addRow(autoRange_);
  form->addRow(tr("Minimum"), min_);
  form->addRow(tr("Maximum"), max_);
  return form;
}

bool FieldsPanel::compute(FieldKind kind) {
  const planning::Project& p = workbench().document.project();
  const QString title = tr("Compute %1").arg(kindTitle(kind));
  bool started = false;
  runUserAction(workbench().reportError, title, [&] {
    if (!p.part) throw InvalidInput("there is no part to compute a field on");
    if (kind == FieldKind::MaterialRemoved && p.states.empty())
      throw InvalidInput("material removed needs a stock state; the project has no states");
    if (kind == FieldKind::Deviation && !p.designMesh)
      throw InvalidInput("the project has no design mesh to compare with (open a mesh file)");
    auto in = std::make_shared<FieldInputs>(
        FieldInputs{*p.part, p.states.empty() ? std::vector<float>{} : p.states.front().heights,
                    p.designMesh, planning::partCurvatureParams(p)});
    Workbench* wb = &workbench();
    started = wb->jobs.start(title, [in, kind, wb](const ProgressCallback& progress) {
      auto field = std::make_shared<planning::ScalarField>(computeField(kind, *in, progress));
      planning::markComputedFrom(*field, in->part);
      return std::function<void()>([field, wb] {
        const std::string name = field->name;
        wb->document.push(std::make_unique<AddFieldCommand>(wb->document, std::move(*field)));
        wb->partView.showField(name);
      });
    });
    if (!started) throw InvalidInput("another job is running; wait for it or cancel it first");
  });
  return started;
}

bool FieldsPanel::recomputeSelected() {
  const auto& fields = workbench().document.project().fields;
  const int row = list_->currentRow();
  bool started = false;
  runUserAction(workbench().reportError, tr("Recompute field"), [&] {
    if (row < 1 || row > static_cast<int>(fields.size())) throw InvalidInput("select a field");
    const planning::ScalarField& field = fields[static_cast<std::size_t>(row - 1)];
    const std::optional<FieldKind> kind = kindOfField(field.name);
    if (!kind)
      throw InvalidInput("'" + field.name +
                         "' is not a field of the Compute menu; compute it again where it was "
                         "made (e.g. the Error map panel)");
    started = compute(*kind);
  });
  return started;
}

void FieldsPanel::refreshList() {
  updating_ = true;
  const planning::Project& project = workbench().document.project();
  const auto& fields = project.fields;
  const std::uint64_t digest =
      project.part ? planning::heightsDigest(project.part->allHeights()) : 0;
  list_->clear();
  list_->addItem(tr("(none: plain surface)"));
  int current = 0;
  for (std::size_t i = 0; i < fields.size(); ++i) {
    const auto& f = fields[i];
    auto* item = new QListWidgetItem(
        QString::fromStdString(f.unit.empty() ? f.name : f.name + " [" + f.unit + "]"), list_);
    if (project.part && planning::isStale(f, digest)) {
      item->setText(item->text() + tr("  (stale: heights changed)"));
      item->setForeground(QColor(176, 96, 0));
      item->setToolTip(tr("The part's heights changed after this field was computed; its "
                          "values describe the earlier surface. Recompute it."));
    }
    if (f.name == workbench().partView.fieldDisplay().field) current = static_cast<int>(i) + 1;
  }
  list_->setCurrentRow(current);
  remove_->setEnabled(current > 0);
  recompute_->setEnabled(current > 0 &&
                         kindOfField(fields[static_cast<std::size_t>(current - 1)].name));
  updating_ = false;
}

void FieldsPanel::onSelectionChanged() {
  if (updating_) return;
  const int row = list_->currentRow();
  const auto& fields = workbench().document.project().fields;
  remove_->setEnabled(row > 0);
  recompute_->setEnabled(row > 0 && row - 1 < static_cast<int>(fields.size()) &&
                         kindOfField(fields[static_cast<std::size_t>(row - 1)].name));
  runUserAction(workbench().reportError, tr("Show field"), [&] {
    workbench().partView.showField(row > 0 && row - 1 < static_cast<int>(fields.size())
                                       ? fields[static_cast<std::size_t>(row - 1)].name
                                       : std::string());
  });
}

void FieldsPanel::refreshDisplayControls() {
  updating_ = true;
  const FieldDisplay& d = workbench().partView.fieldDisplay();
  const planning::ScalarField* field = workbench().partView.shownField();
  colourMap_->setCurrentIndex(colourMap_->findData(static_cast<int>(d.map)));
  autoRange_->setChecked(d.autoRange);
  const QString suffix =
      field && !field->unit.empty() ? " " + QString::fromStdString(field->unit) : "";
  for (QDoubleSpinBox* box : {min_, max_}) {
    box->setSuffix(suffix);
    box->setEnabled(field != nullptr);
  }
  min_->setValue(d.lo);
  max_->setValue(d.hi);
  colourMap_->setEnabled(field != nullptr);
  autoRange_->setEnabled(field != nullptr);
  updating_ = false;
}

void FieldsPanel::applyRangeFromControls() {
  runUserAction(workbench().reportError, tr("Set colour range"),
                [&] { workbench().partView.setRange(min_->value(), max_->value()); });
}

void FieldsPanel::updateHistogram() {
  const planning::ScalarField* field = workbench().partView.shownField();
  const auto& project = workbench().document.project();
  if (!field || !project.part) return;
  const FieldDisplay& d = workbench().partView.fieldDisplay();
  // Shared raster points once each, over all values and the colour range: the range's ends are
  // lines on it that the engineer drags, and the bars beyond them are what the scalar bar's
  // out-of-range colours show.
  const std::vector<float> perPoint = ddf::valuesPerPoint(*project.part, field->values);
  const std::optional<planning::FieldRange> all = planning::fieldRange(perPoint);
  double lo = all ? std::min(all->min, d.lo) : d.lo, hi = all ? std::max(all->max, d.hi) : d.hi;
  if (!(hi > lo)) hi = lo + 1.0;
  const planning::Histogram h = planning::histogram(perPoint, kHistogramBins, lo, hi);
  const std::string label =
      field->unit.empty() ? field->name : field->name + " [" + field->unit + "]";
  workbench().plots.showHistogram(h, QString::fromStdString(label));
  rangeMarkers_->show(workbench().plots.findPlot(PlotDock::kHistogramTab), d.lo, d.hi);
}

}  // namespace ddfcam::gui
