// SPDX-License-Identifier: MIT
// ddfcam gui: MouldToolsPanel: widgets, the history table and the convergence plot.
#include <ddfcam/gui/panels/mould_tools_panel.h>

#include <ddfcam/gui/adapters/plot_series.h>
#include <ddfcam/gui/document.h>
#include <ddfcam/gui/mould_view.h>
#include <ddfcam/gui/plot_dock.h>
#include <ddfcam/planning/model/project.h>

#include <qcustomplot.h>
#include <QCheckBox>
#include <QComboBox>
#include <QDoubleSpinBox>
#include <QFileDialog>
#include <QFormLayout>
#include <QGroupBox>
#include <QHBoxLayout>
#include <QHeaderView>
#include <QLabel>
#include <QPushButton>
#include <QTableWidget>
#include <QVBoxLayout>

#include <algorithm>
#include <cmath>

#include "unit_combo.h"

namespace ddfcam::gui {
namespace {

// Both series share the axes; colour, markers and a legend tell them apart. The deviation of a
// converging loop falls geometrically (alpha^j), so a logarithmic axis shows the rate as a
// straight line; iterations are whole numbers.
void styleConvergencePlot(QCustomPlot* plot, const std::vector<double>& maxMm,
                          const std::vector<double>& rmsMm) {
  for (int g = 0; g < plot->graphCount(); ++g) {
    QCPGraph* graph = plot->graph(g);
    const bool rms = graph->name() == QLatin1String(MouldToolsPanel::kRmsSeries);
    if (!rms && graph->name() != QLatin1String(MouldToolsPanel::kMaxSeries)) continue;
    graph->setPen(QPen(rms ? QColor(200, 40, 40) : QColor(30, 60, 200), 1.5));
    graph->setScatterStyle(
        QCPScatterStyle(rms ? QCPScatterStyle::ssSquare : QCPScatterStyle::ssCircle, 6));
  }
  auto ticker = QSharedPointer<QCPAxisTickerFixed>::create();
  ticker->setTickStep(1.0);
  ticker->setScaleStrategy(QCPAxisTickerFixed::ssMultiples);
  plot->xAxis->setTicker(ticker);
  const auto positive = [](const std::vector<double>& v) {
    return std::all_of(v.begin(), v.end(), [](double x) { return x > 0.0; });
  };
  const bool logScale = !maxMm.empty() && positive(maxMm) && positive(rmsMm);
  plot->yAxis->setScaleType(logScale ? QCPAxis::stLogarithmic : QCPAxis::stLinear);
  if (logScale) {
    plot->yAxis->setTicker(QSharedPointer<QCPAxisTickerLog>::create());
    const double lo = *std::min_element(rmsMm.begin(), rmsMm.end());
    const double hi = *std::max_element(maxMm.begin(), maxMm.end());
    plot->yAxis->setRange(lo / 1.5, hi * 1.5);
  } else {
    plot->yAxis->setTicker(QSharedPointer<QCPAxisTicker>::create());
  }
  if (!maxMm.empty()) plot->xAxis->setRange(-0.25, static_cast<double>(maxMm.size()) - 0.75);
  plot->legend->setVisible(true);
  plot->replot();
}

QDoubleSpinBox* alphaSpin(QWidget* parent, const QString& name, double value) {
  auto* spin = new QDoubleSpinBox(parent);
  spin->setObjectName(name);
  spin->setDecimals(3);
  spin->setSingleStep(0.05);
  spin->setRange(0.0, 0.99);
  spin->setValue(value);
  return spin;
}

QPushButton* button(QWidget* parent, const QString& text, const char* name) {
  auto* b = new QPushButton(text, parent);
  b->setObjectName(name);
  return b;
}

QString millimetres(double value) {
  return std::isnan(value) ? QStringLiteral("-") : QString::number(value, 'g', 4);
}

}  // namespace

MouldToolsPanel::MouldToolsPanel(Workbench& workbench, QWidget* parent) : Panel(workbench, parent) {
  auto* layout = new QVBoxLayout(this);
  layout->addWidget(buildBlending());
  layout->addWidget(buildWarps());
  layout->addWidget(buildCompensation());
  layout->addStretch();
  connect(&workbench.document, &Document::changed, this, [this](Changes what) {
    if (what & (Change::Mould | Change::Part)) refresh();
  });
  if (workbench.mouldView != nullptr)
    connect(workbench.mouldView, &MouldView::pointPicked, this,
            [this](int, Eigen::Vector3d point) { applyPick(point); });
  refresh();
}

QGroupBox* MouldToolsPanel::buildCompensation() {
  auto* group = new QGroupBox(tr("Compensation"), this);
  group->setObjectName("compensationGroup");
  auto* box = new QVBoxLayout(group);
  box->addLayout(buildCompensationForm(group));
  box->addWidget(modelLabel_);
  buildCompensationButtons(group, box);
  buildHistoryTable(group);
  box->addWidget(table_);
  connectCompensation();
  return group;
}

QFormLayout* MouldToolsPanel::buildCompensationForm(QGroupBox* group) {
  auto* form = new QFormLayout;
  source_ = new QComboBox(group);
  source_->setObjectName("responseSourceCombo");
  source_->addItem(tr("Imported formed surface"),
                   static_cast<int>(ResponseSource::ImportedSurface));
  source_->addItem(tr("Linear model"), static_cast<int>(ResponseSource::LinearModel));
  lambda_ = new QDoubleSpinBox(group);
  lambda_->setObjectName("lambdaSpin");
  lambda_->setDecimals(3);
  lambda_->setRange(0.001, 10.0);
  lambda_->setSingleStep(0.1);
  lambda_->setValue(1.0);
  alpha_ = alphaSpin(group, "alphaSpin", planning::LinearSpringbackModel{}.alpha);
  perAxis_ = new QCheckBox(tr("per axis (x, y, z)"), group);
  perAxis_->setObjectName("perAxisCheck");
  auto* axes = new QHBoxLayout;
  for (const char* axis : {"x", "y", "z"}) {
    axisAlpha_.push_back(alphaSpin(group, QStringLiteral("alpha%1Spin").arg(axis), 0.3));
    axes->addWidget(axisAlpha_.back());
  }
  modelLabel_ = new QLabel(tr("model: not calibrated"), group);
  modelLabel_->setObjectName("modelLabel");
  form->addRow(tr("Response"), source_);
  form->addRow(tr("lambda"), lambda_);
  form->addRow(tr("alpha"), alpha_);
  form->addRow(perAxis_, axes);
  return form;
}

void MouldToolsPanel::buildCompensationButtons(QGroupBox* group, QBoxLayout* box) {
  start_ = button(group, tr("Start from target"), "startCompensationButton");
  calibrate_ = button(group, tr("Calibrate model"), "calibrateModelButton");
  import_ = button(group, tr("Import formed surface..."), "importFormedButton");
  importUnit_ = makeUnitCombo(group, "importFormedUnitCombo");
  evaluate_ = button(group, tr("Evaluate last mould"), "evaluateMouldButton");
  step_ = button(group, tr("Step"), "compensationStepButton");
  export_ = button(group, tr("Export mould..."), "exportMouldButton");
  auto* row1 = new QHBoxLayout;
  row1->addWidget(start_);
  row1->addWidget(calibrate_);
  row1->addWidget(import_);
  row1->addWidget(importUnit_);
  auto* row2 = new QHBoxLayout;
  row2->addWidget(evaluate_);
  row2->addWidget(step_);
  row2->addWidget(export_);
  box->addLayout(row1);
  box->addLayout(row2);
}

void MouldToolsPanel::buildHistoryTable(QGroupBox* group) {
  table_ = new QTableWidget(0, 4, group);
  table_->setObjectName("compensationHistoryTable");
  table_->setHorizontalHeaderLabels({tr("iteration"), tr("source"), tr("max mm"), tr("RMS mm")});
  table_->horizontalHeader()->setStretchLastSection(true);
  table_->setSelectionBehavior(QAbstractItemView::SelectRows);
  table_->setSelectionMode(QAbstractItemView::SingleSelection);
  table_->setEditTriggers(QAbstractItemView::NoEditTriggers);
  table_->setMinimumHeight(140);
}

void MouldToolsPanel::connectCompensation() {
  connect(table_, &QTableWidget::cellClicked, this, [this](int row, int) { showMould(row); });
  connect(start_, &QPushButton::clicked, this, [this] { startCompensation(); });
  connect(calibrate_, &QPushButton::clicked, this, [this] { calibrateLinearModel(); });
  connect(evaluate_, &QPushButton::clicked, this, [this] { evaluateLastMould(); });
  connect(step_, &QPushButton::clicked, this, [this] { step(); });
  connect(import_, &QPushButton::clicked, this, [this] {
    const QString path = askOpenPath(tr("Import formed surface"), tr("Meshes (*.stl *.obj *.ply)"));
    if (!path.isEmpty()) importFormedSurface(path);
  });
  connect(export_, &QPushButton::clicked, this, [this] {
    const int row = table_->currentRow() >= 0 ? table_->currentRow() : table_->rowCount() - 1;
    const QString path =
        askSavePath(tr("Export mould"), tr("STL (*.stl);;OBJ (*.obj);;PLY (*.ply)"));
    if (!path.isEmpty()) exportMould(row, path);
  });
}

void MouldToolsPanel::setFormedUnit(LengthUnit unit) {
  selectUnit(importUnit_, unit);
}

void MouldToolsPanel::setResponseSource(ResponseSource source) {
  source_->setCurrentIndex(source_->findData(static_cast<int>(source)));
}

ResponseSource MouldToolsPanel::responseSource() const {
  return static_cast<ResponseSource>(source_->currentData().toInt());
}

void MouldToolsPanel::setLambda(double lambda) {
  lambda_->setValue(lambda);
}
double MouldToolsPanel::lambda() const {
  return lambda_->value();
}

void MouldToolsPanel::setLinearModel(planning::LinearSpringbackModel model) {
  alpha_->setValue(model.alpha);
  perAxis_->setChecked(model.axisAlpha.has_value());
  if (model.axisAlpha)
    for (int a = 0; a < 3; ++a) axisAlpha_[a]->setValue((*model.axisAlpha)[a]);
  modelLabel_->setText(tr("model: relaxed shape of %1 heights").arg(model.relaxedHeights.size()));
  model_ = std::move(model);
}

planning::LinearSpringbackModel MouldToolsPanel::modelWithPanelAlphas() const {
  planning::LinearSpringbackModel model = *model_;
  model.alpha = alpha_->value();
  model.axisAlpha.reset();
  if (perAxis_->isChecked())
    model.axisAlpha =
        Eigen::Vector3d(axisAlpha_[0]->value(), axisAlpha_[1]->value(), axisAlpha_[2]->value());
  return model;
}

const planning::CompensationHistory* MouldToolsPanel::history() const {
  const planning::Project& p = workbench().document.project();
  if (!p.mould || !p.mould->compensation) return nullptr;
  return &*p.mould->compensation;
}

int MouldToolsPanel::historyRows() const {
  return table_->rowCount();
}

void MouldToolsPanel::refresh() {
  const planning::Project& p = workbench().document.project();
  const planning::CompensationHistory* h = history();
  start_->setEnabled(p.mould.has_value());
  calibrate_->setEnabled(h != nullptr && p.mould->formed.has_value());
  for (QPushButton* b : {import_, evaluate_, step_, export_}) b->setEnabled(h != nullptr);
  refreshHistory(h);
  if (h != nullptr)
    plotConvergence(*h);
  else if (workbench().plots.findPlot(kConvergenceTab) != nullptr)
    plotConvergence(planning::CompensationHistory{});
  // A new, undone or redone iteration shows the newest mould; other study edits leave the
  // mould view to the panel that made them.
  const int rows = h ? static_cast<int>(h->iterations.size()) : 0;
  if (rows != shownHistorySize_ && rows > 0) showMould(rows - 1);
  shownHistorySize_ = rows;
}

void MouldToolsPanel::refreshHistory(const planning::CompensationHistory* history) {
  const int keep = table_->currentRow();
  const int rows = history ? static_cast<int>(history->iterations.size()) : 0;
  table_->setRowCount(rows);
  for (int r = 0; r < rows; ++r) {
    const planning::CompensationIteration& it = history->iterations[static_cast<std::size_t>(r)];
    const QStringList cells = {QString::number(r), QString::fromStdString(it.formedSource),
                               millimetres(it.maxDeviationMm), millimetres(it.rmsDeviationMm)};
    for (int c = 0; c < cells.size(); ++c) table_->setItem(r, c, new QTableWidgetItem(cells[c]));
  }
  table_->setCurrentCell(keep >= 0 && keep < rows ? keep : rows - 1, 0);
}

// Only iterations whose response is known have a point: the plot shows measured quality.
void MouldToolsPanel::plotConvergence(const planning::CompensationHistory& history) {
  std::vector<double> x, maxMm, rmsMm;
  for (std::size_t j = 0; j < history.iterations.size(); ++j) {
    const planning::CompensationIteration& it = history.iterations[j];
    if (std::isnan(it.maxDeviationMm)) continue;
    x.push_back(static_cast<double>(j));
    maxMm.push_back(it.maxDeviationMm);
    rmsMm.push_back(it.rmsDeviationMm);
  }
  QCustomPlot* plot = workbench().plots.plot(kConvergenceTab);
  setLineSeries(plot, kMaxSeries, x, maxMm, tr("iteration"), tr("deviation (mm)"));
  setLineSeries(plot, kRmsSeries, x, rmsMm, tr("iteration"), tr("deviation (mm)"));
  styleConvergencePlot(plot, maxMm, rmsMm);
}

QString MouldToolsPanel::askSavePath(const QString& title, const QString& filter) {
  return QFileDialog::getSaveFileName(this, title, QString(), filter);
}

QString MouldToolsPanel::askOpenPath(const QString& title, const QString& filter) {
  return QFileDialog::getOpenFileName(this, title, QString(), filter);
}

}  // namespace ddfcam::gui
