// SPDX-License-Identifier: MIT
// ddfcam gui: ErrorMapPanel: statistics, histogram, deviation along a path, scallop table.
#include <ddfcam/error.h>
#include <ddfcam/gui/adapters/error_plots.h>
#include <ddfcam/gui/document.h>
#include <ddfcam/gui/job_runner.h>
#include <ddfcam/gui/panels/error_map_panel.h>
#include <ddfcam/gui/part_view.h>
#include <ddfcam/gui/plot_dock.h>
#include <ddfcam/planning/model/field_freshness.h>

#include <QComboBox>
#include <QHeaderView>
#include <QLabel>
#include <QPushButton>
#include <QTableWidget>
#include <QVBoxLayout>

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <vector>

namespace ddfcam::gui {
namespace {

constexpr int kHistogramBins = 40;

std::vector<int> regionFaces(const planning::Project& p, int region) {
  if (region < 0 || region >= static_cast<int>(p.regions.size())) return {};
  return p.regions[static_cast<std::size_t>(region)].faces;
}

QString mm(double value) {
  return QString::number(value, 'f', 4) + QStringLiteral(" mm");
}

QString percent(double value) {
  return QString::number(value, 'f', 1) + QStringLiteral(" %");
}

std::vector<std::uint8_t> finiteMask(const planning::ScalarField& field) {
  std::vector<std::uint8_t> mask(field.values.size());
  for (std::size_t l = 0; l < mask.size(); ++l) mask[l] = std::isfinite(field.values[l]) ? 1 : 0;
  return mask;
}

// The coverage line, with a warning below kLowPathCoveragePercent, and the clamping line.
QString coverageText(const planning::Coverage& c, const planning::CrustClamping& clamped) {
  QString text = QObject::tr("coverage %1 of the region (%2 of %3 mm²)")
                     .arg(percent(c.percent()), QString::number(c.coveredAreaMm2, 'f', 1),
                          QString::number(c.totalAreaMm2, 'f', 1));
  if (c.percent() < planning::kLowPathCoveragePercent)
    text += QObject::tr("\nwarning: the statistics describe only %1 of the region")
                .arg(percent(c.percent()));
  if (clamped.points > 0)
    text += QObject::tr(
                "\nwarning: %1 raster points (%2 mm²) were cut below the crust bottom and "
                "clamped: the true overcut is deeper there, min is only a bound")
                .arg(clamped.points)
                .arg(clamped.areaMm2, 0, 'f', 2);
  return text;
}

QTableWidgetItem* cell(const QString& text) {
  auto* item = new QTableWidgetItem(text);
  item->setFlags(item->flags() & ~Qt::ItemIsEditable);
  return item;
}

}  // namespace

void ErrorMapPanel::buildOutputs() {
  auto* layout = qobject_cast<QVBoxLayout*>(this->layout());
  stats_ = new QLabel(this);
  stats_->setObjectName("errorStatisticsLabel");
  stats_->setTextInteractionFlags(Qt::TextSelectableByMouse);
  stats_->setWordWrap(true);
  // Room for the statistics and their coverage, so the table below never squeezes them.
  stats_->setMinimumHeight(8 * stats_->fontMetrics().lineSpacing());
  layout->addWidget(stats_);
  path_ = new QComboBox(this);
  path_->setObjectName("errorPathCombo");
  layout->addWidget(path_);
  alongPath_ = new QPushButton(tr("Plot deviation along path"), this);
  alongPath_->setObjectName("plotAlongPathButton");
  layout->addWidget(alongPath_);
  scallop_ = new QPushButton(tr("Scallop table: theory vs simulation"), this);
  scallop_->setObjectName("scallopTableButton");
  layout->addWidget(scallop_);
  scallopTable_ = new QTableWidget(0, 6, this);
  scallopTable_->setObjectName("scallopTable");
  scallopTable_->setHorizontalHeaderLabels({tr("tool"), tr("spacing [mm]"), tr("k_s [1/mm]"),
                                            tr("theory [mm]"), tr("simulated [mm]"),
                                            tr("rel. error")});
  scallopTable_->horizontalHeader()->setSectionResizeMode(QHeaderView::ResizeToContents);
  layout->addWidget(scallopTable_, 1);
  connect(alongPath_, &QPushButton::clicked, this,
          [this] { plotAlongPath(path_->currentIndex()); });
  connect(scallop_, &QPushButton::clicked, this, [this] { computeScallopTable(); });
}

void ErrorMapPanel::updateStatistics() {
  statistics_.reset();
  coverage_.reset();
  clamping_.reset();
  const planning::Project& p = workbench().document.project();
  const planning::ScalarField* field = deviationField();
  stale_ = field != nullptr && p.part && planning::isStale(*field, *p.part);
  if (field != nullptr && p.part) {
    const std::vector<int> faces = regionFaces(p, region_->currentData().toInt());
    // The map shows what the statistics count: the chosen region only, the rest "no value".
    const planning::ScalarField* shown = workbench().partView.shownField();
    if (shown && shown->name == kDeviationField) workbench().partView.setShownFaces(faces);
    runUserAction(workbench().reportError, tr("Error statistics"), [&] {
      const planning::ToleranceBand band = toleranceBand();
      statistics_ = planning::errorStatistics(*field, *p.part, band, faces);
      coverage_ = planning::maskCoverage(*p.part, finiteMask(*field), faces);
      clamping_ = planning::crustClamping(*field, *p.part, faces);
      const double lo = std::min(statistics_->minMm, 2.0 * band.lowerMm);
      double hi = std::max(statistics_->maxMm, 2.0 * band.upperMm);
      if (!(hi > lo)) hi = lo + 1e-3;
      const planning::AreaHistogram histogram =
          planning::errorHistogram(*field, *p.part, kHistogramBins, lo, hi, faces);
      setAreaHistogramBars(workbench().plots.plot(kHistogramTab), histogram, band);
    });
  }
  showStatistics();
}

void ErrorMapPanel::showStatistics() {
  if (!statistics_) {
    stats_->setText(tr("No error map yet: choose the desired surface and press Compute."));
    return;
  }
  const planning::ErrorStatistics& s = *statistics_;
  stats_->setText(
      (stale_ ? tr("STALE: the part's heights changed after this error map was computed; "
                   "press Compute error map again.\n")
              : QString()) +
      tr("max %1, min %2\nmean %3, RMS %4\nin tolerance %5\nmaterial left %6, "
         "overcut %7\narea %8 mm², %9 raster points")
          .arg(mm(s.maxMm), mm(s.minMm), mm(s.meanMm), mm(s.rmsMm), percent(s.inTolerancePercent),
               percent(s.materialLeftPercent), percent(s.overcutPercent),
               QString::number(s.areaMm2, 'f', 1))
          .arg(s.points) +
      (coverage_ && clamping_ ? '\n' + coverageText(*coverage_, *clamping_) : QString()));
}

bool ErrorMapPanel::plotAlongPath(int index) {
  const planning::Project& p = workbench().document.project();
  return runUserAction(workbench().reportError, tr("Deviation along path"), [&] {
    const planning::ScalarField* field = deviationField();
    if (field == nullptr || !p.part) throw InvalidInput("compute the error map first");
    if (index < 0 || index >= static_cast<int>(p.paths.size()))
      throw InvalidInput("choose a tool path");
    const auto samples =
        planning::deviationAlongPath(*field, *p.part, p.paths[static_cast<std::size_t>(index)]);
    setDeviationAlongPath(workbench().plots.plot(kAlongPathTab), samples, toleranceBand());
    workbench().plots.showPlot(kAlongPathTab);
  });
}

std::vector<planning::ScallopCase> ErrorMapPanel::defaultScallopCases() {
  using Model = planning::ScallopToolModel;
  return {
      {"ball R5, plane", Model::Ball, 5.0, 10.0, 0.2, 1.0, 0.0},
      {"ball R5, convex R20", Model::Ball, 5.0, 10.0, 0.2, 1.0, 1.0 / 20.0},
      {"flat wheel R5 B10, convex R50", Model::FlatWheel, 5.0, 10.0, 0.2, 3.0, 1.0 / 50.0},
      {"flat end R5, lead 0.2 rad", Model::TiltedFlatEnd, 5.0, 10.0, 0.2, 1.5, 0.0},
  };
}

bool ErrorMapPanel::computeScallopTable() {
  bool started = false;
  runUserAction(workbench().reportError, tr("Scallop table"), [&] {
    ErrorMapPanel* self = this;
    auto job = [self, simulation = scallopSimulation_](const ProgressCallback& progress) {
      planning::ScallopSimulationParams params = simulation;
      params.progress = progress;
      auto rows = planning::scallopTable(defaultScallopCases(), params);
      return std::function<void()>([self, rows = std::move(rows)]() mutable {
        self->scallopRows_ = std::move(rows);
        self->showScallopRows();
      });
    };
    started = workbench().jobs.start(tr("Scallop table"), job);
    if (!started) throw InvalidInput("another job is running; wait for it or cancel it first");
  });
  return started;
}

void ErrorMapPanel::showScallopRows() {
  scallopTable_->setRowCount(static_cast<int>(scallopRows_.size()));
  for (int r = 0; r < static_cast<int>(scallopRows_.size()); ++r) {
    const planning::ScallopRow& row = scallopRows_[static_cast<std::size_t>(r)];
    scallopTable_->setItem(r, 0, cell(QString::fromStdString(row.tool)));
    scallopTable_->setItem(r, 1, cell(QString::number(row.spacingMm, 'f', 3)));
    scallopTable_->setItem(r, 2, cell(QString::number(row.curvaturePerMm, 'f', 4)));
    scallopTable_->setItem(r, 3, cell(QString::number(row.predictedMm, 'f', 5)));
    scallopTable_->setItem(r, 4, cell(QString::number(row.simulatedMm, 'f', 5)));
    scallopTable_->setItem(r, 5, cell(QString::number(100.0 * row.relativeError, 'f', 1) + " %"));
  }
}

}  // namespace ddfcam::gui
