// SPDX-License-Identifier: MIT
// ddfcam gui: MouldPanel: the comparison job, statistics, histogram and the band settings.
#include <ddfcam/error.h>
#include <ddfcam/gui/adapters/error_plots.h>
#include <ddfcam/gui/document.h>
#include <ddfcam/gui/job_runner.h>
#include <ddfcam/gui/mould_view.h>
#include <ddfcam/gui/panels/mould_panel.h>
#include <ddfcam/gui/plot_dock.h>
#include <ddfcam/planning/inspection/surface_comparison.h>

#include <qcustomplot.h>

#include <QCheckBox>
#include <QComboBox>
#include <QDoubleSpinBox>
#include <QFormLayout>
#include <QGroupBox>
#include <QLabel>
#include <QPushButton>
#include <QSlider>
#include <QSpinBox>
#include <QVBoxLayout>

#include <algorithm>
#include <cmath>
#include <memory>

namespace ddfcam::gui {
namespace {

QString mm(double value) {
  return QString::number(value, 'f', 3) + QStringLiteral(" mm");
}

QPushButton* button(QWidget* parent, const QString& text, const char* name) {
  auto* b = new QPushButton(text, parent);
  b->setObjectName(name);
  return b;
}

QDoubleSpinBox* bandSpin(QWidget* parent, const char* name, double value) {
  auto* spin = new QDoubleSpinBox(parent);
  spin->setObjectName(name);
  spin->setDecimals(3);
  spin->setSingleStep(0.05);
  spin->setRange(value < 0.0 ? -100.0 : 0.0, value < 0.0 ? 0.0 : 100.0);
  spin->setSuffix(QStringLiteral(" mm"));
  spin->setValue(value);
  return spin;
}

}  // namespace

void MouldPanel::buildOutputs() {
  auto* group = new QGroupBox(tr("Comparison"), this);
  auto* form = new QFormLayout(group);
  const planning::ComparisonParams defaults;
  resolution_ = new QSpinBox(group);
  resolution_->setObjectName("mouldResolutionSpin");
  resolution_->setRange(2, 64);
  resolution_->setValue(defaults.resolution);
  lower_ = bandSpin(group, "mouldToleranceLowerSpin", defaults.band.lowerMm);
  upper_ = bandSpin(group, "mouldToleranceUpperSpin", defaults.band.upperMm);
  flip_ = new QCheckBox(tr("Flip mould normal"), group);
  flip_->setObjectName("flipNormalCheck");
  compare_ = button(group, tr("Compare"), "compareSurfacesButton");
  stats_ = new QLabel(group);
  stats_->setObjectName("mouldStatisticsLabel");
  stats_->setTextInteractionFlags(Qt::TextSelectableByMouse);
  crossing_ = new QLabel(group);
  crossing_->setObjectName("crossingLabel");
  crossing_->setWordWrap(true);
  QPushButton* section = button(group, tr("Draw section"), "drawSectionButton");
  QPushButton* exportDev = button(group, tr("Export deviation..."), "exportDeviationButton");
  form->addRow(tr("Resolution m"), resolution_);
  form->addRow(tr("Lower tolerance"), lower_);
  form->addRow(tr("Upper tolerance"), upper_);
  form->addRow(flip_);
  form->addRow(compare_);
  form->addRow(stats_);
  form->addRow(crossing_);
  form->addRow(section);
  form->addRow(exportDev);
  layout()->addWidget(group);
  connect(compare_, &QPushButton::clicked, this, [this] { compare(); });
  for (QDoubleSpinBox* spin : {lower_, upper_})
    connect(spin, &QDoubleSpinBox::editingFinished, this, [this] { applyBandToResult(); });
  connect(flip_, &QCheckBox::clicked, this, [this] { applyBandToResult(); });
  connect(section, &QPushButton::clicked, this, [this] { setPickMode(PickMode::SectionStart); });
  connect(exportDev, &QPushButton::clicked, this, [this] {
    const QString path = ask(tr("Export deviation"),
                             tr("VTK PolyData (*.vtp);;CSV points and vectors (*.csv)"), true);
    if (!path.isEmpty()) exportDeviation(path);
  });
}

void MouldPanel::buildMorph() {
  auto* group = new QGroupBox(tr("View and morph"), this);
  auto* form = new QFormLayout(group);
  layout_ = new QComboBox(group);
  layout_->setObjectName("mouldLayoutCombo");
  layout_->addItem(tr("Side by side"));
  layout_->addItem(tr("Overlay"));
  morph_ = new QSlider(Qt::Horizontal, group);
  morph_->setObjectName("morphSlider");
  morph_->setRange(-100, 200);  // lambda x 100
  morph_->setValue(100);
  morphLabel_ = new QLabel(group);
  morphLabel_->setObjectName("morphLabel");
  QPushButton* exportMorph = button(group, tr("Export morph surface..."), "exportMorphButton");
  form->addRow(tr("Layout"), layout_);
  form->addRow(tr("Morph lambda"), morph_);
  form->addRow(morphLabel_);
  form->addRow(exportMorph);
  layout()->addWidget(group);
  connect(layout_, &QComboBox::currentIndexChanged, this, [this](int index) {
    if (workbench().mouldView)
      workbench().mouldView->setLayout(index == 1 ? MouldView::Layout::Overlay
                                                  : MouldView::Layout::SideBySide);
  });
  connect(morph_, &QSlider::valueChanged, this, [this] {
    morphShown_ = raster_.has_value();
    showMorph();
  });
  connect(exportMorph, &QPushButton::clicked, this, [this] {
    const QString path = ask(tr("Export morph surface"), tr("Meshes (*.stl *.obj *.ply)"), true);
    if (!path.isEmpty()) exportMorphSurface(path);
  });
}

void MouldPanel::setResolution(int m) {
  resolution_->setValue(m);
}

void MouldPanel::setToleranceBand(const planning::ToleranceBand& band) {
  planning::validateToleranceBand(band);
  lower_->setValue(band.lowerMm);
  upper_->setValue(band.upperMm);
  applyBandToResult();
}

void MouldPanel::setFlipNormal(bool flip) {
  flip_->setChecked(flip);
  applyBandToResult();
}

planning::ComparisonParams MouldPanel::comparisonParams() const {
  planning::ComparisonParams params;
  if (const auto& study = workbench().document.project().mould) params = study->comparison;
  params.resolution = resolution_->value();
  params.band = {lower_->value(), upper_->value()};
  params.flipNormal = flip_->isChecked();
  params.progress = {};
  params.sequence.progress = {};
  return params;
}

bool MouldPanel::compare() {
  bool started = false;
  runUserAction(workbench().reportError, tr("Compare surfaces"), [&] {
    const auto& study = workbench().document.project().mould;
    if (!study || !study->formed) throw InvalidInput("load the mould and the formed surface");
    const planning::ComparisonParams params = comparisonParams();
    planning::validateToleranceBand(params.band);
    auto mould = std::make_shared<const ddf::TriangleMesh>(study->mould.mesh);
    auto formed = std::make_shared<const ddf::TriangleMesh>(study->formed->mesh);
    MouldPanel* self = this;
    started = workbench().jobs.start(tr("Compare surfaces"), [=](const ProgressCallback& progress) {
      planning::ComparisonParams run = params;
      run.progress = progress;
      auto result = std::make_shared<planning::SurfaceComparison>(
          planning::compareSurfaces(*mould, *formed, run));
      return std::function<void()>([self, params, result] {
        const auto& now = self->workbench().document.project().mould;
        if (!now) return;
        planning::MouldStudy after = *now;
        after.comparison = params;
        after.result = std::move(*result);
        self->morphShown_ = false;
        self->pushStudy(std::move(after), tr("Compare surfaces"));
        self->workbench().plots.showPlot(kHistogramTab);
      });
    });
    if (!started) throw InvalidInput("another job is running; wait for it or cancel it first");
  });
  return started;
}

void MouldPanel::showStudy() {
  MouldView* view = workbench().mouldView;
  const auto& study = workbench().document.project().mould;
  raster_.reset();
  vertexCopy_.clear();
  if (!study) {
    morphShown_ = false;
    if (view) view->clear();
    stats_->setText(tr("No comparison yet."));
    crossing_->clear();
    return;
  }
  if (study->result) {
    showResult(*study);
  } else {
    morphShown_ = false;
    stats_->setText(tr("No comparison yet: load both surfaces and press Compare."));
    crossing_->clear();
    if (view) view->showPrimaryPlain(study->mould.mesh);
  }
  if (morphShown_ && raster_) {
    showMorph();
  } else if (view) {
    const planning::MeshField* field =
        study->formed && !study->formed->fields.empty() ? &study->formed->fields.front() : nullptr;
    view->showSecondary(study->formed ? study->formed->mesh : ddf::TriangleMesh{}, field);
  }
  morphLabel_->setText(tr("lambda = %1 (0 = mould, 1 = formed)%2")
                           .arg(morphLambda(), 0, 'f', 2)
                           .arg(raster_ ? QString() : tr("; compare first")));
}

void MouldPanel::showResult(const planning::MouldStudy& study) {
  const planning::SurfaceComparison& r = *study.result;
  const ddf::DisplacementField& ddf = r.sequence.stages.front().ddf;
  indexRasterCopies(ddf);
  showResultText(r);
  runUserAction(workbench().reportError, tr("Deviation histogram"), [&] { showHistogram(r, ddf); });
  if (MouldView* view = workbench().mouldView) showDeviation(*view, r, ddf);
}

// Each raster vertex takes the value of the first copy of its point (a point on a shared edge
// or corner has one copy per face).
void MouldPanel::indexRasterCopies(const ddf::DisplacementField& ddf) {
  raster_ = ddf::extractRasterMesh(ddf);
  vertexCopy_.resize(raster_->vertexPoint.size());
  for (std::size_t v = 0; v < vertexCopy_.size(); ++v) {
    bool first = true;
    ddf.topology().forEachCopy(raster_->vertexPoint[v], [&](ddf::PointCopy c) {
      if (first) vertexCopy_[v] = static_cast<std::size_t>(c.face) * ddf.pointsPerFace() + c.local;
      first = false;
    });
  }
}

void MouldPanel::showResultText(const planning::SurfaceComparison& r) {
  const planning::ErrorStatistics& s = r.statistics;
  const planning::ComparisonCoverage c = planning::comparisonCoverage(r);
  QString text = tr("max %1, min %2\nmean %3, sigma %4\nwithin %5 .. %6: %7 %\narea %8 mm²")
                     .arg(mm(s.maxMm), mm(s.minMm), mm(s.meanMm), mm(s.sigmaMm), mm(r.band.lowerMm),
                          mm(r.band.upperMm), QString::number(s.inTolerancePercent, 'f', 1),
                          QString::number(s.areaMm2, 'f', 1));
  text += tr("\ncoverage %1 % of the mould's %2 mm²")
              .arg(QString::number(c.compared.percent(), 'f', 2))
              .arg(QString::number(c.compared.totalAreaMm2, 'f', 1));
  if (c.compared.percent() < planning::kLowComparisonCoveragePercent)
    text += tr("\nwarning: the statistics describe only %1 % of the mould")
                .arg(QString::number(c.compared.percent(), 'f', 2));
  if (r.sequence.stalled)
    text += tr("\nwarning: %1").arg(QString::fromStdString(planning::stallAdvice(r)));
  if (c.unresolvedFaces > 0)
    text += tr("\nwarning: %1 unresolved faces (%2 mm²) left out of the statistics")
                .arg(c.unresolvedFaces)
                .arg(QString::number(c.unresolvedAreaMm2, 'f', 1));
  stats_->setText(text);
  const auto& seq = r.sequence;
  crossing_->setText(
      seq.crossingFaces.empty()
          ? tr("unique projection holds on every face (1 stage)")
          : tr("unique projection fails on %1 faces: split into %2 stages; %3 unresolved faces, "
               "%4 points missed")
                .arg(seq.crossingFaces.size())
                .arg(seq.stages.size())
                .arg(seq.unresolvedFaces.size())
                .arg(seq.missingPoints));
}

void MouldPanel::showHistogram(const planning::SurfaceComparison& r,
                               const ddf::DisplacementField& ddf) {
  const planning::ErrorStatistics& s = r.statistics;
  const double lo = std::min(s.minMm, 2.0 * r.band.lowerMm);
  double hi = std::max(s.maxMm, 2.0 * r.band.upperMm);
  if (!(hi > lo)) hi = lo + 1e-3;
  const planning::AreaHistogram histogram = planning::errorHistogram(
      r.deviation, ddf, kHistogramBins, lo, hi, planning::resolvedFaces(r));
  QCustomPlot* plot = workbench().plots.plot(kHistogramTab);
  setAreaHistogramBars(plot, histogram, r.band,
                       {kShortOfMouldBarsName, kInToleranceBarsName, kBeyondMouldBarsName});
}

void MouldPanel::showDeviation(MouldView& view, const planning::SurfaceComparison& r,
                               const ddf::DisplacementField& ddf) {
  const auto& seq = r.sequence;
  const std::vector<ddf::Vec3> mouldPoints = ddf::morphPositions(seq, 0.0);
  ddf::TriangleMesh mesh = raster_->mesh;
  std::vector<float> values(vertexCopy_.size());
  for (std::size_t v = 0; v < vertexCopy_.size(); ++v) {
    mesh.vertices[v] = mouldPoints[vertexCopy_[v]];
    values[v] = r.deviation.values[vertexCopy_[v]];
  }
  view.showPrimary(mesh, std::move(values), r.band);
  const int perFace = (ddf.resolution() - 1) * (ddf.resolution() - 1);
  std::vector<int> triangles;
  for (int f : seq.crossingFaces)
    for (int t = 0; t < perFace; ++t) triangles.push_back(f * perFace + t);
  view.showHighlightedTriangles(triangles);
}

QString MouldPanel::statisticsText() const {
  return stats_->text();
}

QString MouldPanel::crossingText() const {
  return crossing_->text();
}

// The deformed points do not depend on the band or the normal's orientation, so a new band
// re-evaluates the stored comparison instead of running it again.
void MouldPanel::applyBandToResult() {
  runUserAction(workbench().reportError, tr("Tolerance band"), [&] {
    const auto& study = workbench().document.project().mould;
    if (!study || !study->result) return;
    const planning::ToleranceBand band{lower_->value(), upper_->value()};
    const bool flip = flip_->isChecked();
    const planning::ToleranceBand& now = study->result->band;
    if (band.lowerMm == now.lowerMm && band.upperMm == now.upperMm &&
        flip == study->comparison.flipNormal)
      return;
    planning::MouldStudy after = *study;
    planning::updateComparisonBand(*after.result, band, flip != after.comparison.flipNormal);
    after.comparison.band = band;
    after.comparison.flipNormal = flip;
    pushStudy(std::move(after), tr("Change tolerance band"));
  });
}

}  // namespace ddfcam::gui
