// SPDX-License-Identifier: MIT
// ddfcam gui: MouldPanel: widgets, loading, alignment and the study -> view refresh.
#include <ddfcam/gui/panels/mould_panel.h>

#include <ddfcam/error.h>
#include <ddfcam/gui/document.h>
#include <ddfcam/gui/interaction_mode.h>
#include <ddfcam/gui/job_runner.h>
#include <ddfcam/gui/mould_commands.h>
#include <ddfcam/gui/mould_view.h>
#include <ddfcam/io/mesh/mesh_units.h>
#include <ddfcam/io/mesh/surface_file.h>
#include <ddfcam/planning/mould/surface_alignment.h>

#include <QCheckBox>
#include <QComboBox>
#include <QFileDialog>
#include <QGroupBox>
#include <QHBoxLayout>
#include <QLabel>
#include <QListWidget>
#include <QPushButton>
#include <QSignalBlocker>
#include <QVBoxLayout>

#include <memory>
#include <utility>

#include "unit_combo.h"

namespace ddfcam::gui {
namespace {

QPushButton* button(QWidget* parent, const QString& text, const char* name) {
  auto* b = new QPushButton(text, parent);
  b->setObjectName(name);
  return b;
}

QString point(const Eigen::Vector3d& p) {
  return QStringLiteral("(%1, %2, %3)")
      .arg(p.x(), 0, 'f', 2)
      .arg(p.y(), 0, 'f', 2)
      .arg(p.z(), 0, 'f', 2);
}

// The formed mesh back in its file frame (the study keeps it aligned).
ddf::TriangleMesh fileFrameMesh(const planning::MouldStudy& study) {
  const Eigen::Isometry3d toMould = planning::fromRowMajor(study.alignment.transform);
  return study.formed->mesh.transformed(toMould.inverse());
}

}  // namespace

MouldPanel::MouldPanel(Workbench& workbench, QWidget* parent) : Panel(workbench, parent) {
  new QVBoxLayout(this);
  buildInputs();
  buildAlignment();
  buildOutputs();
  buildMorph();
  qobject_cast<QVBoxLayout*>(this->layout())->addStretch(1);
  connect(&workbench.document, &Document::changed, this, [this](Changes what) {
    if (what & Change::Mould) refresh();
  });
  if (workbench.mouldView)
    connect(workbench.mouldView, &MouldView::pointPicked, this,
            [this](int view, Eigen::Vector3d p) { onPicked(view, p); });
  refresh();
}

void MouldPanel::buildInputs() {
  auto* group = new QGroupBox(tr("Surfaces"), this);
  auto* box = new QVBoxLayout(group);
  QPushButton* mould = button(group, tr("Load mould..."), "loadMouldButton");
  QPushButton* formed = button(group, tr("Load formed..."), "loadFormedButton");
  mouldUnit_ = makeUnitCombo(group, "mouldUnitCombo");
  formedUnit_ = makeUnitCombo(group, "formedUnitCombo");
  files_ = new QLabel(group);
  files_->setObjectName("mouldFilesLabel");
  files_->setWordWrap(true);
  for (auto [load, unit] : {std::pair{mould, mouldUnit_}, std::pair{formed, formedUnit_}}) {
    auto* row = new QHBoxLayout;
    row->addWidget(load, 1);
    row->addWidget(unit);
    box->addLayout(row);
  }
  box->addWidget(files_);
  layout()->addWidget(group);
  const QString filter = QString::fromStdString(io::surfaceFileDialogFilter());
  connect(mould, &QPushButton::clicked, this, [this, filter] {
    const QString path = ask(tr("Load mould"), filter, false);
    if (!path.isEmpty()) loadMould(path);
  });
  connect(formed, &QPushButton::clicked, this, [this, filter] {
    const QString path = ask(tr("Load formed surface"), filter, false);
    if (!path.isEmpty()) loadFormed(path);
  });
}

void MouldPanel::buildAlignment() {
  auto* group = new QGroupBox(tr("Alignment of the formed surface"), this);
  auto* box = new QVBoxLayout(group);
  alignment_ = new QComboBox(group);
  alignment_->setObjectName("alignmentCombo");
  alignment_->addItem(tr("None (as positioned)"),
                      static_cast<int>(planning::AlignmentMethod::None));
  alignment_->addItem(tr("Point pairs"), static_cast<int>(planning::AlignmentMethod::PointPairs));
  alignment_->addItem(tr("Best fit"), static_cast<int>(planning::AlignmentMethod::BestFit));
  QPushButton* pick = button(group, tr("Pick pair (formed, then mould)"), "pickPairButton");
  QPushButton* clear = button(group, tr("Clear pairs"), "clearPairsButton");
  QPushButton* apply = button(group, tr("Apply alignment"), "applyAlignmentButton");
  pairList_ = new QListWidget(group);
  pairList_->setObjectName("pointPairList");
  pairList_->setMaximumHeight(80);
  alignmentLabel_ = new QLabel(group);
  alignmentLabel_->setObjectName("alignmentLabel");
  alignmentLabel_->setWordWrap(true);
  box->addWidget(alignment_);
  box->addWidget(pick);
  box->addWidget(pairList_);
  box->addWidget(clear);
  box->addWidget(apply);
  box->addWidget(alignmentLabel_);
  layout()->addWidget(group);
  connect(alignment_, &QComboBox::currentIndexChanged, this, [this] { refresh(); });
  connect(pick, &QPushButton::clicked, this, [this] { setPickMode(PickMode::PairFormed); });
  connect(clear, &QPushButton::clicked, this, [this] { clearPointPairs(); });
  connect(apply, &QPushButton::clicked, this, [this] { applyAlignment(); });
}

QString MouldPanel::ask(const QString& title, const QString& filter, bool save) {
  if (askPath_) return askPath_(title, filter, save);
  return save ? QFileDialog::getSaveFileName(this, title, QString(), filter)
              : QFileDialog::getOpenFileName(this, title, QString(), filter);
}

void MouldPanel::pushStudy(std::optional<planning::MouldStudy> after, const QString& text) {
  Document& doc = workbench().document;
  doc.push(
      std::make_unique<SetMouldStudyCommand>(doc, doc.project().mould, std::move(after), text));
}

bool MouldPanel::loadMould(const QString& path) {
  return runUserAction(workbench().reportError, tr("Load mould"), [&] {
    planning::MouldStudy study;
    if (const auto& old = workbench().document.project().mould) study.comparison = old->comparison;
    study.mould = io::readSurfaceFileInUnit(path.toStdString(), unitOf(mouldUnit_));
    if (study.mould.mesh.triangles.empty())
      throw InvalidInput("the mould file '" + path.toStdString() + "' has no triangles");
    pushStudy(std::move(study), tr("Load mould"));
    if (workbench().mouldView) workbench().mouldView->fitCameras();
  });
}

bool MouldPanel::loadFormed(const QString& path) {
  return runUserAction(workbench().reportError, tr("Load formed surface"), [&] {
    const auto& current = workbench().document.project().mould;
    if (!current) throw InvalidInput("load the mould first: it is the reference frame");
    planning::MouldStudy study = *current;
    study.formed = io::readSurfaceFileInUnit(path.toStdString(), unitOf(formedUnit_));
    if (study.formed->mesh.triangles.empty())
      throw InvalidInput("the formed file '" + path.toStdString() + "' has no triangles");
    study.alignment = {};
    study.result.reset();
    pushStudy(std::move(study), tr("Load formed surface"));
    clearPointPairs();
  });
}

void MouldPanel::setSurfaceUnits(LengthUnit mould, LengthUnit formed) {
  selectUnit(mouldUnit_, mould);
  selectUnit(formedUnit_, formed);
}

void MouldPanel::setAlignmentMethod(planning::AlignmentMethod method) {
  alignment_->setCurrentIndex(alignment_->findData(static_cast<int>(method)));
}

planning::AlignmentMethod MouldPanel::alignmentMethod() const {
  return static_cast<planning::AlignmentMethod>(alignment_->currentData().toInt());
}

void MouldPanel::addPointPair(const Eigen::Vector3d& formedShown, const Eigen::Vector3d& mould) {
  const auto& study = workbench().document.project().mould;
  Eigen::Vector3d formedFile = formedShown;
  if (study)
    formedFile = planning::fromRowMajor(study->alignment.transform).inverse() * formedShown;
  pairs_.push_back({formedFile, mould});
  pairList_->addItem(
      tr("%1: formed %2 -> mould %3").arg(pairs_.size()).arg(point(formedShown), point(mould)));
}

void MouldPanel::clearPointPairs() {
  pairs_.clear();
  pairList_->clear();
  pendingFormed_.reset();
}

bool MouldPanel::applyAlignment() {
  bool done = false;
  runUserAction(workbench().reportError, tr("Align formed surface"), [&] {
    const auto& current = workbench().document.project().mould;
    if (!current || !current->formed) throw InvalidInput("load the mould and the formed surface");
    const planning::AlignmentMethod method = alignmentMethod();
    if (method != planning::AlignmentMethod::BestFit) {
      applyDirectAlignment(*current, method);
      done = true;
      return;
    }
    done = startBestFit(*current);
    if (!done) throw InvalidInput("another job is running; wait for it or cancel it first");
  });
  return done;
}

// None and PointPairs are immediate: one undoable edit, no job.
void MouldPanel::applyDirectAlignment(planning::MouldStudy study,
                                      planning::AlignmentMethod method) {
  const ddf::TriangleMesh file = fileFrameMesh(study);
  planning::RigidAlignment fit;
  if (method == planning::AlignmentMethod::PointPairs) fit = planning::alignByPointPairs(pairs_);
  study.formed->mesh = file.transformed(fit.transform);
  study.alignment = {method, planning::toRowMajor(fit.transform), fit.rmsMm,
                     method == planning::AlignmentMethod::PointPairs
                         ? pairs_
                         : std::vector<std::array<Eigen::Vector3d, 2>>{}};
  study.result.reset();
  pushStudy(std::move(study), tr("Align formed surface"));
}

bool MouldPanel::startBestFit(const planning::MouldStudy& study) {
  auto mould = std::make_shared<const ddf::TriangleMesh>(study.mould.mesh);
  auto moving = std::make_shared<const ddf::TriangleMesh>(fileFrameMesh(study));
  MouldPanel* self = this;
  return workbench().jobs.start(tr("Best fit"), [=](const ProgressCallback& progress) {
    planning::BestFitParams params;
    params.progress = progress;
    const planning::RigidAlignment fit = planning::alignBestFit(*moving, *mould, params);
    return std::function<void()>([self, fit, moving] {
      const auto& now = self->workbench().document.project().mould;
      if (!now || !now->formed) return;
      planning::MouldStudy aligned = *now;
      aligned.formed->mesh = moving->transformed(fit.transform);
      aligned.alignment = {
          planning::AlignmentMethod::BestFit, planning::toRowMajor(fit.transform), fit.rmsMm, {}};
      aligned.result.reset();
      self->pushStudy(std::move(aligned), tr("Best-fit alignment"));
    });
  });
}

QString MouldPanel::alignmentText() const {
  return alignmentLabel_->text();
}

void MouldPanel::setPickMode(PickMode mode) {
  mode_ = mode;
  if (mode == PickMode::PairFormed) pendingFormed_.reset();
  if (mode == PickMode::SectionStart) sectionStart_.reset();
  // Pairs are picked on both surfaces, so they need the two views.
  if ((mode == PickMode::PairFormed || mode == PickMode::PairMould) && workbench().mouldView)
    workbench().mouldView->setLayout(MouldView::Layout::SideBySide);
  announcePickMode();
}

void MouldPanel::announcePickMode() {
  InteractionMode* modes = workbench().mode;
  if (!modes) return;
  switch (mode_) {
    case PickMode::None:
      return modes->clear(this);
    case PickMode::PairFormed:
      return modes->begin(this, tr("Point pair"), tr("click the formed point (right)"),
                          [this] { setPickMode(PickMode::None); });
    case PickMode::PairMould:
      return modes->begin(this, tr("Point pair"),
                          tr("click the mould point (left)"),
                          [this] { setPickMode(PickMode::None); });
    case PickMode::SectionStart:
      return modes->begin(this, tr("Section"), tr("click the line's start"),
                          [this] { setPickMode(PickMode::None); });
    case PickMode::SectionEnd:
      return modes->begin(this, tr("Section"), tr("click the line's end"),
                          [this] { setPickMode(PickMode::None); });
  }
}

void MouldPanel::onPicked(int view, const Eigen::Vector3d& p) {
  switch (mode_) {
    case PickMode::PairFormed:
      if (view != MouldView::kSecondary) return;
      pendingFormed_ = p;
      setPickMode(PickMode::PairMould);
      return;
    case PickMode::PairMould:
      if (view != MouldView::kPrimary || !pendingFormed_) return;
      addPointPair(*pendingFormed_, p);
      pendingFormed_.reset();
      setPickMode(PickMode::None);
      return;
    case PickMode::SectionStart:
      if (view != MouldView::kPrimary) return;
      sectionStart_ = p;
      setPickMode(PickMode::SectionEnd);
      return;
    case PickMode::SectionEnd:
      if (view != MouldView::kPrimary || !sectionStart_) return;
      setPickMode(PickMode::None);
      drawSection(*sectionStart_, p);
      return;
    case PickMode::None:
      return;
  }
}

void MouldPanel::refresh() {
  const auto& study = workbench().document.project().mould;
  QString files = tr("No mould loaded.");
  if (study) {
    files = tr("Mould: %1 (%2 triangles)")
                .arg(QString::fromStdString(study->mould.name))
                .arg(study->mould.mesh.triangles.size());
    if (study->formed)
      files += tr("\nFormed: %1 (%2 triangles)")
                   .arg(QString::fromStdString(study->formed->name))
                   .arg(study->formed->mesh.triangles.size());
  }
  files_->setText(files);
  QString align;
  if (study && study->formed) {
    static const char* names[] = {"none (as positioned)", "point pairs", "best fit"};
    align = tr("Applied: %1, RMS %2 mm")
                .arg(tr(names[static_cast<int>(study->alignment.method)]))
                .arg(study->alignment.rmsMm, 0, 'f', 4);
  }
  if (alignmentMethod() == planning::AlignmentMethod::BestFit ||
      (study && study->alignment.method == planning::AlignmentMethod::BestFit))
    align += QStringLiteral("\n") + tr(planning::kBestFitWarning);
  alignmentLabel_->setText(align);
  compare_->setEnabled(study && study->formed);
  showStudy();
}

}  // namespace ddfcam::gui
